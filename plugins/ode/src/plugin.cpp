// wtc::ode::Plugin: registration, beginStep (one tyre-model step per wheel
// per world step) and handlePair (the near callback's wheel-terrain pairs).
// Design note in include/wtc/ode/plugin.hpp.
#include "wtc/ode/plugin.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "adapter/cap_cylinder.hpp"
#include "base/scratch_capacity.hpp"
#include "contact_joint.hpp"
#include "conversions.hpp"
#include "plugin_state.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc::ode {
namespace {

// Roundoff allowed when checking that the geom's box holds the tread,
// relative to r_f (dimensionless): ODE's box of a cylinder lying along an
// axis equals the tread's box up to the rotation matrix's roundoff.
constexpr double kBoxSlackRelative = 1e-9;

[[noreturn]] void fail(const char* where, const std::string& what) {
  throw InvalidInputError(std::string(where) + ": " + what);
}

// A contact joint's feedback before ODE has solved it: its f1[0] holds
// this NaN, whose payload no arithmetic gives, until the world step
// overwrites it (applied() tells a solved step from one still to come so).
constexpr std::uint64_t kUnsolvedFeedbackBits = 0x7ff8'0000'5754'4300;

bool unsolved(const dJointFeedback& feedback) {
  return std::bit_cast<std::uint64_t>(feedback.f1[0]) == kUnsolvedFeedbackBits;
}

// Half the tread's extent along a world axis whose cosine with the axle is
// `c`: the largest p . e over {|p| <= r, |p . a| <= w/2}. Either the
// sphere's pole r e is on the tread, or the maximum sits on a cut's rim:
// (w/2) |c| + sqrt(r^2 - w^2/4) sqrt(1 - c^2). The tread, not the whole
// sphere, even without tread truncation: contacts on the cut caps only
// arise off design (a wheel on its side), and a cylinder geom of radius
// r_f and width w then still qualifies.
double treadHalfExtent(const WheelGeometry& g, double c) {
  const double r = g.free_radius, half_width = 0.5 * g.tread_width;
  if (half_width >= r || r * std::abs(c) <= half_width) return r;
  return half_width * std::abs(c) + std::sqrt(r * r - half_width * half_width) * std::sqrt(1.0 - c * c);
}

void requireGeomHoldsTread(const RigidWheel& spec, const Eigen::Vector3d& centre, const Eigen::Vector3d& axle,
                           const char* where) {
  dReal box[6];
  dGeomGetAABB(spec.geom, box);
  const double slack = kBoxSlackRelative * spec.description.geometry.free_radius;
  for (int i = 0; i < 3; ++i) {
    const double half = treadHalfExtent(spec.description.geometry, axle[i]);
    if (box[2 * i] > centre[i] - half + slack || box[2 * i + 1] < centre[i] + half - slack) {
      fail(where, "the geom's bounding box [" + formatNumber(box[2 * i]) + ", " + formatNumber(box[2 * i + 1]) +
                      "] along " + "xyz"[i] +
                      " does not hold the tread (r_f = " + formatNumber(spec.description.geometry.free_radius) +
                      " m, w = " + formatNumber(spec.description.geometry.tread_width) +
                      " m): the near callback would miss ground it touches");
    }
  }
}

}  // namespace

detail::PluginState::PluginState(dWorldID w, dSpaceID space, const Terrain& t, ContactMode m, TerrainShape shape)
    : world(w), terrain(t, space, shape), ground_memory(t), mode(m) {}

const Wheel& detail::PluginState::wheel(WheelId id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= wheels.size()) {
    throw std::out_of_range("wtc::ode::Plugin: wheel id " + std::to_string(id) + " is not registered (" +
                            std::to_string(wheels.size()) + " wheels)");
  }
  return *wheels[id];
}

WheelId detail::PluginState::add(const RigidWheel& spec) {
  static constexpr const char* kWhere = "wtc::ode::Plugin::addWheel";
  if (spec.body == nullptr) fail(kWhere, "body is null");
  if (spec.geom == nullptr) fail(kWhere, "geom is null (the near callback knows a wheel by its geom)");
  if (dGeomGetBody(spec.geom) != spec.body) fail(kWhere, "geom is not attached to body (dGeomSetBody)");
  validateMounting(spec.axle_local, spec.centre_local, kWhere);
  dMass m;
  dBodyGetMass(spec.body, &m);
  Eigen::Matrix3d inertia;  // dMass::I is 3 x 4, row-major (dMatrix3)
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) inertia(r, c) = m.I[4 * r + c];
  }
  const WheelDescription description =
      mountedDescription(spec.description, spec.inertia_source, m.mass, inertia, spec.axle_local, kWhere);
  if (wheel_of.count(spec.geom) != 0) fail(kWhere, "this geom is already a registered wheel");
  if (engineSolvesContacts(mode)) {
    dVector3 centre, axle;
    dBodyGetRelPointPos(spec.body, spec.centre_local.x(), spec.centre_local.y(), spec.centre_local.z(), centre);
    dBodyVectorToWorld(spec.body, spec.axle_local.x(), spec.axle_local.y(), spec.axle_local.z(), axle);
    requireGeomHoldsTread(spec, toEigen(centre), toEigen(axle).normalized(), kWhere);
  }
  auto w = std::make_unique<Wheel>(description, spec.effects, mode);
  w->body = spec.body;
  w->geom = spec.geom;
  w->axle_local = spec.axle_local;
  w->centre_local = spec.centre_local;
  w->contacts.reserve(kReservedContacts);
  w->solved_forces.reserve(kReservedContacts);
  // The caps' cylinder (ODE's along its z axis) at centre_local along
  // axle_local: radius sqrt(r_f^2 - (w/2)^2), width w (collideCaps).
  const CapCylinder caps = capCylinder(spec.description.geometry);
  w->cap_geom = dCreateCylinder(nullptr, caps.radius, 2.0 * caps.half_height);
  dGeomSetBody(w->cap_geom, spec.body);
  dGeomSetOffsetPosition(w->cap_geom, spec.centre_local.x(), spec.centre_local.y(), spec.centre_local.z());
  dMatrix3 rotation;
  const Eigen::Vector3d a = spec.axle_local.normalized();
  dRFromZAxis(rotation, a.x(), a.y(), a.z());
  dGeomSetOffsetRotation(w->cap_geom, rotation);
  dBodySetAutoDisableFlag(spec.body, 0);  // the tread state needs every step
  if (ground_memory.regionCount() > 0) w->mounted.state().setGroundMemory(&ground_memory);
  const auto id = static_cast<WheelId>(wheels.size());
  wheel_of.emplace(spec.geom, id);
  wheels.push_back(std::move(w));
  return id;
}

void detail::PluginState::beginStep(double h) {
  if (!(h > 0.0) || !std::isfinite(h)) {
    fail("wtc::ode::Plugin::beginStep", "step_seconds = " + formatNumber(h) + " is not positive and finite");
  }
  // Implicit mode is the tyre's spring solved by ODE: a cap on the rows'
  // correcting velocity cuts the spring where it matters (the robot's tyre
  // sank to 121 mm at ODE's demos' 0.1 m/s; docs/tyre-model.md), so it is
  // refused here, not only counted as in constraint mode.
  if (mode == ContactMode::kImplicit && std::isfinite(dWorldGetContactMaxCorrectingVel(world))) {
    fail("wtc::ode::Plugin::beginStep",
         "implicit mode needs the world's contact max correcting velocity unbounded (it is " +
             formatNumber(dWorldGetContactMaxCorrectingVel(world)) +
             " m/s): a cap cuts the tyre's spring; dWorldSetContactMaxCorrectingVel(world, dInfinity)");
  }
  step_seconds = h;
  const StepClock::Section timed(clock);
  const Terrain& ground = terrain.terrain();
  dVector3 world_gravity;
  dWorldGetGravity(world, world_gravity);
  const Eigen::Vector3d gravity = toEigen(world_gravity);
  for (std::size_t id = 0; id < wheels.size(); ++id) {
    Wheel& w = *wheels[id];
    w.mounted.setRestLoad(gravity);
    const Eigen::Vector3d& c = w.centre_local;
    dVector3 centre, axle, velocity;
    dBodyGetRelPointPos(w.body, c.x(), c.y(), c.z(), centre);
    dBodyGetRelPointVel(w.body, c.x(), c.y(), c.z(), velocity);
    dBodyVectorToWorld(w.body, w.axle_local.x(), w.axle_local.y(), w.axle_local.z(), axle);
    WheelMotion motion;
    motion.velocity = toEigen(velocity);
    motion.angular_velocity = toEigen(dBodyGetAngularVel(w.body));
    const MountedWheelStep& r = w.mounted.step(ground, {toEigen(centre), toEigen(axle)}, motion, h);
    w.handled = false;
    w.applied_ready = false;
    w.contacts.clear();
    if (r.skipped) {
      // Its body's state is not finite: no force and no contact joint this
      // step (an exception here would leave the caller's step half-done).
      w.mounted.tell(listener, static_cast<WheelId>(id), h);
      continue;
    }
    // The wrench about O: F through O, then the torque (in constraint mode
    // the rolling moment alone; the contact joints carry the rest). ODE
    // clears both after the world step, so they act on exactly this step.
    dBodyAddForceAtPos(w.body, r.force.x(), r.force.y(), r.force.z(), centre[0], centre[1], centre[2]);
    dBodyAddTorque(w.body, r.torque.x(), r.torque.y(), r.torque.z());
    for (const SolverContact& contact : r.contacts) w.contacts.push_back({contact});
    // Counted now, taken back when handlePair hands the contacts to ODE.
    if (!w.contacts.empty()) ++w.diagnostics.unhandled_steps;
    w.mounted.tell(listener, static_cast<WheelId>(id), h);
  }
  soil_bodies.step(ground, ground_memory.regionCount() > 0 ? &ground_memory : nullptr, h);
}

bool detail::PluginState::handlePair(dGeomID a, dGeomID b, dJointGroupID group) {
  auto found = wheel_of.find(a);
  dGeomID ground = b;
  if (found == wheel_of.end() || !terrain.contains(b)) {
    found = wheel_of.find(b);
    ground = a;
    if (found == wheel_of.end() || !terrain.contains(a)) return false;
  }
  const StepClock::Section timed(clock);
  Wheel& w = *wheels[found->second];
  if (!w.mounted.state().capContacts().empty()) collideCaps(w, ground, group);
  // The wheel's contacts are the core's, for all pieces at once: they go to
  // ODE the first time the wheel meets the terrain in this step (against
  // the terrain space, or against one of its pieces), and never twice.
  if (engineSolvesContacts(mode) && !w.handled && !w.contacts.empty()) {
    const double layer = dWorldGetContactSurfaceLayer(world), cap = dWorldGetContactMaxCorrectingVel(world);
    w.applied_ready = false;
    for (SolvedContact& s : w.contacts) {
      const dContact contact = toOdeContact(s.contact, step_seconds, layer, w.geom, ground);
      const dJointID joint = dJointCreateContact(world, group, &contact);
      dJointAttach(joint, w.body, nullptr);
      s.feedback.f1[0] = std::bit_cast<dReal>(kUnsolvedFeedbackBits);
      dJointSetFeedback(joint, &s.feedback);
      if (correctingVelocity(s.contact, step_seconds) > cap) ++w.diagnostics.capped_contacts;
    }
    --w.diagnostics.unhandled_steps;
  }
  w.handled = true;
  return true;
}

namespace {

// What collideCaps hands to ODE's callback for the pieces of a space.
struct CapPass {
  detail::PluginState* state;
  Wheel* wheel;
  dJointGroupID group;
};

}  // namespace

// The ground touches a cut cap (a fallen wheel): WTC gives no force there,
// so ODE collides the cut sphere's cap discs (the wheel's cap cylinder,
// whose rims are the caps' edges) with `ground` (a piece, or the terrain
// space), and the contacts whose normal is a cap's (wtc::onCap, the tread
// filter's test) become rigid contact joints; tread contacts are WTC's and
// are dropped. Not the wheel's own geom: a cylinder of radius r_f reaches
// 9 mm past the tread at the tread's limit (18.4 deg), and threw the wheel
// off a side slope as the cap took over (issue 11). Rare: only when the
// finder saw a cap contact.
void detail::PluginState::collideCaps(Wheel& w, dGeomID ground, dJointGroupID group) {
  if (dGeomIsSpace(ground)) {
    CapPass pass{this, &w, group};
    dSpaceCollide2(w.cap_geom, ground, &pass, [](void* data, dGeomID a, dGeomID b) {
      CapPass& p = *static_cast<CapPass*>(data);
      p.state->collideCaps(*p.wheel, a == p.wheel->cap_geom ? b : a, p.group);
    });
    return;
  }
  constexpr int kMaxCapContacts = 8;  // per piece: a cylinder's face on a triangle mesh
  dContact contacts[kMaxCapContacts] = {};
  const int n = dCollide(w.cap_geom, ground, kMaxCapContacts, &contacts[0].geom, sizeof(dContact));
  dVector3 axle;
  dBodyVectorToWorld(w.body, w.axle_local.x(), w.axle_local.y(), w.axle_local.z(), axle);
  const Eigen::Vector3d a = toEigen(axle).normalized();
  const double mu = terrain.terrain().materials()[w.mounted.state().capContacts().front().material].mu_max;
  for (int i = 0; i < n; ++i) {
    if (!onCap(w.mounted.description().geometry, toEigen(contacts[i].geom.normal), a)) continue;
    contacts[i].surface.mode = dContactApprox1;
    contacts[i].surface.mu = mu;
    dJointAttach(dJointCreateContact(world, group, &contacts[i]), w.body, nullptr);
  }
}

// The joints' feedback f1 is their force on the wheel body (the joint's
// first body) over the last world step; a wheel whose pair ODE never handled
// had no joints and felt none. ODE has no hook after its step (the user
// calls dWorldStep), and the feedback changes only inside it: the wrench is
// assembled at the first call that finds every joint solved, and kept until
// beginStep or handlePair makes new joints. A call before the world step
// counts an unsolved joint as no force, and keeps nothing.
const WheelForces& detail::PluginState::applied(WheelId id) {
  wheel(id);  // throws for an id that is not registered
  Wheel& w = *wheels[static_cast<std::size_t>(id)];
  if (engineSolvesContacts(mode) && !w.mounted.last().skipped && !w.applied_ready) {
    bool solved = true;
    w.solved_forces.clear();
    for (const SolvedContact& c : w.contacts) {
      solved = solved && !unsolved(c.feedback);
      w.solved_forces.push_back(unsolved(c.feedback) ? Eigen::Vector3d::Zero() : c.force());
    }
    w.mounted.setSolvedForces(w.solved_forces);
    w.applied_ready = solved;
  }
  return w.mounted.applied();
}

Plugin::Plugin(dWorldID world, dSpaceID space, const Terrain& terrain, ContactMode mode, TerrainShape shape)
    : state_(std::make_unique<detail::PluginState>(world, space, terrain, mode, shape)) {}

Plugin::~Plugin() = default;

WheelId Plugin::addWheel(const RigidWheel& wheel) { return state_->add(wheel); }
void Plugin::beginStep(double step_seconds) { state_->beginStep(step_seconds); }
bool Plugin::handlePair(dGeomID a, dGeomID b, dJointGroupID contacts) { return state_->handlePair(a, b, contacts); }

const WheelForces& Plugin::forces(WheelId wheel) const { return state_->wheel(wheel).mounted.forces(); }
const WheelForces& Plugin::applied(WheelId wheel) const { return state_->applied(wheel); }

const WheelState& Plugin::state(WheelId wheel) const { return state_->wheel(wheel).mounted.state(); }
SoilBodyId Plugin::addSoilBody(const SoilBody& body) {
  const bool is_wheel = std::any_of(state_->wheels.begin(), state_->wheels.end(),
                                    [&](const auto& w) { return w->body == body.body; });
  return state_->soil_bodies.add(body, is_wheel);
}
const BodySoilForces& Plugin::soilForces(SoilBodyId body) const { return state_->soil_bodies.forces(body); }
int Plugin::soilBodyCount() const { return state_->soil_bodies.count(); }
int Plugin::keepRigidContacts(dGeomID a, dGeomID b, dContactGeom* contacts, int count, int stride) const {
  return state_->soil_bodies.keepRigidContacts(state_->terrain, a, b, contacts, count, stride);
}
const GroundMemory& Plugin::groundMemory() const { return state_->ground_memory; }
GroundMemory& Plugin::groundMemory() { return state_->ground_memory; }
std::span<const SolvedContact> Plugin::solvedContacts(WheelId wheel) const { return state_->wheel(wheel).contacts; }
const WheelDiagnostics& Plugin::diagnostics(WheelId wheel) const { return state_->wheel(wheel).diagnostics; }
int Plugin::wheelCount() const { return static_cast<int>(state_->wheels.size()); }
double Plugin::contactSeconds() const { return state_->clock.seconds(); }
ContactMode Plugin::mode() const { return state_->mode; }
const TerrainGeoms& Plugin::terrainGeoms() const { return state_->terrain; }
void Plugin::setListener(WheelListener* listener) { state_->listener = listener; }

}  // namespace wtc::ode

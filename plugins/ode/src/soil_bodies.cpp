// The plugin's bodies on soft soil (soil_bodies.hpp).
#include "soil_bodies.hpp"

#include <cstring>
#include <string>

#include "conversions.hpp"
#include "wtc/base/error.hpp"

namespace wtc::ode {

SoilBodyId SoilBodies::add(const SoilBody& spec, bool is_wheel) {
  static constexpr const char* kWhere = "wtc::ode::Plugin::addSoilBody";
  if (spec.body == nullptr) throw InvalidInputError(std::string(kWhere) + ": body is null");
  if (is_wheel) {
    throw InvalidInputError(std::string(kWhere) + ": this body is a registered wheel's: the soil meets it as one");
  }
  if (of_body_.count(spec.body) != 0)
    throw InvalidInputError(std::string(kWhere) + ": this body is already a soil body");
  dMass m;
  dBodyGetMass(spec.body, &m);
  auto b = std::make_unique<Body>(Body{.body = spec.body, .soil = BodyOnSoil(spec.hulls, m.mass, kWhere), .last = {}});
  const auto id = static_cast<SoilBodyId>(bodies_.size());
  of_body_.emplace(spec.body, id);
  bodies_.push_back(std::move(b));
  return id;
}

void SoilBodies::step(const Terrain& terrain, GroundMemory* memory, double h) {
  for (const auto& b : bodies_) {
    BodySoilMotion motion;
    motion.pose.linear() = rotationFromOde(dBodyGetRotation(b->body));
    motion.pose.translation() = toEigen(dBodyGetPosition(b->body));
    motion.velocity = toEigen(dBodyGetLinearVel(b->body));
    motion.angular_velocity = toEigen(dBodyGetAngularVel(b->body));
    b->last = b->soil.step(terrain, memory, motion, h);
    if (b->last.nodes == 0) continue;
    // The torque is about the body's frame's origin, its centre of mass.
    dBodyAddForce(b->body, b->last.force.x(), b->last.force.y(), b->last.force.z());
    dBodyAddTorque(b->body, b->last.torque.x(), b->last.torque.y(), b->last.torque.z());
  }
}

const BodySoilForces& SoilBodies::forces(SoilBodyId id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= bodies_.size()) {
    throw InvalidInputError("wtc::ode::Plugin::soilForces: soil body " + std::to_string(id) + " is not registered (" +
                            std::to_string(bodies_.size()) + " soil bodies)");
  }
  return bodies_[static_cast<std::size_t>(id)]->last;
}

int SoilBodies::keepRigidContacts(const TerrainGeoms& terrain, dGeomID a, dGeomID b, dContactGeom* contacts, int count,
                                  int stride) const {
  if (bodies_.empty()) return count;
  const bool ground_is_a = terrain.contains(a);
  if (ground_is_a == terrain.contains(b)) return count;
  const dGeomID ground = ground_is_a ? a : b;
  const dBodyID body = dGeomGetBody(ground_is_a ? b : a);
  if (body == nullptr || of_body_.count(body) == 0) return count;
  const Terrain& pieces = terrain.terrain();
  auto* bytes = reinterpret_cast<unsigned char*>(contacts);
  int kept = 0;
  for (int k = 0; k < count; ++k) {
    const auto* c = reinterpret_cast<const dContactGeom*>(bytes + static_cast<std::ptrdiff_t>(k) * stride);
    const PieceId piece = terrain.piece(ground, toEigen(c->pos));
    if (piece >= 0 && pieces.material(piece).soil) continue;
    if (kept != k) std::memmove(bytes + static_cast<std::ptrdiff_t>(kept) * stride, c, sizeof(dContactGeom));
    ++kept;
  }
  return kept;
}

}  // namespace wtc::ode

#pragma once
// wtc::ode: WTC wheels in any ODE world (dWorldStep or dWorldQuickStep).
// The adapter does nothing physical itself: it reads poses and velocities
// from ODE, asks the core (wtc::TyreModel, one step per wheel per world
// step), and hands the core's contacts and forces back to ODE.
// docs/ode-plugin.md has the details and the validation.
//
// How it plugs in:
//  - The terrain's pieces become static ODE geoms (TerrainGeoms) in their
//    own quadtree space inside the user's space; every pair but
//    wheel-terrain collides with them through ODE's own colliders.
//  - A wheel is the user's body and its collision geom (a cylinder or a
//    sphere), registered here; the plugin knows it by its geom.
//  - ODE has no pre-step callback, so the program calls the plugin itself,
//    once per world step, in this order:
//
//      plugin.beginStep(h);                   // 1. every wheel's tyre model
//      dSpaceCollide(space, data, &near);     // 2. near() calls handlePair first
//      dWorldStep(world, h);                  // 3. or dWorldQuickStep
//      dJointGroupEmpty(contacts);            // 4. as every ODE program does
//
//    where near(a, b) starts with
//      if (plugin.handlePair(a, b, contacts)) return;  // wheel-terrain: WTC's
//    and goes on as before for every other pair (dSpaceCollide2 into
//    spaces, dCollide, contact joints).
//
// Force mode: beginStep applies each wheel's tyre wrench with
// dBodyAddForceAtPos and dBodyAddTorque. ODE integrates the accumulated
// forces over the next step and clears them at its end, so they act on
// exactly that step and never pile up (unlike Bullet's substeps). The
// pairs handled by handlePair create no joint.
// Constraint mode: handlePair turns the wheel's contacts (wtc::SolverContact,
// one per contact the core found, even if ODE reports the wheel against
// several pieces) into dContact joints: soft ERP and CFM from
// wtc::softConstraint (the tyre's spring-damper, implicit in ODE's solver),
// mu the slip law's coefficient (dContactApprox1: a coefficient, not a
// force) along fdir1, the traction's direction, and no second friction
// direction (mu2 = 0: a cone's cap, not ODE's pyramid). Rolling resistance
// is an explicit torque in both modes.
//
// Bodies on soft soil (addSoilBody; docs/soft-soil.md, "A body on the
// soil"): beginStep puts on each registered body the soil's pressure and
// shear under it (wtc::BodyOnSoil), after the wheels; the near callback
// drops its rigid contacts with soil pieces by calling keepRigidContacts
// after dCollide (a body-terrain pair is the user's, not WTC's):
//
//      int n = dCollide(a, b, max, &contact[0].geom, sizeof(dContact));
//      n = plugin.keepRigidContacts(a, b, &contact[0].geom, n, sizeof(dContact));
//
// Lifetime: the terrain and the registered bodies and geoms must outlive
// the plugin, and the plugin must be destroyed before the user's space
// (which would otherwise destroy the terrain space first) and the world.
// Registered wheels are kept awake (auto-disable off): the tread state needs
// every step.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <ode/ode.h>
#include <Eigen/Core>

#include "wtc/adapter/solver_contact.hpp"
#include "wtc/adapter/wheel_listener.hpp"
#include "wtc/adapter/wheel_spec.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/ode/terrain_geoms.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/tyre/tyre_model.hpp"

namespace wtc::ode {
namespace detail {
struct PluginState;
}  // namespace detail

using WheelId = wtc::WheelId;
using WheelListener = wtc::WheelListener;

/// A wheel: an ODE body and its collision geom (on a hinge to its carrier,
/// typically). ODE bodies have their origin at the centre of mass.
/// wtc/adapter/wheel_spec.hpp: what the wheel is and where its inertia
/// comes from.
struct RigidWheel : WheelSpec {
  dBodyID body = nullptr;                                 ///< The wheel (not owned).
  dGeomID geom = nullptr;                                 ///< Its geom, attached to `body` (not owned).
  Eigen::Vector3d axle_local{Eigen::Vector3d::UnitZ()};   ///< Axle in the body frame: z, ODE's cylinder axis.
  Eigen::Vector3d centre_local{Eigen::Vector3d::Zero()};  ///< Wheel centre O in the body frame (m).
};

/// One WTC contact as ODE solved it (constraint mode). `feedback` is the
/// contact joint's dJointFeedback: ODE fills it during the world step, so
/// the forces are those of the last completed step (until that step, from
/// the joint's creation in handlePair, its f1[0] is NaN: not yet solved).
struct SolvedContact {
  SolverContact contact;      ///< What the plugin gave ODE.
  dJointFeedback feedback{};  ///< f1, t1: the joint's force and torque on the wheel body.
  /// The joint's force on the wheel (N, world).
  Eigen::Vector3d force() const { return {feedback.f1[0], feedback.f1[1], feedback.f1[2]}; }
  /// Its component along contact.normal (N, >= 0) and the rest (N).
  double normalForce() const { return force().dot(contact.normal); }
  Eigen::Vector3d tangentialForce() const { return force() - normalForce() * contact.normal; }
};

/// Non-fatal conditions, counted per wheel (read them after the near
/// callback has run for the step).
struct WheelDiagnostics {
  /// Constraint-mode steps whose contacts never reached ODE: the wheel had
  /// contacts but handlePair did not see it against the terrain (a near
  /// callback without handlePair, a geom disabled or filtered out).
  std::uint64_t unhandled_steps = 0;
  /// Constraint-mode contacts whose spring ODE's correcting-velocity cap
  /// cut: ERP Z / h above dWorldGetContactMaxCorrectingVel (leave the cap at
  /// its default, infinity, for WTC's wheels; implicit mode refuses a cap).
  std::uint64_t capped_contacts = 0;
};

/// A body whose underside meets soft soil (wtc/tyre/body_soil.hpp).
struct SoilBody {
  dBodyID body = nullptr;  ///< Not owned.
  /// Its shape in the body's frame (ODE's: at its centre of mass; m), one
  /// or more convex hulls.
  std::vector<ConvexPolyhedron> hulls;
};
using SoilBodyId = int;

class Plugin {
 public:
  /// Mirrors `terrain` (which must outlive the plugin) as geoms of `shape`
  /// in a new space inside `space`. Contact joints are created in `world`.
  Plugin(dWorldID world, dSpaceID space, const Terrain& terrain, ContactMode mode = ContactMode::kForce,
         TerrainShape shape = TerrainShape::kTriMesh);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  /// Registers a wheel. Throws InvalidInputError naming the problem: null
  /// body or geom, a geom on another body, a zero axle, invalid parameters,
  /// a wheel registered twice, and in constraint mode a geom whose bounding
  /// box does not hold the tread (the near callback would miss ground the
  /// tread touches).
  WheelId addWheel(const RigidWheel& wheel);

  /// Step 1 of the call order: runs every wheel's tyre model for a world
  /// step of `step_seconds` (> 0) from the bodies' current state; force
  /// mode applies the forces, constraint mode prepares the contacts.
  void beginStep(double step_seconds);

  /// Step 2, from the near callback: true if (a, b) is a registered wheel's
  /// geom against the terrain (its space or one of its pieces): the pair is
  /// WTC's and the callback should return. In constraint mode the wheel's
  /// contact joints go into `contacts` the first time its pair comes up in
  /// the step. False for any other pair.
  bool handlePair(dGeomID a, dGeomID b, dJointGroupID contacts);

  /// Registers a body whose underside meets the terrain's soil pieces as
  /// soft soil (InvalidInputError: a null body, a registered soil body, a
  /// body that is a registered wheel's, hulls BodyOnSoil refuses). In a
  /// soil region it reads and presses the ground's memory.
  SoilBodyId addSoilBody(const SoilBody& body);
  /// What the soil did to it in the last beginStep.
  const BodySoilForces& soilForces(SoilBodyId body) const;
  int soilBodyCount() const;
  /// From the near callback, after dCollide(a, b) of a pair handlePair did
  /// not take: of the `count` contacts (each `stride` bytes after the last:
  /// sizeof(dContact) when they are an array of dContact's geoms), keeps
  /// at the front those that are not a soil body's on a piece with a soil,
  /// and returns how many. A pair that is not a soil body's against the
  /// terrain keeps them all.
  int keepRigidContacts(dGeomID a, dGeomID b, dContactGeom* contacts, int count,
                        int stride = sizeof(dContactGeom)) const;

  /// The last beginStep's result and state of a wheel (these accessors
  /// throw std::out_of_range for an id that is not registered).
  const WheelForces& forces(WheelId wheel) const;
  const WheelState& state(WheelId wheel) const;
  /// What the terrain's soil regions remember (wtc/tyre/ground_memory.hpp):
  /// every wheel reads and presses it; empty without a region. Writable
  /// between steps: ruts a run left, read back (wtc/io/ground_memory_file.hpp).
  const GroundMemory& groundMemory() const;
  GroundMemory& groundMemory();
  /// What acted on the wheel in the last world step (call it after the
  /// step): forces() in force mode; in constraint mode the forces ODE's
  /// solver applied at each contact (the joints' feedback), their wrench
  /// and the rolling moment (wtc::MountedWheel::applied), assembled at the
  /// first call once ODE has solved every joint of the step and kept until
  /// the next beginStep (before the world step a contact counts as no
  /// force). Report these, not forces(), as the contact forces of a
  /// constraint-mode run.
  const WheelForces& applied(WheelId wheel) const;
  /// The wheel's contacts as ODE solved them in the last world step
  /// (constraint mode; empty in force mode).
  std::span<const SolvedContact> solvedContacts(WheelId wheel) const;
  /// Non-fatal conditions met by the wheel since its registration.
  const WheelDiagnostics& diagnostics(WheelId wheel) const;
  int wheelCount() const;
  /// Wall time (s) the plugin's own per-step work took since construction:
  /// reading the wheels' state, their contacts, the tyre model and handing
  /// the result to the engine (wtc::StepClock), the engine's solve not
  /// included. Against the simulation's wall time: WTC's share of a step.
  double contactSeconds() const;

  ContactMode mode() const;
  const TerrainGeoms& terrainGeoms() const;
  /// Called by beginStep for each wheel after its tyre model ran (before
  /// ODE integrates the step); null: none.
  void setListener(WheelListener* listener);

 private:
  // The plugin's state (plugins/ode/src/plugin_state.hpp).
  std::unique_ptr<detail::PluginState> state_;
};

}  // namespace wtc::ode

#pragma once
// The state behind wtc::ode::Plugin (internal to wtc::ode).
#include <memory>
#include <unordered_map>
#include <vector>

#include "adapter/mounted_wheel.hpp"
#include "adapter/step_clock.hpp"
#include "soil_bodies.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/ode/plugin.hpp"

namespace wtc::ode {

struct Wheel {
  Wheel(const WheelDescription& description, EffectSet effects, ContactMode mode)
      : mounted(description, effects, mode) {}
  ~Wheel() {
    if (cap_geom != nullptr) dGeomDestroy(cap_geom);
  }
  Wheel(const Wheel&) = delete;
  Wheel& operator=(const Wheel&) = delete;

  dBodyID body = nullptr;
  dGeomID geom = nullptr;
  dGeomID cap_geom = nullptr;  // the cut sphere's caps, on the body, in no space (collideCaps)
  Eigen::Vector3d axle_local, centre_local;
  MountedWheel mounted;  // tyre model, state, this step's result and engine contacts
  // Constraint mode: this step's contacts with their joints' feedback. ODE
  // writes each joint's feedback here during the world step, so the vector
  // changes only in beginStep (the previous step's joints are gone by then:
  // dJointGroupEmpty).
  std::vector<SolvedContact> contacts;
  std::vector<Eigen::Vector3d> solved_forces;  // scratch for MountedWheel::setSolvedForces
  bool handled = false;                        // handlePair has seen this wheel against the terrain this step
  bool applied_ready = false;                  // constraint mode: mounted.applied() holds this step's solve
  WheelDiagnostics diagnostics;
};

namespace detail {

struct PluginState {
  PluginState(dWorldID world, dSpaceID space, const Terrain& terrain, ContactMode mode, TerrainShape shape);
  WheelId add(const RigidWheel& spec);
  void beginStep(double step_seconds);
  bool handlePair(dGeomID a, dGeomID b, dJointGroupID contacts);
  void collideCaps(Wheel& wheel, dGeomID ground, dJointGroupID contacts);
  const Wheel& wheel(WheelId id) const;
  const WheelForces& applied(WheelId id);

  dWorldID world;
  TerrainGeoms terrain;
  // The soil regions' memory, which every wheel reads and presses (null
  // in a wheel's state when the terrain has none).
  GroundMemory ground_memory;
  ContactMode mode;
  double step_seconds = 0.0;  // of the current step, for the joints' ERP and CFM
  std::vector<std::unique_ptr<Wheel>> wheels;
  std::unordered_map<dGeomID, WheelId> wheel_of;
  WheelListener* listener = nullptr;
  StepClock clock;  // beginStep and the wheel-terrain pairs of handlePair
  SoilBodies soil_bodies;  // bodies on soft soil (addSoilBody)
};

}  // namespace detail
}  // namespace wtc::ode

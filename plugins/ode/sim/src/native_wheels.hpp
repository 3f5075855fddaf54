#pragma once
// ODE's own wheels in the ODE sim engine (the native-wheel baseline): the
// wheel geoms (cylinder or sphere, NativeWheelShape) meet the terrain's
// geoms through ODE's colliders, with its contact joint and the Coulomb
// friction (dContactApprox1) of the piece's mu; after each step the joints'
// feedback is read back as the wheels' forces.
#include <cstddef>
#include <deque>
#include <span>
#include <vector>

#include "ode_wheels.hpp"
#include "sim/native_wheel_contacts.hpp"
#include "wtc/ode/plugin.hpp"

namespace wtc::ode {

class NativeWheels final : public sim::NativeWheels<Plugin, OdeWheels> {
 public:
  /// Wheel k is bodies[k]; contact joints are made in `world`, in `contacts`.
  NativeWheels(const sim::Engine& engine, Plugin& plugin, dWorldID world, dJointGroupID contacts,
               const Terrain& terrain, std::span<const WheelBody> bodies, sim::NativeWheelShape shape);

  /// A wheel's geom against a terrain piece: ODE's contacts, with the
  /// piece's friction and feedback.
  bool collide(dGeomID a, dGeomID b) override;
  /// Reads the feedback of the step's contacts.
  void stepped() override;

 private:
  // One contact of a wheel this step: ODE writes the force on the wheel
  // (body 1) into `feedback`.
  struct RecordedContact {
    int wheel = -1;
    dContactGeom geom{};
    dJointFeedback feedback{};
  };

  // The wheel whose geom is `geom`, or -1.
  int wheelOf(dGeomID geom) const;
  void collideWheel(int wheel, dGeomID wheel_geom, dGeomID ground);

  dWorldID world_;
  dJointGroupID contacts_;
  const Terrain& terrain_;
  std::vector<dGeomID> geoms_;                     // per wheel
  std::vector<double> mu_;                         // per material id
  std::deque<RecordedContact> recorded_contacts_;  // grows to the most contacts a step had; never shrinks
  std::size_t recorded_ = 0;                       // used this step
};

}  // namespace wtc::ode

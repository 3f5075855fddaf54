#pragma once
// An ODE world with WTC plugged in, and wheel bodies, for the validation
// scenes of the ODE plugin. Gravity -9.81 m/s^2 along z; the wheel is a
// cylinder (radius r_f, width w) whose axis, ODE's local z, lies along the
// world's y axis. ODE is initialised once for the test program (a GoogleTest
// environment in ode_fixture.cpp).
#include <memory>

#include <ode/ode.h>
#include <Eigen/Core>

#include "wheel_sim.hpp"
#include "wtc/ode/plugin.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::testing {

enum class Stepper { kStep, kQuickStep };

/// A disc-like wheel: mass (kg), ODE's solid cylinder inertia (axial
/// m r^2 / 2), its geom in the world's space.
struct OdeWheel {
  dBodyID body = nullptr;
  dGeomID geom = nullptr;
  double mass = 0.0;
};

/// The world, its space and contact group, and the plugin; step() runs one
/// world step in the plugin's call order.
class OdeWorld {
 public:
  OdeWorld(const Terrain& terrain, ContactMode mode, Stepper stepper = Stepper::kStep,
           ode::TerrainShape shape = ode::TerrainShape::kTriMesh);
  ~OdeWorld();
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;

  /// A wheel body (r_f = 0.19 m, w = 0.12 m) centred at `centre`, at rest.
  OdeWheel addWheelBody(double mass, const Eigen::Vector3d& centre);
  /// beginStep, collide(), the world step, dJointGroupEmpty.
  void step(double step_seconds);
  /// dSpaceCollide with an ordinary near callback that calls handlePair first.
  void collide();

  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contacts = nullptr;
  std::unique_ptr<ode::Plugin> plugin;
  Stepper stepper;
  bool call_handle_pair = true;  ///< false: a near callback that forgot the plugin.
};

/// Registers `wheel` with the robot wheel's defaults; the plugin reads its
/// mass and axial inertia from the body (a free wheel's spin).
ode::WheelId addWheel(OdeWorld& w, const OdeWheel& wheel, EffectSet effects = EffectSet::full(),
                      const TyreParameters& tyre = {});

/// An angular motor holding a body upright (no rotation about world x and
/// z; a wheel's spin about y free), or all its rotation (a parked wheel's
/// brake; an axle kept level by the rest of its vehicle). A constraint, not
/// dBodySetAngularVel(0) before each step: in constraint mode the wheel
/// would still roll within each step, its contact point held by the
/// friction joint (measured: 51 mm in 10 s on 15 deg at 1 ms, instead of
/// 0.4 mm).
void keepUpright(OdeWorld& w, dBodyID body);
void lockRotation(OdeWorld& w, dBodyID body);

Eigen::Vector3d position(dBodyID body);
Eigen::Vector3d velocity(dBodyID body);

}  // namespace wtc::testing

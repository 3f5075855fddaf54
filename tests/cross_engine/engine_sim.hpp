#pragma once
// One WTC wheel in one engine, behind one interface, so that a scene is
// written once and run in Bullet, ODE and MuJoCo (the cross-engine tests). The
// wheel is the robot's (r_f = 0.19 m, w = 0.12 m, a disc's inertia), its
// axle along world y, its spin about y.
#include <memory>
#include <string>

#include <Eigen/Core>

#include "wtc/adapter/solver_contact.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/tyre_parameters.hpp"
#include "wtc/tyre/wheel_forces.hpp"

namespace wtc::testing {

/// kOde steps with dWorldStep, kOdeQuick with dWorldQuickStep (20 iterations);
/// kMujoco with wtc::mujoco::Plugin::step (MuJoCo's Euler step).
enum class Engine { kBullet, kOde, kOdeQuick, kMujoco };
std::string engineName(Engine engine);
/// Whether the engine's adapter serves `mode` (MuJoCo: not implicit mode,
/// docs/mujoco-plugin.md).
bool serves(Engine engine, ContactMode mode);
/// MuJoCo's impratio in the cross-engine wheel's model: the sim engine's
/// (plugins/mujoco/sim/src/mujoco_constants.hpp). Its soft cone's friction
/// compliance is R / impratio (docs/mujoco-plugin.md, "Friction").
inline constexpr double kMujocoImpratio = 10.0;

/// What holds the wheel's rotation: nothing, upright (spin about y only, as
/// its hinge would), or locked (a parked wheel's brake).
enum class Hold { kFree, kUpright, kLocked };

class EngineSim {
 public:
  virtual ~EngineSim() = default;
  /// Adds force (N, at the centre) and torque about y (N m) for the next step.
  virtual void push(const Eigen::Vector3d& force, double torque_y) = 0;
  virtual void setMotion(const Eigen::Vector3d& velocity, double spin_y) = 0;
  /// One step of the engine with the plugin, h (s).
  virtual void step(double step_seconds) = 0;
  virtual Eigen::Vector3d position() const = 0;
  virtual Eigen::Vector3d velocity() const = 0;
  /// The tyre model's result of the last step.
  virtual const WheelForces& forces() const = 0;
  /// What acted on the wheel in the last step (the plugin's applied()).
  virtual const WheelForces& applied() const = 0;
};

/// A wheel of `mass` (kg) at `centre` on `terrain` (which must outlive it),
/// with `tyre` (the robot's by default).
std::unique_ptr<EngineSim> makeEngineSim(Engine engine, ContactMode mode, const Terrain& terrain, double mass,
                                         const Eigen::Vector3d& centre, Hold hold, const TyreParameters& tyre = {});

}  // namespace wtc::testing

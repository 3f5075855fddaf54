#pragma once
// One engine interface for whole vehicles (wtc::sim). Design note:
//
// An Engine holds one world: the terrain, one vehicle built from its
// engine-free description (wtc::vehicle::VehicleDescription), its WTC wheels
// through the engine's plugin (or the engine's own wheels), and a motor on
// every driven joint. Each engine implements it once, beside its plugin
// (wtc::bullet_sim, wtc::ode_sim), and registers itself in the engine table
// (wtc/sim/engine_table.hpp, wtc::sim_engines); makeEngine builds the one
// EngineSettings::engine names. The run loop, the controllers, the tests
// and the benchmarks drive every engine through this interface, so a scene
// is written once.
//
// Indices are the description's body indices throughout. A step:
//   setMotorTarget / addForce for the next step   (the caller: controller, hitch)
//   step()                                        (tyre models, collision, solve)
//   body / jointPosition / motorEffort / wheelForces   (the state after it)
// Joint coordinates are zero at the description's reference configuration:
// a revolute joint's angle is the child's rotation about the axis relative
// to its parent, a prismatic joint's position the child's displacement
// along it.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

#include "wtc/adapter/wheel_listener.hpp"
#include "wtc/sim/start_velocity.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/contact_mode.hpp"
#include "wtc/tyre/effects.hpp"
#include "wtc/tyre/tyre_model.hpp"
#include "wtc/vehicle/drive.hpp"
#include "wtc/vehicle/hitch_law.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim {

/// The engine's own wheel contact, a baseline to compare WTC with: the
/// wheel body collides with the terrain pieces as a cylinder (or a sphere
/// of radius r_f) through the engine's own collision, with its default
/// rigid contact and Coulomb friction at the peak of the ground's mu(s); no
/// tyre model, no rolling resistance. Each engine chooses its native-wheels
/// strategy with it once, when it is built.
enum class NativeWheelShape { kCylinder, kSphere };

struct EngineSettings {
  /// The engine, by its name in the engine table (wtc/sim/engine_table.hpp,
  /// wtc::sim_engines): "bullet", "ode" (dWorldStep, direct), "ode_quick"
  /// (dWorldQuickStep, iterative).
  std::string engine = "bullet";
  ContactMode mode = ContactMode::kForce;  ///< WTC's contact mode (unused with native_wheels).
  /// The engine's own wheel contact instead of WTC's wheels; none: WTC's.
  std::optional<NativeWheelShape> native_wheels = std::nullopt;
  double step_seconds = 4e-4;  ///< h (s), > 0: the source's mean step.
  int solver_iterations = 50;  ///< Iterative solvers' iterations per step (Bullet, ODE quickstep), > 0.
  /// Bullet's solver stops iterating once the squared velocity errors of
  /// its rows sum below this ((m/s)^2, > 0): 1e-6 is about 3e-4 m/s on each
  /// of the robot's dozen rows, and brings the ledge climb as close to the
  /// reference as ODE's direct solver at the same step (docs/accuracy-
  /// study.md). ODE's quickstep always runs its iterations.
  double solver_residual = 1e-6;
  EffectSet tyre_effects = EffectSet::full();
  /// Where `engine` came from, for the message that refuses a name the
  /// table does not have: a scene file's "<file>:<line>:<col>: engine"
  /// (the scene reader, a layer below the table, keeps the place and the
  /// table judges the name when the engine is made).
  std::string engine_where = "engine";
};

/// How the wheels meet the ground, as scenes, summaries and reports name it:
/// "force", "constraint", "implicit" (WTC's modes), "engine_cylinder", "engine_sphere".
std::string_view modeName(const EngineSettings& settings);
/// Sets mode and native_wheels from such a name; InvalidInputError naming
/// `where` and the known names otherwise.
void parseMode(std::string_view name, EngineSettings& settings, const std::string& where);

/// The Coulomb coefficients of the native-wheel baseline, per material id
/// of `terrain`: the peak of each material's mu(s) (the static coefficient
/// of a tread that may stick).
std::vector<double> nativeWheelFrictions(const Terrain& terrain);

/// Whether a wheel body's collision shape in the engine is a sphere of
/// radius r_f rather than a cylinder of radius r_f and width w: for
/// NativeWheelShape::kSphere, and for any wheel as wide as its sphere
/// (w >= 2 r_f), whose cylinder would reach past the sphere. (WTC's wheels
/// keep the shape for every pair but wheel-terrain.)
bool treadIsSphere(const EngineSettings& settings, const WheelGeometry& geometry);

/// Throws InvalidInputError naming the field and `where`.
void validate(const EngineSettings& settings, const std::string& where);

/// A message an engine's solver gave as it went on stepping, counted
/// instead of printed: ODE's "LCP internal error, s <= 0" says that its
/// direct solver stopped pivoting and left the rows it had not solved
/// without force in that step (wtc/ode/message_log.hpp). WTC's ODE engine
/// does not keep such a solve: it solves the step again without the rows
/// that made the pivot degenerate and, where ODE still gives up, by
/// dWorldQuickStep; only that last case is a message here
/// (plugins/ode/sim/src/direct_step.hpp, docs/hard-cases.md).
struct SolverMessage {
  std::string engine;         ///< Whose: "ODE".
  std::string text;           ///< The message without its numbers: "LCP internal error, s <= 0".
  std::uint64_t steps = 0;    ///< Steps in which it came, once or more.
  std::uint64_t count = 0;    ///< Times it came.
  double first_time_s = 0.0;  ///< The end of the first such step (s of simulated time since the engine was built).
};

class Engine {
 public:
  virtual ~Engine() = default;

  /// The motor of `body`'s joint for the next step (ignored for a body
  /// without a drive; an inactive target switches the motor off).
  virtual void setMotorTarget(int body, const vehicle::MotorTarget& target) = 0;
  /// A force (N, world) at a world point on `body`, for the next step only.
  virtual void addForce(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point) = 0;
  /// One step of settings().step_seconds.
  virtual void step() = 0;
  /// Gravity for the next steps (m/s^2, world; (0, 0, -kGravityMps2) until
  /// set): a scene's tilt table turns it slowly instead of the ground
  /// (sim::TiltTable). Run::setGravity also tells the energy balance.
  virtual void setGravity(const Eigen::Vector3d& g_W) = 0;
  /// Before the first step: every body's velocity (one per body, world),
  /// such as startVelocities gives. The engines keep what their joints
  /// allow: Bullet's multibodies take the roots' velocities and each
  /// joint's rate from the child's velocity against its parent's, ODE takes
  /// each body's as given; the two agree for velocities the joints allow
  /// (startVelocities' do). Throws InvalidInputError for a wrong count.
  virtual void setVelocities(std::span<const BodyVelocity> velocities) = 0;

  /// Pose and velocity of a body's centre of mass (world), the pose in the
  /// frame the engine integrates it in (Body::pose's; principal axes for a
  /// URDF tensor with products of inertia): vehicle::ownFrame turns it to
  /// the body's own axes, as every output gives them.
  virtual vehicle::BodyKinematics body(int body) const = 0;
  /// Coordinate (rad or m) and rate of `body`'s joint to its parent
  /// (revolute and prismatic joints; 0 for others).
  virtual double jointPosition(int body) const = 0;
  virtual double jointRate(int body) const = 0;
  /// The effort `body`'s motor applied in the last step (N m or N).
  virtual double motorEffort(int body) const = 0;
  /// What acted on a wheel body in the last step (the plugins' applied():
  /// the tyre model's forces in force mode, the forces the engine's solver
  /// applied at WTC's contacts in constraint mode), and its tyre state.
  virtual const WheelForces& wheelForces(int body) const = 0;
  virtual const WheelState& wheelState(int body) const = 0;
  /// Called for each wheel at each step after its tyre model ran; null:
  /// none. Its WheelId k is the k-th wheel of vehicle().wheels().
  virtual void setWheelListener(WheelListener* listener) = 0;
  /// Wall time (s) WTC's plugin took in the steps so far (its
  /// contactSeconds): WTC's part of the steps' cost.
  virtual double contactSeconds() const = 0;
  /// The memory of the soft ground the engine's plugin keeps for this
  /// world (wtc/tyre/ground_memory.hpp), which its WTC wheels and its
  /// bodies on soil read and press: null where the terrain has no soil
  /// regions.
  virtual GroundMemory* groundMemory() const = 0;
  /// What the engine's solver said in the steps so far, by message (none
  /// for an engine whose solver says nothing).
  virtual std::vector<SolverMessage> solverMessages() const { return {}; }

  const EngineSettings& settings() const { return settings_; }
  const vehicle::VehicleDescription& vehicle() const { return vehicle_; }

 protected:
  Engine(const EngineSettings& settings, const vehicle::VehicleDescription& vehicle)
      : settings_(settings), vehicle_(vehicle) {}

 private:
  EngineSettings settings_;
  vehicle::VehicleDescription vehicle_;
};

/// The world pose of each body at the start: `placement` (the vehicle frame
/// V in the world) times its reference pose, for an engine to build from.
Eigen::Isometry3d startPose(const vehicle::VehicleDescription& vehicle, int body, const Eigen::Isometry3d& placement);

/// engine.groundMemory() (Engine::groundMemory).
inline GroundMemory* groundMemory(const Engine& engine) { return engine.groundMemory(); }

/// What a tyre model needs of a wheel body: its geometry and tyre, and as
/// inertia the body's own mass and its moment about the axle.
WheelDescription wheelDescription(const vehicle::Body& body);

}  // namespace wtc::sim

#pragma once
// A vehicle's controller (wtc::vehicle): sensors in, drive commands out,
// once per engine step. Engine-free: it sees what a real robot's sensors
// give (body poses and rates as an IMU and odometry would, joint positions
// and rates from encoders, each wheel's contact as WTC measures it), never
// the terrain.
#include <map>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wtc/vehicle/drive.hpp"
#include "wtc/vehicle/hitch_law.hpp"

namespace wtc::vehicle {

/// One of a wheel's contacts with the ground, as WTC finds it.
struct SensedContact {
  Eigen::Vector3d point{Eigen::Vector3d::Zero()};    ///< The ground point P (world, m).
  Eigen::Vector3d normal{Eigen::Vector3d::UnitZ()};  ///< Out of the ground toward the wheel centre (unit, world).
  double load = 0.0;                                 ///< Normal force (N).
};

/// A wheel's contact, as a load cell in its hub and WTC's contact state
/// report it.
struct WheelSensor {
  int contacts = 0;                                ///< Contacts with the ground this step.
  Eigen::Vector3d force{Eigen::Vector3d::Zero()};  ///< Ground force on the wheel (N, world).
  Eigen::Vector3d contact_normal{
      Eigen::Vector3d::UnitZ()};      ///< Load-weighted mean normal, unit (world); +z without contact.
  std::vector<SensedContact> points;  ///< Each contact (a wheel at a step's foot has two).
};

/// Everything a controller may read, indexed by body (the description's
/// order); `wheels` is empty for bodies that are not wheels.
struct VehicleState {
  double time = 0.0;                   ///< Since the start (s).
  std::vector<BodyKinematics> bodies;  ///< Centre-of-mass poses and velocities (world).
  std::vector<double> joint_position;  ///< Of each body's joint to its parent (rad or m; 0 for roots).
  std::vector<double> joint_rate;      ///< (rad/s or m/s).
  std::vector<WheelSensor> wheels;     ///< Per body; meaningful for wheels only.
};

class Controller {
 public:
  virtual ~Controller() = default;
  /// The drive commands for the next step: `commands` has one entry per
  /// body (kOff for bodies without a drive), pre-filled with the last ones.
  virtual void update(const VehicleState& state, std::span<DriveCommand> commands) = 0;
  /// The controller's own figures for the run's summary (a tracking error,
  /// a phase reached), added to `fields` by name with units in the name.
  /// May throw InvalidInputError for figures it cannot give (a Python
  /// controller's summary() that is not numbers): the run keeps its own
  /// figures and reports the message as a warning.
  virtual void summarize(std::map<std::string, double>& fields) const { (void)fields; }
  /// True once the controller could not do its task (a path it could not
  /// hold): the run then fails, and says why (failure()).
  virtual bool failed() const { return false; }
  virtual std::string failure() const { return {}; }
};

}  // namespace wtc::vehicle

#include "wtc/vehicle/controllers/climb_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace {

// A contact normal with n . forward below this points back at the robot:
// the wheel presses on a face ahead (cos 127 deg).
constexpr double kFaceNormalForward = -0.6;
// A contact normal with n_z above this carries the wheel from below: it
// stands on an edge (60 deg from the vertical) ...
constexpr double kEdgeNormalUp = 0.5;
// ... and above this on a surface (25 deg from the vertical).
constexpr double kTopNormalUp = 0.9;
// A front wheel stands on the top edge once it stands on a point at least
// this far above the ground under the start (m): higher than any bump of
// the approach it should ignore, lower than any step worth climbing.
constexpr double kRaisedFrontM = 0.05;
// The middle wheels are lifted until M stands this many wheel radii above
// the measured edge: their contact with it then points 49 deg from the
// vertical, which a driven wheel pulled by the front axle rolls over.
constexpr double kLiftAboveEdgeRadii = 0.75;
// A wheel is on the top once its contact point is at most this far below
// the measured edge (m): the edge estimate's error plus the tyre deflection.
constexpr double kOnTopToleranceM = 0.05;
// Gains of the levelling loop (fold rate per radian of middle pitch, 1/s),
// the lift loop (1/s, on the height error over the arm), the heading hold
// (yaw rate per radian of heading error, 1/s).
constexpr double kLevelGain = 4.0;
constexpr double kLiftGain = 3.0;
constexpr double kHeadingGain = 1.0;
// Approach: after one front wheel touches, the other side has this long to
// touch too (s) before the robot starts climbing anyway.
constexpr double kSquareUpSeconds = 2.0;
// At the front fold's limit (within kFoldLimitMarginRad) without reaching
// the edge for kFoldLimitSeconds, the step is out of reach.
constexpr double kFoldLimitMarginRad = 0.03;
constexpr double kFoldLimitSeconds = 1.5;
// Raising the front: with both front wheels in the air above this fold
// angle (rad), the fold comes down at this fraction of its rated speed to
// set them on the top.
constexpr double kLowerOntoTopFromRad = 30.0 * std::numbers::pi / 180.0;
constexpr double kLowerOntoTopFraction = 0.3;
// The highest step climbable: the rear fold short of its limit by this
// (rad), and the middle wheels' centres this far above the edge (m).
constexpr double kFoldReserveRad = 5.0 * std::numbers::pi / 180.0;
constexpr double kStepClearanceM = 0.0;
// While the rear rises, each front wheel must bear at least this (N): a
// tenth of its share of the robot's weight on level ground.
constexpr double kFrontLoadN = 20.0;
// The rear arm counts as level within this (rad).
constexpr double kLevelRad = 0.05;

double clampRate(double rate, double max) { return std::clamp(rate, -max, max); }

}  // namespace

struct ClimbController::Sensed {
  Eigen::Vector3d forward;                     // horizontal heading (unit)
  double yaw = 0.0, beta = 0.0;                // middle body yaw and pitch (nose up > 0)
  std::array<Eigen::Vector3d, 3> axle;         // axle centres
  double gamma_front = 0.0, gamma_rear = 0.0;  // sections' elevations (rad)
  std::array<std::array<const WheelSensor*, 2>, 3> sensor{};
  std::array<std::array<Eigen::Vector3d, 2>, 3> centre;

  // A contact of wheel (a, s) pressing on a face ahead.
  bool face(int a, int s) const {
    for (const SensedContact& c : sensor[a][s]->points) {
      if (c.normal.dot(forward) < kFaceNormalForward) return true;
    }
    return false;
  }
  // The wheel's total normal load (N).
  double load(int a, int s) const {
    double n = 0.0;
    for (const SensedContact& c : sensor[a][s]->points) n += c.load;
    return n;
  }
  // The highest ground point among the wheel's contacts whose normal is
  // within acos(threshold) of the vertical (one it stands on), or -inf.
  double standZ(int a, int s, double threshold) const {
    double z = -std::numeric_limits<double>::infinity();
    for (const SensedContact& c : sensor[a][s]->points) {
      if (c.normal.z() > threshold) z = std::max(z, c.point.z());
    }
    return z;
  }
};

const char* ClimbController::phaseName(Phase phase) {
  switch (phase) {
    case Phase::kApproach:
      return "approach";
    case Phase::kRaiseFront:
      return "raise front";
    case Phase::kLiftMiddle:
      return "lift middle";
    case Phase::kRaiseRear:
      return "raise rear";
    case Phase::kDriveOn:
      return "drive on";
    case Phase::kStopped:
      return "stopped";
    case Phase::kAborted:
      return "aborted";
  }
  return "?";
}

ClimbController::ClimbController(const VehicleDescription& v, const ClimbControllerParams& p, const std::string& where)
    : params_(p) {
  const auto body = [&](const std::string& name, bool driven) {
    const int b = v.find(name);
    if (b < 0 || (driven && (!v.bodies[b].joint.actuator || v.bodies[b].parent < 0))) {
      throw InvalidInputError(where + ": the climbing controller needs a " + (driven ? "driven body" : "body") + " '" +
                              name + "' (as in vehicles/six_wheel_robot.yaml); vehicle '" + v.name + "' has none");
    }
    return b;
  };
  middle_ = body("middle", false);
  front_fold_ = body("front_carrier", true);
  rear_fold_ = body("rear_carrier", true);
  front_slider_ = body("front_slider", true);
  rear_slider_ = body("rear_slider", true);
  const char* axles[] = {"front", "middle", "rear"};
  for (int a = 0; a < 3; ++a) {
    for (int s = 0; s < 2; ++s) {
      const int w = body(std::string(axles[a]) + (s == 0 ? "_left_wheel" : "_right_wheel"), true);
      if (!v.bodies[w].wheel) throw InvalidInputError(where + ": '" + v.bodies[w].name + "' is not a wheel");
      wheels_[a][s] = w;
    }
  }
  radius_ = v.bodies[wheels_[kMiddle][0]].wheel->geometry.free_radius;
  wheel_max_rate_ = v.bodies[wheels_[kMiddle][0]].joint.actuator->max_speed;
  const auto travel = [&](int b) {
    if (!v.bodies[b].joint.limits) {
      throw InvalidInputError(where + ": '" + v.bodies[b].name + "' needs joint limits for the climbing controller");
    }
    return *v.bodies[b].joint.limits;
  };
  front_travel_ = travel(front_slider_).upper;
  rear_travel_ = travel(rear_slider_).upper;
  fold_max_ = travel(front_fold_).upper;
  fold_speed_ =
      std::min(v.bodies[front_fold_].joint.actuator->max_speed, v.bodies[rear_fold_].joint.actuator->max_speed);
  // The arm from M to an outer axle at zero extension.
  arm_ = (v.bodies[wheels_[kRear][0]].pose.translation() - v.bodies[wheels_[kMiddle][0]].pose.translation()).norm();
  // The highest step: the rear arm, fully out and folded down to its limit
  // less kFoldReserveRad, lifts M above the rear wheels' centres by
  //   (M - A)_z - (R(-reach) (p + L u - A))_z
  // (A the fold axis's anchor, p a rear wheel's centre, u the slider's
  // axis, all at the reference configuration with the middle body level):
  // (arm + L) sin(reach) when the fold axis lies on the middle axle line.
  // The middle wheels ride onto the top only from there (the step's height
  // plus kStepClearanceM below M).
  const double rear_reach = std::min(-travel(rear_fold_).lower, std::numbers::pi / 2) - kFoldReserveRad;
  const vehicle::Joint& rear_fold = v.bodies[rear_fold_].joint;
  const Eigen::Vector3d rear_out = v.bodies[wheels_[kRear][0]].pose.translation() +
                                   rear_travel_ * v.bodies[rear_slider_].joint.axis - rear_fold.anchor;
  const Eigen::Vector3d folded = Eigen::AngleAxisd(-rear_reach, rear_fold.axis) * rear_out;
  const Eigen::Vector3d middle_axle = v.bodies[wheels_[kMiddle][0]].pose.translation() - rear_fold.anchor;
  max_step_ = middle_axle.z() - folded.z() - kStepClearanceM;

  const auto positive = [&](double value, const char* name, double max) {
    if (!std::isfinite(value) || value <= 0.0 || value > max) {
      throw InvalidInputError(where + ": " + name + " " + formatNumber(value) + " must be in (0, " + formatNumber(max) +
                              "]");
    }
  };
  const double top_speed = wheel_max_rate_ * radius_;
  positive(p.approach_speed, "approach_speed (m/s)", top_speed);
  positive(p.crawl_speed, "crawl_speed (m/s)", top_speed);
  positive(p.phase_timeout, "phase_timeout (s)", 1e6);
  if (!std::isfinite(p.drive_on_time) || p.drive_on_time < 0.0) {
    throw InvalidInputError(where + ": drive_on_time must be >= 0 s");
  }
}

ClimbController::Sensed ClimbController::sense(const VehicleState& state) const {
  Sensed s;
  const Eigen::Matrix3d& r = state.bodies[middle_].pose.linear();
  const Eigen::Vector3d x = r.col(0);
  s.forward = Eigen::Vector3d(x.x(), x.y(), 0.0).normalized();
  s.yaw = std::atan2(x.y(), x.x());
  s.beta = std::atan2(x.z(), x.head<2>().norm());
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      s.sensor[a][side] = &state.wheels[wheels_[a][side]];
      s.centre[a][side] = state.bodies[wheels_[a][side]].pose.translation();
    }
    s.axle[a] = 0.5 * (s.centre[a][0] + s.centre[a][1]);
  }
  const Eigen::Vector3d to_front = s.axle[kFront] - s.axle[kMiddle];
  const Eigen::Vector3d to_rear = s.axle[kRear] - s.axle[kMiddle];
  s.gamma_front = std::atan2(to_front.z(), to_front.dot(s.forward));
  s.gamma_rear = std::atan2(to_rear.z(), -to_rear.dot(s.forward));
  return s;
}

void ClimbController::enter(Phase phase, double time) {
  phase_ = phase;
  phase_start_ = time;
}

void ClimbController::abort(const std::string& why, double time) {
  failure_ = std::string("climb aborted in phase '") + phaseName(phase_) +
             "' at t = " + formatNumber(std::round(time * 1e3) / 1e3) + " s: " + why;
  enter(Phase::kAborted, time);
}

void ClimbController::update(const VehicleState& state, std::span<DriveCommand> commands) {
  const double t = state.time;
  const Sensed s = sense(state);
  const double ground_left = s.standZ(kMiddle, 0, kTopNormalUp), ground_right = s.standZ(kMiddle, 1, kTopNormalUp);
  if (!ground_known_ && std::isfinite(ground_left) && std::isfinite(ground_right)) {
    ground_z_ = 0.5 * (ground_left + ground_right);
    ground_known_ = true;
    heading_ = s.yaw;
  }
  max_front_pitch_ = std::max(max_front_pitch_, std::abs(s.gamma_front));
  max_rear_pitch_ = std::max(max_rear_pitch_, std::abs(s.gamma_rear));
  max_middle_pitch_ = std::max(max_middle_pitch_, std::abs(s.beta));

  const double front_fold = state.joint_position[front_fold_];
  const double rear_fold = state.joint_position[rear_fold_];

  if (t - phase_start_ > params_.phase_timeout &&
      (phase_ == Phase::kRaiseFront || phase_ == Phase::kLiftMiddle || phase_ == Phase::kRaiseRear)) {
    abort("the phase did not end within " + formatNumber(params_.phase_timeout) + " s", t);
  }

  // Phase transitions, on what the sensors say now.
  switch (phase_) {
    case Phase::kApproach:
      for (int side = 0; side < 2; ++side) {
        if (first_touch_[side] < 0.0 && s.face(kFront, side)) first_touch_[side] = t;
      }
      if (touch_time_ < 0.0 && (first_touch_[0] >= 0.0 || first_touch_[1] >= 0.0)) touch_time_ = t;
      if ((first_touch_[0] >= 0.0 && first_touch_[1] >= 0.0) ||
          (touch_time_ >= 0.0 && t - touch_time_ > kSquareUpSeconds)) {
        heading_ = s.yaw;
        enter(Phase::kRaiseFront, t);
      }
      break;
    case Phase::kRaiseFront: {
      // Both front wheels stand on something well above the ground, nearly
      // upright over it: they have rolled onto the top.
      const double left = s.standZ(kFront, 0, kTopNormalUp), right = s.standZ(kFront, 1, kTopNormalUp);
      if (left > ground_z_ + kRaisedFrontM && right > ground_z_ + kRaisedFrontM) {
        edge_z_ = 0.5 * (left + right);
        edge_known_ = true;
        if (edge_z_ - ground_z_ > max_step_) {
          abort("the step (" + formatNumber(std::round((edge_z_ - ground_z_) * 1e3) / 1e3) +
                    " m) is higher than the rear fold can lift the middle axle with the rear wheels on the ground (" +
                    formatNumber(std::round(max_step_ * 1e3) / 1e3) +
                    " m): the rear wheels would leave the ground with the centre of mass behind the edge",
                t);
          break;
        }
        enter(Phase::kLiftMiddle, t);
        break;
      }
      if (front_fold >= fold_max_ - kFoldLimitMarginRad) {
        if (fold_limit_time_ < 0.0) fold_limit_time_ = t;
        if (t - fold_limit_time_ > kFoldLimitSeconds) {
          abort(
              "the front section at its fold limit does not reach the top edge: the step is taller than the robot "
              "can climb",
              t);
        }
      } else {
        fold_limit_time_ = -1.0;
      }
      break;
    }
    case Phase::kLiftMiddle: {
      const bool on_top = s.standZ(kMiddle, 0, kTopNormalUp) > edge_z_ - kOnTopToleranceM &&
                          s.standZ(kMiddle, 1, kTopNormalUp) > edge_z_ - kOnTopToleranceM;
      if (on_top) enter(Phase::kRaiseRear, t);
      break;
    }
    case Phase::kRaiseRear:
      if (std::abs(rear_fold) < kLevelRad) enter(Phase::kDriveOn, t);
      break;
    case Phase::kDriveOn: {
      bool all = true;
      for (int a = 0; a < 3; ++a) {
        for (int side = 0; side < 2; ++side) {
          all = all && s.standZ(a, side, kTopNormalUp) > edge_z_ - kOnTopToleranceM;
        }
      }
      if (all && climbed_time_ < 0.0) climbed_time_ = t;
      if (climbed_time_ >= 0.0 && t - climbed_time_ >= params_.drive_on_time) enter(Phase::kStopped, t);
      break;
    }
    case Phase::kStopped:
    case Phase::kAborted:
      break;
  }

  // Commands for the phase.
  double speed = params_.crawl_speed;
  std::array<double, 2> side_speed{};
  DriveCommand front{.mode = DriveMode::kPosition, .value = 0.0};
  bool front_wheels_free = false;
  // Levelling the middle body with the front fold works while the front
  // wheels bear on the ground (raising the fold then pitches the middle
  // nose down); with them in the air it would only lift them: hold.
  const bool front_bears = s.sensor[kFront][0]->contacts > 0 || s.sensor[kFront][1]->contacts > 0;
  const double level = front_bears ? kLevelGain * s.beta : 0.0;
  DriveCommand rear{.mode = DriveMode::kPosition, .value = 0.0};
  switch (phase_) {
    case Phase::kApproach:
      speed = params_.approach_speed;
      break;
    case Phase::kRaiseFront: {
      // Up while a front wheel presses on the face below its edge; down
      // gently once both ride on the edge (driven, they roll over it) or
      // have lost the face above it (they land on the top).
      const bool on_edge = s.standZ(kFront, 0, kEdgeNormalUp) > ground_z_ + kRaisedFrontM &&
                           s.standZ(kFront, 1, kEdgeNormalUp) > ground_z_ + kRaisedFrontM;
      const bool pressing = !on_edge && (s.face(kFront, 0) || s.face(kFront, 1));
      const bool free = s.sensor[kFront][0]->contacts == 0 && s.sensor[kFront][1]->contacts == 0;
      double rate = 0.0;
      if (pressing) {
        rate = fold_speed_;
      } else if ((free || on_edge) && front_fold > kLowerOntoTopFromRad) {
        rate = -kLowerOntoTopFraction * fold_speed_;
      }
      front_wheels_free = !on_edge;
      front = {.mode = DriveMode::kVelocity, .value = rate};
      break;
    }
    case Phase::kLiftMiddle: {
      // Once the middle wheels bear on the edge, the corner carries M and
      // the front fold no longer pitches the middle body: levelling would
      // only lift the front wheels off the top. The front holds; the rear
      // fold presses its wheels on (and up) the face while every wheel
      // drives M over the edge.
      const bool middle_on_edge = s.standZ(kMiddle, 0, kEdgeNormalUp) > ground_z_ + kRaisedFrontM ||
                                  s.standZ(kMiddle, 1, kEdgeNormalUp) > ground_z_ + kRaisedFrontM;
      if (middle_on_edge) {
        front = {.mode = DriveMode::kVelocity, .value = 0.0};
        rear = {.mode = DriveMode::kVelocity, .value = -fold_speed_};
        break;
      }
      front = {.mode = DriveMode::kVelocity, .value = level};
      const double target_z = edge_z_ + kLiftAboveEdgeRadii * radius_;
      rear = {.mode = DriveMode::kVelocity, .value = -kLiftGain * (target_z - s.axle[kMiddle].z()) / arm_};
      break;
    }
    case Phase::kRaiseRear: {
      // The rear wheels leave the ground only while the front wheels stay
      // loaded: with the centre of mass still behind the middle wheels,
      // lifting the rear would tip the robot back onto it. Until then the
      // robot crawls on and the rear arm follows the ground.
      const bool front_loaded = s.load(kFront, 0) > kFrontLoadN && s.load(kFront, 1) > kFrontLoadN;
      front = {.mode = DriveMode::kVelocity, .value = level};
      rear = {.mode = DriveMode::kVelocity, .value = front_loaded ? fold_speed_ : 0.0};
      if (rear_fold > 0.0) rear = {.mode = DriveMode::kPosition, .value = 0.0};
      break;
    }
    case Phase::kDriveOn:
      speed = params_.approach_speed;
      break;
    case Phase::kStopped:
    case Phase::kAborted:
      speed = 0.0;
      break;
  }
  // Heading: before squaring up, each side that touched crawls; after, a
  // yaw-rate correction holds the heading (Omega = k e, v_R,L = v +- Omega d).
  const double half_track = 0.5 * (s.centre[kMiddle][0] - s.centre[kMiddle][1]).norm();
  const double omega = speed == 0.0 ? 0.0 : kHeadingGain * std::remainder(heading_ - s.yaw, 2.0 * std::numbers::pi);
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? -1.0 : 1.0;  // left: v - Omega d
    side_speed[side] = speed + sign * omega * half_track;
    if (phase_ == Phase::kApproach && first_touch_[side] >= 0.0) side_speed[side] = params_.crawl_speed;
  }
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      commands[wheels_[a][side]] = {.mode = DriveMode::kVelocity,
                                    .value = clampRate(side_speed[side] / radius_, wheel_max_rate_)};
    }
  }
  // Raising the front: its wheels run free, so that they roll up the face
  // as the fold lifts them instead of holding on to it by friction; on the
  // edge they are driven again.
  if (front_wheels_free) {
    for (int side = 0; side < 2; ++side) commands[wheels_[kFront][side]] = {.mode = DriveMode::kOff, .value = 0.0};
  }
  if (front.mode == DriveMode::kVelocity) front.value = clampRate(front.value, fold_speed_);
  if (rear.mode == DriveMode::kVelocity) rear.value = clampRate(rear.value, fold_speed_);
  commands[front_fold_] = front;
  commands[rear_fold_] = rear;
  commands[front_slider_] = {.mode = DriveMode::kPosition, .value = front_travel_};
  commands[rear_slider_] = {.mode = DriveMode::kPosition, .value = rear_travel_};
}

void ClimbController::summarize(std::map<std::string, double>& fields) const {
  fields["climbed"] = climbed_time_ >= 0.0 ? 1.0 : 0.0;
  if (climbed_time_ >= 0.0 && touch_time_ >= 0.0) fields["time_to_climb_s"] = climbed_time_ - touch_time_;
  if (edge_known_ && ground_known_) {
    fields["measured_ledge_height_m"] = edge_z_ - ground_z_;
  }
  fields["max_front_pitch_deg"] = max_front_pitch_ * kDegPerRad;
  fields["max_rear_pitch_deg"] = max_rear_pitch_ * kDegPerRad;
  fields["max_middle_pitch_deg"] = max_middle_pitch_ * kDegPerRad;
  fields["phase"] = static_cast<double>(phase_);
  fields["max_climbable_step_m"] = max_step_;
}

}  // namespace wtc::vehicle

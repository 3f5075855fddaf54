#pragma once
// The six-wheel robot's ledge-climbing controller (vehicles spec, sections
// 1 and 3; wtc::vehicle). It sees what the robot's own sensors give: body
// poses (IMU and odometry), joint positions (encoders) and each wheel's
// contact as WTC measures it (load and ground normal). It never reads the
// terrain or a height constant: it finds the step when a front wheel meets
// its face, and measures the step's height when that wheel reaches the top
// edge (the edge point is the wheel centre minus r along the contact normal).
//
// Geometry it relies on (vehicles/six_wheel_robot.yaml): both fold axes on
// the middle axle M; the front axle F and the rear axle R on arms of length
// a + L from M. With the middle body's pitch beta, a section's elevation
// gamma (its arm above the horizontal) and its fold angle phi are related by
// phi_front = gamma_F - beta and phi_rear = gamma_R + beta.
//
// Phases:
//   approach     sections level, sliders out, wheels at the approach speed;
//                a front wheel whose contact normal points back (n . forward
//                < -0.6) has met a face; that side crawls until the other
//                side touches too, which squares the robot to the face.
//   raise front  every wheel crawls forward (a wheel pressed on a face and
//                turning forward climbs it); the front fold rises at its
//                rated speed until both front wheels' normals point up (on
//                the top edge). The edge's height and position are stored.
//                At the fold's limit without reaching it: abort.
//   lift middle  the front fold keeps the middle body level (rate k beta);
//                the rear fold lowers its arm until M stands the measured
//                height plus 0.75 r above the ground, pushing M up to the
//                edge while every wheel crawls forward; ends when the middle
//                wheels stand on the top (normal up, centre above the edge).
//   raise rear   front fold level; the rear fold swings the rear arm up to
//                level, lifting the rear wheels past the edge.
//   drive on     sections level, wheels at the approach speed; climbed once
//                every wheel stands on the top. Then the robot stops.
//   abort        a step it cannot climb (or a phase that does not end): the
//                wheels hold, the sections return level; failed() says why.
#include <array>
#include <string>

#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

struct ClimbControllerParams {
  double approach_speed = 0.4;  ///< Forward speed on the ground (m/s), > 0, within the wheels' rated rate.
  double crawl_speed = 0.1;     ///< Forward speed while reshaping (m/s), > 0.
  double drive_on_time = 2.0;   ///< Driving on after the climb before stopping (s), >= 0.
  double phase_timeout = 25.0;  ///< A phase lasting longer aborts the climb (s), > 0.
};

class ClimbController final : public Controller {
 public:
  enum class Phase { kApproach, kRaiseFront, kLiftMiddle, kRaiseRear, kDriveOn, kStopped, kAborted };

  /// Throws InvalidInputError naming `where` when the vehicle lacks one of
  /// the robot's bodies (by the names of vehicles/six_wheel_robot.yaml), a
  /// drive, a fold or slider limit, or when a parameter is out of range.
  ClimbController(const VehicleDescription& vehicle, const ClimbControllerParams& params, const std::string& where);

  void update(const VehicleState& state, std::span<DriveCommand> commands) override;
  /// climbed (0/1), time_to_climb_s (first touch to six wheels on top),
  /// measured_ledge_height_m, max_front_pitch_deg, max_rear_pitch_deg
  /// (sections' elevations), max_middle_pitch_deg, phase.
  void summarize(std::map<std::string, double>& fields) const override;
  bool failed() const override { return phase_ == Phase::kAborted; }
  std::string failure() const override { return failure_; }

  Phase phase() const { return phase_; }
  static const char* phaseName(Phase phase);

 private:
  enum Axle { kFront, kMiddle, kRear };
  struct Sensed;  // this step's derived quantities
  Sensed sense(const VehicleState& state) const;
  void enter(Phase phase, double time);
  void abort(const std::string& why, double time);

  ClimbControllerParams params_;
  int middle_ = -1, front_fold_ = -1, rear_fold_ = -1, front_slider_ = -1, rear_slider_ = -1;
  std::array<std::array<int, 2>, 3> wheels_{};  // [axle][left, right]
  double radius_ = 0.0, arm_ = 0.0, front_travel_ = 0.0, rear_travel_ = 0.0;
  double fold_max_ = 0.0, fold_speed_ = 0.0, wheel_max_rate_ = 0.0, max_step_ = 0.0;

  Phase phase_ = Phase::kApproach;
  double phase_start_ = 0.0;
  bool ground_known_ = false, edge_known_ = false;
  double ground_z_ = 0.0;                          // the ground under the start (world z, m)
  std::array<double, 2> first_touch_{-1.0, -1.0};  // per side (s)
  double touch_time_ = -1.0;                       // first face contact (s)
  double fold_limit_time_ = -1.0;
  double edge_z_ = 0.0;  // the top edge, measured (world z, m)
  double climbed_time_ = -1.0;  // every wheel first on the top (s)
  double max_front_pitch_ = 0.0, max_rear_pitch_ = 0.0, max_middle_pitch_ = 0.0;
  double heading_ = 0.0;  // yaw held after squaring up (rad)
  std::string failure_;
};

}  // namespace wtc::vehicle

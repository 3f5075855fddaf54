// A tilt table's run: the tip or the slide, and its angle (tilt_watch.hpp).
#include "tilt_watch.hpp"

#include <numbers>

#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim::detail {

TiltWatch::TiltWatch(const TiltTable& table, const vehicle::VehicleDescription& vehicle)
    : table_(table), vehicle_(vehicle), origin_(Eigen::Vector3d::Zero()) {}

void TiltWatch::before(Run& run) {
  const double angle = table_.angleRad(run.time());
  if (angle == last_angle_) return;
  run.setGravity(table_.gravity(run.time()));
  last_angle_ = angle;
}

// At start_s: the wheels uphill of the centre of mass (the table rises
// along +y about x, along -x about y), and where the first body stands.
void TiltWatch::start(const Run& run) {
  const vehicle::VehicleState& s = run.state();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < vehicle_.bodies.size(); ++i) centre += vehicle_.bodies[i].mass * s.bodies[i].pose.translation();
  centre /= vehicle_.totalMass();
  const Eigen::Vector3d uphill = table_.axis == 0 ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(-1, 0, 0);
  for (const int w : vehicle_.wheels()) {
    if ((s.bodies[w].pose.translation() - centre).dot(uphill) > 0.0) uphill_.push_back(w);
  }
  origin_ = s.bodies.front().pose.translation();
  started_ = true;
}

void TiltWatch::after(const Run& run) {
  const double t = run.time();
  if (t < table_.start_s || tipped_ || slid_) return;
  if (!started_) start(run);
  const vehicle::VehicleState& s = run.state();
  bool all_lifted = !uphill_.empty();
  for (const int w : uphill_) all_lifted = all_lifted && s.wheels[w].contacts == 0;
  if (!all_lifted) {
    lifted_.reset();
  } else if (!lifted_) {
    lifted_ = t;
  } else if (t - *lifted_ >= kTiltLiftHoldS) {
    tipped_ = table_.angleRad(*lifted_);
    at_ = t;
    return;
  }
  const Eigen::Vector3d moved = s.bodies.front().pose.translation() - origin_;
  if (moved.norm() > table_.slide_m && s.bodies.front().linear_velocity.norm() > table_.slide_speed_mps) {
    slid_ = table_.angleRad(t);
    at_ = t;
  }
}

bool TiltWatch::done(double t) const { return (tipped_ || slid_) && t - at_ >= kTiltAfterS; }

void TiltWatch::summarize(double t, std::map<std::string, double>& fields) const {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  if (tipped_) fields["tilt_tipped_deg"] = *tipped_ * kDeg;
  if (slid_) fields["tilt_slid_deg"] = *slid_ * kDeg;
  fields["tilt_final_deg"] = table_.angleRad(t) * kDeg;
}

}  // namespace wtc::sim::detail

#pragma once
// What a tilt table's run watches for (wtc::sim, private; the table:
// wtc/sim/tilt_table.hpp). From start_s on: the vehicle tipped when every
// wheel on its uphill side (uphill of its centre of mass, as it stood at
// start_s) has had no contact for kTipHoldS, the angle taken where that
// began; it slid when its first body has moved slide_m over the table and
// moves faster than slide_speed_mps (a slide, not a compliant vehicle's give). The
// first of the two is the run's answer; the run ends kTiltAfterS after it.
#include <optional>
#include <string>
#include <vector>

#include "wtc/sim/run.hpp"
#include "wtc/sim/tilt_table.hpp"

namespace wtc::sim::detail {

class TiltWatch {
 public:
  TiltWatch(const TiltTable& table, const vehicle::VehicleDescription& vehicle);

  /// Before each step: the table's gravity for it (Run::setGravity when it changed).
  void before(Run& run);
  /// After each step: looks for the tip or the slide.
  void after(const Run& run);
  /// The run may end: kTiltAfterS past the tip or the slide.
  bool done(double t) const;
  /// Its fields: tilt_tipped_deg or tilt_slid_deg (whichever came first),
  /// and tilt_final_deg (the table's angle at the run's end).
  void summarize(double t, std::map<std::string, double>& fields) const;

 private:
  void start(const Run& run);

  TiltTable table_;
  const vehicle::VehicleDescription& vehicle_;
  bool started_ = false;
  std::vector<int> uphill_;       // the wheels uphill of the centre of mass at start_s
  Eigen::Vector3d origin_;        // the first body's position at start_s
  std::optional<double> lifted_;  // since when every uphill wheel has had no contact (s)
  std::optional<double> tipped_, slid_;  // the angle (rad) and when (s)
  double at_ = 0.0;                // when the answer came (s)
  double last_angle_ = -1.0;       // the angle gravity was last set for (rad)
};

}  // namespace wtc::sim::detail

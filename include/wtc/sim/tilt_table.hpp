#pragma once
// A tilt table (wtc::sim): the test SAE J2180 describes for a vehicle's
// static stability. The vehicle settles on level ground, then the ground
// tilts slowly about a horizontal axis until the vehicle's uphill wheels
// lift (it tips) or it slides; the angle at which that happens is the
// answer, in one run. Here the ground stays and gravity turns the other
// way, which is the same for the vehicle (the run's frame is the table's):
// the terrain needs no motion, and the engines only a gravity to set.
//
// Scene key (scenes/README.md):
//   tilt_table: {axis: x, rate_deg_s: 0.5, start_s: 1, slide_m: 0.005, slide_speed_mps: 0.01}
// About +x, the table's +y side rises: a vehicle facing +x meets a side
// slope falling to -y (its right); about +y, the +x side falls: a vehicle
// facing +x stands nose-down, one facing -x nose-up (a grade).
#include <Eigen/Core>

namespace wtc::sim {

struct TiltTable {
  int axis = 0;             ///< The world axis the table turns about: 0 x, 1 y.
  double rate_deg_s = 0.5;  ///< Tilt rate (deg/s), > 0.
  double start_s = 1.0;     ///< Level until then: the vehicle settles (s), >= 0.
  /// It slid when its first body has moved this far over the table since
  /// start_s (m), > 0: past the tyres' tangential give under a load near
  /// their friction (under a millimetre for the shipped tyres), short of
  /// the slide's own acceleration (at 5 cm a cart on a 1 deg/s table was
  /// read a degree late; at 5 mm within 0.15 deg of atan(mu)).
  double slide_m = 0.005;
  /// And is moving over the table faster than this (m/s), > 0: a vehicle
  /// that gives as the table turns (a hitch's spring, the sections'
  /// joints) creeps at well under a millimetre a second at 0.5 deg/s and
  /// does not slide; a slide accelerates through it within a tenth of a
  /// second.
  double slide_speed_mps = 0.01;

  /// The table's angle at time t (rad): 0 before start_s.
  double angleRad(double t) const;
  /// Gravity in the table's frame at time t (m/s^2): (0, 0, -g) turned by
  /// -angle about the axis.
  Eigen::Vector3d gravity(double t) const;
};

}  // namespace wtc::sim

#pragma once
// A vehicle as the bounds of the mobility events see it (wtc::mobility):
// its mass and centre of mass, its wheels (where, how large, how stiff,
// driven or free, castering or not) and its static wheel loads, from the
// vehicle description alone (docs/mobility-bounds.md, section 2).
//
// The loads are planar, quasi-static statics in the slope's frame: the
// vehicle faces +x up a grade theta and accelerates at a; each root body is
// rigid with its joints at zero and moves by a heave z and a pitch beta
// (w(x) = z + beta x); each wheel is a vertical spring c at its centre's x;
// the hitch is stiff along x (its force H_x unknown) and a spring k_z
// vertically. Free wheels carry a longitudinal force -k_free N at the
// ground (rolling resistance while rolling, 0 parked); the driven wheels
// take what their root's x balance needs. A wheel whose spring would pull
// lifts off (N = 0) and the loads are solved again without it.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::mobility {

struct WheelInfo {
  int body = -1;
  std::string name;
  int root = -1;               ///< The root body it hangs from.
  Eigen::Vector3d position;    ///< Its centre in the vehicle frame (m).
  double radius_m = 0.0;       ///< r_f.
  double width_m = 0.0;        ///< w, the tread's width.
  double r0_ratio = 0.97;      ///< r_0 / r_f.
  double stiffness_Npm = 0.0;  ///< c.
  double spin_inertia = 0.0;   ///< I about the axle (kg m^2).
  bool driven = false;
  double max_torque_Nm = 0.0;   ///< The drive's max_effort (driven only).
  double max_rate_radps = 0.0;  ///< The drive's max_speed (driven only).
  bool caster = false;          ///< Free in yaw (a ball joint, or a parent swivelling about z): no side force.
};

struct RootInfo {
  int body = -1;
  double mass_kg = 0.0;
  Eigen::Vector3d com{Eigen::Vector3d::Zero()};  ///< With every body hanging from it (m, vehicle frame).
};

struct HitchInfo {
  int root_a = -1, root_b = -1;                    ///< The tug's and the towed body's roots.
  Eigen::Vector3d point{Eigen::Vector3d::Zero()};  ///< D1 in the vehicle frame (m).
  double vertical_stiffness_Npm = 0.0;
};

struct VehicleStatics {
  std::string name;
  double mass_kg = 0.0;
  Eigen::Vector3d com{Eigen::Vector3d::Zero()};
  std::vector<RootInfo> roots;
  std::vector<WheelInfo> wheels;
  std::optional<HitchInfo> hitch;

  double weight() const;  ///< m g (N).
  bool allDriven() const;
};

/// Throws InvalidInputError for a vehicle without wheels, or one whose
/// towed body carries a driven wheel (not handled by the planar statics).
VehicleStatics describeStatics(const vehicle::VehicleDescription& vehicle);

struct Loads {
  std::vector<double> normal_N;         ///< Per wheel of VehicleStatics::wheels.
  std::vector<std::string> lifted;      ///< The wheels that lifted off.
  double hitch_x_N = 0.0;               ///< H_x on the towed body (0 without a hitch).
  double driven_N = 0.0, free_N = 0.0;  ///< Sums.
  bool equilibrium = true;              ///< False: the supports left cannot hold it (it tips).
};

/// The loads on a grade `slope_rad` (facing up it) at acceleration
/// `accel_mps2`, free wheels resisting with `free_coefficient` N.
Loads wheelLoads(const VehicleStatics& v, double slope_rad = 0.0, double accel_mps2 = 0.0,
                 double free_coefficient = 0.0);

}  // namespace wtc::mobility

#pragma once
// A vehicle, described once and built by any engine (wtc::vehicle). Design note:
//
// A vehicle is a forest of rigid bodies: each body but the roots hangs from
// its parent by one joint (revolute, prismatic, ball or fixed), as in URDF
// and MJCF, so that a reduced-coordinate engine (Bullet's btMultiBody) and a
// maximal-coordinate one (ODE's joints) build it alike. Roots float freely;
// a towed system has two roots joined by a hitch, a force element and not a
// joint. Everything is given in the vehicle frame V (x forward, y left, z up)
// at the reference configuration, where every joint coordinate is zero;
// a scene places V in the world.
//
// Bodies that are wheels carry a WheelGeometry and tyre parameters; their
// contact with the ground is WTC's, and every other body collides with the
// ground through its box, cylinder or sphere shape, or through a compound of
// such shapes and convex hulls, each at its own pose (a body read from URDF
// with several collision elements, or one off its centre of mass). Bodies
// of one vehicle do not collide with each other.
//
// The description is immutable during a run; per-run state (joint
// positions, actuator counters) lives with the engine and the run loop.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "wtc/tyre/tyre_parameters.hpp"

namespace wtc::vehicle {

/// A body's collision and inertia shape, centred on its centre of mass and
/// aligned with its frame (or, as a part of a compound, with the part's).
struct Shape {
  enum class Kind { kNone, kBox, kCylinder, kSphere, kHull };
  Kind kind = Kind::kNone;
  Eigen::Vector3d box_size{Eigen::Vector3d::Zero()};  ///< Full edge lengths along x, y, z (m), box only.
  double radius = 0.0;                                ///< Cylinder or sphere radius (m).
  double length = 0.0;                                ///< Cylinder length along its axis (m).
  int cylinder_axis = 1;                              ///< Cylinder axis in the body frame: 0 x, 1 y, 2 z.
  /// Hull only: the vertices of a convex hull (m, in the shape's frame);
  /// no inertia is computed from a hull (a URDF gives its link's).
  std::vector<Eigen::Vector3d> hull_vertices;
};

/// One part of a compound collision shape, at its pose in the body's frame.
struct ShapePart {
  Shape shape;                                               ///< kBox, kCylinder, kSphere or kHull.
  Eigen::Isometry3d pose_BS{Eigen::Isometry3d::Identity()};  ///< The part's frame S in the body frame B.
};

/// The principal moments of a solid of mass `mass` (kg) and shape `shape`
/// about its centre, in its frame (kg m^2). Throws for Kind::kNone.
Eigen::Vector3d solidInertia(const Shape& shape, double mass);

/// A wheel: a body whose ground contact is WTC's (a sphere of radius r_f cut
/// at +-w/2 along its axle). Its inertia defaults to a solid disc of the
/// same radius and width.
struct Wheel {
  WheelGeometry geometry;
  TyreParameters tyre;
  Eigen::Vector3d axle{Eigen::Vector3d::UnitY()};  ///< Axle direction in the body frame (unit after validation).
};

enum class JointType { kRevolute, kPrismatic, kBall, kFixed };

/// Joint limits in the joint's own coordinate (rad or m). Absent: unlimited.
struct JointLimits {
  double lower = 0.0;
  double upper = 0.0;
};

/// A drive on a joint's coordinate, with the limits a real drive has.
struct ActuatorLimits {
  double max_effort = 0.0;  ///< Torque (N m, revolute) or force (N, prismatic), > 0.
  double max_speed = 0.0;   ///< Rate (rad/s or m/s), > 0.
  /// Position mode: the commanded rate is position_gain (q* - q) (1/s),
  /// clamped to max_speed; the drive then holds that rate within max_effort.
  double position_gain = 10.0;
};

/// A joint whose coordinate follows another's (URDF's <mimic>):
/// q = multiplier q_master + offset. Engines hold it as a constraint or
/// refuse the vehicle by the joint's name (docs/urdf.md).
struct Mimic {
  int master = -1;          ///< Index of the body whose joint is the master.
  double multiplier = 1.0;  ///< (dimensionless; m/rad etc. across types)
  double offset = 0.0;      ///< (rad or m)
};

/// The joint that holds a body to its parent.
struct Joint {
  JointType type = JointType::kFixed;
  Eigen::Vector3d anchor{Eigen::Vector3d::Zero()};  ///< Joint origin in V at the reference configuration (m).
  Eigen::Vector3d axis{Eigen::Vector3d::UnitY()};   ///< Rotation or sliding axis in V (unit after validation).
  std::optional<JointLimits> limits;                ///< Revolute and prismatic only.
  std::optional<ActuatorLimits> actuator;           ///< A drive on the joint (revolute and prismatic only).
  std::optional<Mimic> mimic;                       ///< Follows another joint (revolute and prismatic only).
  std::string name;                                 ///< The joint's name in its source (URDF), for messages.
};

struct Body {
  std::string name;
  double mass = 0.0;                                      ///< (kg), > 0.
  Eigen::Vector3d inertia{Eigen::Vector3d::Zero()};       ///< Principal moments about the centre of mass (kg m^2).
  Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< Centre-of-mass frame in V at the reference (m).
  /// The body's own axes (a URDF link's, as written) in its centre-of-mass
  /// frame `pose`, which the engines integrate in: a body whose tensor has
  /// products of inertia is turned to its principal axes, of arbitrary sign
  /// and order. What users read as the body's rotation is R_WB own_axes
  /// (ownFrame). Identity where the two agree (every YAML body).
  Eigen::Matrix3d own_axes{Eigen::Matrix3d::Identity()};
  Shape shape;                                            ///< Collision with the ground (kNone: none).
  /// When not empty, the body's collision shape instead of `shape`: the
  /// parts together (a URDF link's several collision elements).
  std::vector<ShapePart> compound;
  std::optional<Wheel> wheel;  ///< Present for a wheel.
  int parent = -1;             ///< Index of the parent body; -1 for a root.
  Joint joint;                 ///< To the parent (ignored for a root).
};

/// A body's pose as users read it (outputs, sensors, controllers): at its
/// centre of mass, turned to its own axes. `pose_B` is the body's
/// centre-of-mass frame (Body::pose, or an engine's answer in the world).
inline Eigen::Isometry3d ownFrame(const Body& body, const Eigen::Isometry3d& pose_B) {
  Eigen::Isometry3d out = pose_B;
  out.linear() = pose_B.linear() * body.own_axes;
  return out;
}

/// The elastic hitch of the towed system (vehicles spec, section 2):
/// P = diag(C) (D1 - D2) + diag(mu) d(D1 - D2)/dt, in the horizontal axes of
/// body_a (x forward, y left) and the world vertical; P pulls body_b toward
/// D1 and body_a toward D2 (equal and opposite).
struct Hitch {
  int body_a = -1;                                     ///< The tug.
  int body_b = -1;                                     ///< The towed body.
  Eigen::Vector3d point_a{Eigen::Vector3d::Zero()};    ///< D1 in body_a's frame (m).
  Eigen::Vector3d point_b{Eigen::Vector3d::Zero()};    ///< D2 in body_b's frame (m).
  Eigen::Vector3d stiffness{Eigen::Vector3d::Zero()};  ///< Cx, Cy, Cz (N/m), >= 0.
  Eigen::Vector3d damping{Eigen::Vector3d::Zero()};    ///< mu_x, mu_y, mu_z (N s/m), >= 0.
};

struct VehicleDescription {
  std::string name;
  std::vector<Body> bodies;  ///< Parents before children.
  std::optional<Hitch> hitch;

  /// Index of the body called `name`, or -1.
  int find(const std::string& name) const;
  double totalMass() const;
  /// Indices of the bodies that are wheels, in body order.
  std::vector<int> wheels() const;
  /// Indices of the bodies whose joint has a drive, in body order.
  std::vector<int> actuated() const;
};

/// Throws InvalidInputError naming the body, the field, its value and
/// `where` (e.g. the file): non-finite or non-positive masses, inertias,
/// radii; a parent after its child or out of range; a zero axis; limits
/// with lower > upper; a drive or limits on a ball or fixed joint; a hitch
/// naming missing bodies or with negative coefficients. Normalises axes.
void validate(VehicleDescription& vehicle, const std::string& where);
/// The same checks for the body at `index` of a vehicle whose earlier
/// bodies are valid (a file reader checks each body where it stands).
void validate(Body& body, int index, const std::string& where);

}  // namespace wtc::vehicle

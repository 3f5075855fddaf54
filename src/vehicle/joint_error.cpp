#include "wtc/vehicle/joint_error.hpp"

#include <algorithm>
#include <cmath>

namespace wtc::vehicle {

JointError jointError(const VehicleDescription& vehicle, int body, const BodyKinematics& child,
                      const BodyKinematics& parent) {
  const Body& c = vehicle.bodies.at(body);
  const Body& p = vehicle.bodies.at(c.parent);
  // Each body's map from the reference configuration to now: X = T T0^-1.
  const Eigen::Isometry3d child_move = child.pose * c.pose.inverse();
  const Eigen::Isometry3d parent_move = parent.pose * p.pose.inverse();
  Eigen::Vector3d gap = child_move * c.joint.anchor - parent_move * c.joint.anchor;
  const Eigen::Vector3d axis_by_parent = parent_move.linear() * c.joint.axis;
  JointError e;
  switch (c.joint.type) {
    case JointType::kPrismatic:
      gap -= gap.dot(axis_by_parent) * axis_by_parent;
      [[fallthrough]];
    case JointType::kFixed:
      e.angle = Eigen::AngleAxisd(parent_move.linear().transpose() * child_move.linear()).angle();
      break;
    case JointType::kRevolute: {
      const Eigen::Vector3d axis_by_child = child_move.linear() * c.joint.axis;
      e.angle = std::atan2(axis_by_child.cross(axis_by_parent).norm(), axis_by_child.dot(axis_by_parent));
      break;
    }
    case JointType::kBall:
      break;
  }
  e.distance = gap.norm();
  return e;
}

}  // namespace wtc::vehicle

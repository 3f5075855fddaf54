#include "wtc/vehicle/hitch_law.hpp"

#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc::vehicle {
namespace {

Eigen::Vector3d pointVelocity(const BodyKinematics& body, const Eigen::Vector3d& point_world) {
  return body.linear_velocity + body.angular_velocity.cross(point_world - body.pose.translation());
}

}  // namespace

HitchForce hitchForce(const Hitch& hitch, const BodyKinematics& a, const BodyKinematics& b, bool damping_on) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d forward = a.pose.linear().col(0);
  forward -= forward.dot(up) * up;
  if (!forward.allFinite() || forward.norm() < tolerance::kMinAxleNorm) {
    throw InvalidInputError("wtc::vehicle::hitchForce: the tug's forward axis " + formatVector(a.pose.linear().col(0)) +
                            " has no horizontal part");
  }
  Eigen::Matrix3d axes;  // H: columns x_h, y_h, z.
  axes.col(0) = forward.normalized();
  axes.col(2) = up;
  axes.col(1) = up.cross(axes.col(0));

  HitchForce out;
  out.point_a = a.pose * hitch.point_a;
  out.point_b = b.pose * hitch.point_b;
  out.deflection = axes.transpose() * (out.point_a - out.point_b);
  out.force_local = hitch.stiffness.cwiseProduct(out.deflection);
  if (damping_on) {
    const Eigen::Vector3d rate = axes.transpose() * (pointVelocity(a, out.point_a) - pointVelocity(b, out.point_b));
    out.force_local += hitch.damping.cwiseProduct(rate);
  }
  out.force_on_b = axes * out.force_local;
  return out;
}

}  // namespace wtc::vehicle

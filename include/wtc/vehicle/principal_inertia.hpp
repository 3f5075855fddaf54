#pragma once
// A rigid body's inertia tensor turned to its principal axes: I = R diag(m) Rᵀ
// with R a rotation (right-handed: det R = +1). A body's frame in WTC is its
// principal frame (Body::inertia holds three moments), so a tensor with
// products of inertia, as URDF and CAD give, turns the body frame by R.
#include <Eigen/Core>

namespace wtc::vehicle {

struct PrincipalInertia {
  Eigen::Vector3d moments{Eigen::Vector3d::Zero()};       ///< Principal moments (kg m^2).
  Eigen::Matrix3d rotation{Eigen::Matrix3d::Identity()};  ///< Columns: the principal axes in the tensor's frame.
};

/// The principal moments and axes of the symmetric tensor `tensor` (kg m^2).
/// A tensor that is diagonal already (every product exactly 0) is kept as
/// it is, with R = identity: an eigen-solver would sort its moments and so
/// permute the body's axes for no physical reason. Otherwise Eigen's
/// SelfAdjointEigenSolver (moments ascending), the third axis flipped if
/// needed to make R right-handed. The moments are not checked here.
PrincipalInertia principalInertia(const Eigen::Matrix3d& tensor);

}  // namespace wtc::vehicle

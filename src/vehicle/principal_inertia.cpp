#include "wtc/vehicle/principal_inertia.hpp"

#include <Eigen/Eigenvalues>

namespace wtc::vehicle {

PrincipalInertia principalInertia(const Eigen::Matrix3d& tensor) {
  PrincipalInertia out;
  const Eigen::Matrix3d symmetric = 0.5 * (tensor + tensor.transpose());
  if (symmetric(0, 1) == 0.0 && symmetric(0, 2) == 0.0 && symmetric(1, 2) == 0.0) {
    out.moments = symmetric.diagonal();
    return out;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(symmetric);
  out.moments = solver.eigenvalues();
  out.rotation = solver.eigenvectors();
  if (out.rotation.determinant() < 0.0) out.rotation.col(2) = -out.rotation.col(2);
  return out;
}

}  // namespace wtc::vehicle

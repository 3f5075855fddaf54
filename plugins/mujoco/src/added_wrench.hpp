#pragma once
// A wrench WTC adds to one body's xfrc_applied for one step and takes back
// after it (internal to wtc::mujoco): a wheel's tyre wrench, a soil body's
// soil force. The body's value before is kept and put back exactly, so a
// user's own xfrc_applied survives the step to the bit.
#include <algorithm>
#include <array>

#include <mujoco/mujoco.h>
#include <Eigen/Core>

#include "src/conversions.hpp"

namespace wtc::mujoco {

class AddedWrench {
 public:
  /// Adds `force` (N, world) and `torque` about `point` (N m, world) to
  /// body `body`'s xfrc_applied, which acts at its centre of mass (xipos):
  /// the torque moved there, T + (point - x_ipos) x F.
  void add(mjData& d, int body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
           const Eigen::Vector3d& point) {
    const Eigen::Vector3d at_com = torque + (point - vec3(d.xipos + 3 * body)).cross(force);
    mjtNum* applied = d.xfrc_applied + 6 * body;
    std::copy(applied, applied + 6, before_.begin());
    body_ = body;
    for (int i = 0; i < 3; ++i) {
      applied[i] += force[i];
      applied[3 + i] += at_com[i];
    }
  }
  /// Puts the body's xfrc_applied back as add found it (nothing if no add
  /// since the last restore).
  void restore(mjData& d) {
    if (body_ < 0) return;
    std::copy(before_.begin(), before_.end(), d.xfrc_applied + 6 * body_);
    body_ = -1;
  }

 private:
  std::array<mjtNum, 6> before_{};
  int body_ = -1;  // the body added to, until restore; -1: none
};

}  // namespace wtc::mujoco

#include "wheel_drive_responses.hpp"

#include "wtc/base/tolerances.hpp"

namespace wtc::bullet {
namespace {

constexpr double kRelative = tolerance::kSharedDriveSolveRelative;

// The link's inertia applied to its joint's axis, in the link's
// (principal, centre-of-mass) frame: I t, with Bullet's diagonal I.
btVector3 inertiaAlongAxis(const btMultibodyLink& l) { return l.m_inertiaLocal * l.getAxisTop(0); }

}  // namespace

bool WheelDriveResponses::applies(const btMultiBody& body, int link) {
  if (link < 0 || link >= body.getNumLinks()) return false;
  const btMultibodyLink& l = body.getLink(link);
  if (l.m_jointType != btMultibodyLink::eRevolute) return false;
  for (int k = 0; k < body.getNumLinks(); ++k) {
    if (body.getParent(k) == link) return false;  // not a leaf: e_w moves its children too
  }
  const btVector3 t = l.getAxisTop(0).normalized();
  // The centre of mass on the axis: the pivot-to-centre offset along it.
  if (t.cross(l.m_dVector).length() > kRelative * l.m_dVector.length()) return false;
  // The axis a principal axis: I t along t.
  const btVector3 it = inertiaAlongAxis(l);
  return (it - t * t.dot(it)).length() <= kRelative * it.length() && t.dot(it) > 0.0;
}

void WheelDriveResponses::fill(btMultiBodyJacobianData& data, const btMultiBody& body, int link, double sign,
                               btScalar* response) {
  const btMultibodyLink& l = body.getLink(link);
  const int n = body.getNumDofs() + 6;
  const btVector3 t = l.getAxisTop(0);
  const double moment = t.dot(inertiaAlongAxis(l)) / t.length2();  // J about the axis (kg m^2)
  const btVector3 axis = quatRotate(l.m_cachedWorldTransform.getRotation(), t).normalized();
  Shared* found = nullptr;
  double along = 1.0;  // found's axis against this one: +-1
  for (std::size_t k = 0; k < used_ && found == nullptr; ++k) {
    Shared& s = shared_[k];
    if (s.body == &body && s.parent == l.m_parent && s.axis.cross(axis).length() <= kRelative) {
      found = &s;
      along = s.axis.dot(axis) > 0.0 ? 1.0 : -1.0;
    }
  }
  if (found != nullptr) {
    ++saved_;
  } else {
    if (used_ == shared_.size()) shared_.emplace_back();
    found = &shared_[used_++];
    found->body = &body;
    found->parent = l.m_parent;
    found->axis = axis;
    found->response.resize(static_cast<std::size_t>(n));
    force_.resize(static_cast<std::size_t>(n));
    // J_p^T axis: a pure torque on the parent (no force, so any point).
    body.fillConstraintJacobianMultiDof(l.m_parent, body.getBasePos(), axis, btVector3(0, 0, 0), force_.data(),
                                        data.scratch_r, data.scratch_v, data.scratch_m);
    body.calcAccelerationDeltasMultiDof(force_.data(), found->response.data(), data.scratch_r, data.scratch_v);
  }
  for (int k = 0; k < n; ++k) response[k] = -sign * along * found->response[static_cast<std::size_t>(k)];
  response[6 + l.m_dofOffset] += sign / moment;
}

}  // namespace wtc::bullet

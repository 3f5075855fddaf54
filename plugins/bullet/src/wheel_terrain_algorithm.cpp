#include "wheel_terrain_algorithm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <new>
#include <span>

#include "plugin_state.hpp"

namespace wtc::bullet {

btCollisionAlgorithm* WheelTerrainAlgorithm::CreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper*, const btCollisionObjectWrapper*) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(WheelTerrainAlgorithm));
  return new (memory) WheelTerrainAlgorithm(info, state_);
}

WheelTerrainAlgorithm::WheelTerrainAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                                             detail::PluginState& state)
    : btCollisionAlgorithm(info), state_(state) {}

WheelTerrainAlgorithm::~WheelTerrainAlgorithm() {
  for (btCollisionAlgorithm* child : {child_, cap_child_}) {
    if (child == nullptr) continue;
    child->~btCollisionAlgorithm();
    m_dispatcher->freeCollisionAlgorithm(child);
  }
  if (manifold_ != nullptr) m_dispatcher->releaseManifold(manifold_);
}

void WheelTerrainAlgorithm::processCollision(const btCollisionObjectWrapper* body0,
                                             const btCollisionObjectWrapper* body1,
                                             const btDispatcherInfo& dispatch_info, btManifoldResult* result) {
  const btCollisionObject* terrain = &state_.terrain.object();
  const int wheel0 = state_.wheelOf(body0->getCollisionObject());
  const int wheel1 = state_.wheelOf(body1->getCollisionObject());
  if (wheel0 >= 0 && body1->getCollisionObject() == terrain) {
    writeWtcContacts(wheel0, true, body0, body1, dispatch_info, result);
  } else if (wheel1 >= 0 && body0->getCollisionObject() == terrain) {
    writeWtcContacts(wheel1, false, body0, body1, dispatch_info, result);
  } else {
    delegate(body0, body1, dispatch_info, result);
  }
}

void WheelTerrainAlgorithm::writeWtcContacts(int wheel, bool wheel_is_body0, const btCollisionObjectWrapper* body0,
                                             const btCollisionObjectWrapper* body1,
                                             const btDispatcherInfo& dispatch_info, btManifoldResult* result) {
  if (manifold_ == nullptr) {
    manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
  }
  result->setPersistentManifold(manifold_);
  // The contacts are WTC's, found afresh each step: nothing carries over.
  manifold_->clearManifold();
  Wheel& w = *state_.wheels[wheel];
  if (!w.mounted.state().capContacts().empty()) writeCapContacts(w, body0, body1, dispatch_info, result);
  if (state_.mode == ContactMode::kForce) return;
  w.manifold = manifold_;
  w.wheel_is_body0 = manifold_->getBody0() == (wheel_is_body0 ? body0 : body1)->getCollisionObject();
  w.manifold_point.clear();
  // Bullet adds its linear slop to every contact's distance, which moves
  // the spring's zero by it (docs/tyre-model.md); implicit mode, the tyre
  // model solved by Bullet, hands it Z + slop so that the row's error is Z.
  const double slop = state_.mode == ContactMode::kImplicit ? state_.world.getSolverInfo().m_linearSlop : 0.0;
  const std::span<const SolverContact> contacts = w.mounted.last().contacts;
  // What each manifold point holds this step: every contact merged into it.
  std::array<SolverContact, MANIFOLD_CACHE_SIZE> held;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    SolverContact c = contacts[i];
    c.depth += slop;
    // Bullet's normal on B points from B to A; the point is on B; a
    // negative distance is a penetration.
    const btVector3 normal_on_b = toBt(wheel_is_body0 ? c.normal : Eigen::Vector3d(-c.normal));
    const btVector3 point_on_b = toBt(wheel_is_body0 ? c.ground_point : c.tread_point);
    result->addContactPoint(normal_on_b, point_on_b, -c.depth);
    // The point just added (or the one it replaced): nearest to point_on_b.
    int index = -1;
    btScalar nearest = BT_LARGE_FLOAT;
    for (int k = 0; k < manifold_->getNumContacts(); ++k) {
      const btManifoldPoint& p = manifold_->getContactPoint(k);
      const btScalar d =
          ((manifold_->getBody0() == body0->getCollisionObject()) ? p.m_positionWorldOnB : p.m_positionWorldOnA)
              .distance2(point_on_b);
      if (d < nearest) nearest = d, index = k;
    }
    // A point other contacts of this step already took (Bullet merged
    // them): its impulse is reported once, and it holds all their springs.
    const auto first = std::find(w.manifold_point.begin(), w.manifold_point.end(), index);
    const bool taken = first != w.manifold_point.end();
    w.manifold_point.push_back(index < 0 || taken ? -1 : index);
    if (index < 0) continue;
    if (taken) c = mergedContact(held[static_cast<std::size_t>(index)], c);
    held[static_cast<std::size_t>(index)] = c;
    btManifoldPoint& p = manifold_->getContactPoint(index);
    // A multibody link's friction is its own constraint's
    // (wheel_friction_constraint.hpp): Bullet's would not keep the direction.
    p.m_combinedFriction = w.friction != nullptr ? 0.0 : c.friction;
    p.m_combinedRestitution = 0;
    p.m_combinedRollingFriction = 0;
    p.m_combinedSpinningFriction = 0;
    if (state_.tread_rows != nullptr && w.friction == nullptr) {
      setTreadRows(p, c, w.wheel_is_body0, dispatch_info.m_timeStep);
      setSpring(p, c, dispatch_info.m_timeStep);
      continue;
    }
    const btVector3 normal = p.m_normalWorldOnB;
    btVector3 direction = toBt(c.friction_direction);
    direction -= normal * normal.dot(direction);  // the manifold's normal may be flipped: stay tangent
    if (direction.length2() > 0) {
      // The one friction direction Bullet solves (the plugin turns the
      // second off): along the traction, so the cap mu R_z is a cone's.
      p.m_lateralFrictionDir1 = direction.normalized();
      p.m_lateralFrictionDir2 = normal.cross(p.m_lateralFrictionDir1);
      p.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
    }
    setSpring(p, c, dispatch_info.m_timeStep);
  }
}

// Bullet merges a contact into a point of its manifold that lies within its
// contact breaking threshold (btManifoldResult::addContactPoint), keeping
// the later contact's geometry. Two WTC contacts that close are two
// contacts of one shallow crease, whose springs act in parallel (their load
// shares add, wheel_contact.hpp): the merged point holds both stiffnesses and
// dampings, and the stiffer one's friction. Keeping the later one's alone
// dropped a crease's full contact for its partner's small share: the towed
// system's 5 t body sank its nose wheel 13 cm through the rough ground in
// 0.4 s on a 1.5 % share (Bullet, implicit mode). A third contact merges
// with what the point already holds, the first two (writeWtcContacts).
SolverContact WheelTerrainAlgorithm::mergedContact(const SolverContact& earlier, const SolverContact& later) {
  SolverContact merged = earlier.stiffness > later.stiffness ? earlier : later;
  merged.ground_point = later.ground_point;
  merged.tread_point = later.tread_point;
  merged.normal = later.normal;
  merged.depth = later.depth;
  merged.stiffness = earlier.stiffness + later.stiffness;
  merged.damping = earlier.damping + later.damping;
  return merged;
}

// Implicit mode, a rigid wheel: the tread's two rows as Bullet's friction
// rows of the point (rigid_tread_rows.hpp). Bullet's row k pushes body A
// along its direction d_k to the target m_contactMotion_k of
// d_k . (v_A - v_B): with d_k = +-t_k (+ when the wheel is body A) that is
// t_k . v_wheel = V_k, and the force on the wheel is lambda_k t_k in both
// cases. Row 0 runs along the traction t_0, row 1 along t_1 = e x t_0
// (WheelFrictionConstraint's rows); the solver softens them with these
// compliances and bounds them by mu_k times the point's normal impulse.
void WheelTerrainAlgorithm::setTreadRows(btManifoldPoint& p, const SolverContact& c, bool wheel_is_body0,
                                         double step_seconds) const {
  const btVector3 normal = toBt(c.normal);
  btVector3 along = toBt(c.friction_direction);
  along -= normal * normal.dot(along);
  if (along.length2() > 0) {
    along.normalize();
  } else {
    btVector3 unused;
    btPlaneSpace1(normal, along, unused);
  }
  const double sign = wheel_is_body0 ? 1.0 : -1.0;
  p.m_lateralFrictionDir1 = sign * along;
  p.m_lateralFrictionDir2 = sign * normal.cross(along);
  p.m_contactMotion1 = c.friction_velocity[0];
  p.m_contactMotion2 = c.friction_velocity[1];
  p.m_frictionCFM = 0.0;
  p.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
  p.m_contactPointFlags &= ~BT_CONTACT_FLAG_FRICTION_ANCHOR;  // no positional term in the rows' rhs
  RigidTreadRows::Point rows;
  rows.point = &p;
  for (int k = 0; k < 2; ++k) {
    const double stiffness = c.friction_damping[static_cast<std::size_t>(k)];  // K_k (N s/m)
    rows.compliance[k] = stiffness > 0.0 ? 1.0 / (step_seconds * stiffness) : 0.0;
  }
  rows.mu[0] = c.friction;
  rows.mu[1] = c.friction_across;
  state_.tread_rows->set(rows);
}

// The tyre's spring-damper on a contact point: Bullet derives ERP and CFM
// from its stiffness and damping (wtc::softConstraint's pair). Bullet's
// split impulse (btContactSolverInfo::m_splitImpulse, on by default) solves
// a contact whose distance plus linear slop lies below
// m_splitImpulsePenetrationThreshold (-0.04 m) as a position-only push-out:
// its velocity row then drops the spring's positional error, no longer acts
// as c Z + b v_z, and a soft tyre sinks through (issue 11, defect 4). Such
// a contact goes to Bullet at half the threshold's depth with the same CFM
// and the ERP that keeps the positional error (Z - slop) erp / h: the same
// row as the true depth's without the split. (The multibody solver has no
// split; the same row holds there.)
void WheelTerrainAlgorithm::setSpring(btManifoldPoint& p, const SolverContact& c, double step_seconds) const {
  const btContactSolverInfo& info = state_.world.getSolverInfo();
  const double slop = info.m_linearSlop, threshold = info.m_splitImpulsePenetrationThreshold;
  const bool split = info.m_splitImpulse && threshold < 0.0 && -c.depth + slop <= threshold;
  p.m_contactPointFlags &=
      ~(BT_CONTACT_FLAG_HAS_CONTACT_CFM | BT_CONTACT_FLAG_HAS_CONTACT_ERP | BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING);
  if (!split) {
    p.m_combinedContactStiffness1 = c.stiffness;
    p.m_combinedContactDamping1 = c.damping;
    p.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
    return;
  }
  const double reported = 0.5 * threshold - slop;  // distance + slop = threshold / 2 < 0: not split
  const SoftConstraint soft = softConstraint(c.stiffness, c.damping, step_seconds);
  p.m_distance1 = reported;
  p.m_contactERP = soft.erp * (c.depth - slop) / (-(reported + slop));
  p.m_contactCFM = soft.cfm;
  p.m_contactPointFlags |= BT_CONTACT_FLAG_HAS_CONTACT_CFM | BT_CONTACT_FLAG_HAS_CONTACT_ERP;
}

// The ground touches a cut cap (a fallen wheel): WTC gives no force there,
// so Bullet collides the cut sphere's cap discs with the terrain (the
// wheel's cap cylinder: radius sqrt(r_f^2 - (w/2)^2), width w, whose rims
// are the caps' edges), and the points whose normal is a cap's (wtc::onCap,
// the tread filter's test) are kept; tread points are WTC's and are dropped.
// Not the wheel's own shape: a cylinder of radius r_f reaches
// r_f cos + w/2 sin beyond the centre, 9 mm past the tread at the tread's
// limit of 18.4 deg, so the wheel was thrown off a side slope as the cap
// took over (issue 11). Rare: only when the finder saw a cap contact, so
// the GJK/EPA cost is not paid while rolling.
void WheelTerrainAlgorithm::writeCapContacts(const Wheel& w, const btCollisionObjectWrapper* body0,
                                             const btCollisionObjectWrapper* body1,
                                             const btDispatcherInfo& dispatch_info, btManifoldResult* result) {
  collideOriginals(cap_child_, manifold_, body0, body1, dispatch_info, result, w.collider, w.cap_shape.get());
  const Eigen::Vector3d axle = toEigen(w.collider->getWorldTransform().getBasis() * w.axle_local).normalized();
  const double friction = state_.terrain.terrain().materials()[w.mounted.state().capContacts().front().material].mu_max;
  for (int k = manifold_->getNumContacts() - 1; k >= 0; --k) {
    btManifoldPoint& p = manifold_->getContactPoint(k);
    if (onCap(w.mounted.description().geometry, toEigen(p.m_normalWorldOnB), axle)) {
      p.m_combinedFriction = friction;
      p.m_combinedRestitution = 0;
    } else {
      manifold_->removeContactPoint(k);
    }
  }
}

void WheelTerrainAlgorithm::delegate(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                     const btDispatcherInfo& dispatch_info, btManifoldResult* result) {
  collideOriginals(child_, nullptr, body0, body1, dispatch_info, result);
}

// Bullet's own algorithm for the pair with every WheelShape unwrapped to the
// shape it wraps (or, for `replaced`, to `replacement`), created on first
// use into `child` (writing into `shared`, or its own manifold when null).
void WheelTerrainAlgorithm::collideOriginals(btCollisionAlgorithm*& child, btPersistentManifold* shared,
                                             const btCollisionObjectWrapper* body0,
                                             const btCollisionObjectWrapper* body1,
                                             const btDispatcherInfo& dispatch_info, btManifoldResult* result,
                                             const btCollisionObject* replaced, const btCollisionShape* replacement) {
  const auto shape = [&](const btCollisionObjectWrapper* body) {
    return body->getCollisionObject() == replaced ? replacement : unwrap(body->getCollisionShape());
  };
  const btCollisionObjectWrapper original0(body0->m_parent, shape(body0), body0->getCollisionObject(),
                                           body0->getWorldTransform(), body0->m_partId, body0->m_index);
  const btCollisionObjectWrapper original1(body1->m_parent, shape(body1), body1->getCollisionObject(),
                                           body1->getWorldTransform(), body1->m_partId, body1->m_index);
  if (child == nullptr)
    child = m_dispatcher->findAlgorithm(&original0, &original1, shared, BT_CONTACT_POINT_ALGORITHMS);
  const btCollisionObjectWrapper* saved0 = result->getBody0Wrap();
  const btCollisionObjectWrapper* saved1 = result->getBody1Wrap();
  result->setBody0Wrap(&original0);
  result->setBody1Wrap(&original1);
  child->processCollision(&original0, &original1, dispatch_info, result);
  result->setBody0Wrap(saved0);
  result->setBody1Wrap(saved1);
}

void WheelTerrainAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) {
  if (manifold_ != nullptr) manifolds.push_back(manifold_);
  if (child_ != nullptr) child_->getAllContactManifolds(manifolds);
  // cap_child_ writes into manifold_, listed above.
}

}  // namespace wtc::bullet

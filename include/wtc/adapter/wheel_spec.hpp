#pragma once
// What every engine adapter's wheel registration says alike (wtc::bullet's
// RigidWheel and MultiBodyWheel, wtc::ode's RigidWheel derive from it): what
// the wheel is, which effects its tyre model computes, and where its inertia
// comes from. Each adapter's wheel adds its engine's body handle and the
// mounting in that body's frame, in the engine's own vector type and with
// its default axle (Bullet: y; ODE: z, its cylinder's axis):
//   axle_local    the axle direction in the body frame (any length > 0);
//   centre_local  the wheel centre O in the body frame (m).
// Both are validated on registration (wtc::validateMounting).
#include "wtc/tyre/effects.hpp"
#include "wtc/tyre/tyre_parameters.hpp"

namespace wtc {

struct WheelSpec {
  WheelDescription description;           ///< Geometry, tyre, inertia.
  EffectSet effects = EffectSet::full();  ///< What the wheel's tyre model computes.
  /// kBody (the default): description.inertia's mass and moment about the
  /// axle are read from the body (its spin_held is the caller's: whether a
  /// drive or brake holds the spin); kDescription: all as given.
  InertiaSource inertia_source = InertiaSource::kBody;
};

}  // namespace wtc

#pragma once
// How the ODE sim engine's wheels meet the ground: a sim::WheelContacts
// strategy that also takes the near callback's wheel pairs, chosen once
// when the engine is built: WTC's wheels (wtc_wheels.hpp) or ODE's own
// (native_wheels.hpp).
#include <ode/ode.h>

#include "sim/wheel_contacts.hpp"

namespace wtc::ode {

/// Contacts ODE's own colliders may give per geom pair (a body's shape or
/// a native wheel against a terrain piece).
inline constexpr int kMaxContactsPerPair = 8;

/// A wheel body of the engine: its ODE body and collision geom.
struct WheelBody {
  dBodyID body = nullptr;
  dGeomID geom = nullptr;
};

class OdeWheels : public sim::WheelContacts {
 public:
  /// Called first by the engine's near callback for every pair: true if
  /// the pair is the wheels' and the callback is done with it.
  virtual bool collide(dGeomID a, dGeomID b) = 0;
};

}  // namespace wtc::ode

#pragma once
// How an engine's wheels meet the ground, a strategy each sim engine
// chooses once, when it is built (internal to wtc::sim and the engines):
// WTC's wheels through the engine's plugin (plugin_wheels.hpp), or the
// engine's own contact, the native-wheel baseline
// (native_wheel_contacts.hpp). An engine's own strategy interface derives
// from this one when the engine has more to ask of it (ODE: its near
// callback's wheel pairs). Wheel k is the k-th body of the vehicle's
// wheels(), as the plugin's WheelId k is.
#include <cstddef>

#include "wtc/adapter/wheel_listener.hpp"
#include "wtc/tyre/tyre_model.hpp"
#include "wtc/tyre/wheel_forces.hpp"

namespace wtc::sim {

class WheelContacts {
 public:
  virtual ~WheelContacts() = default;

  /// What acted on wheel k in the last step (Engine::wheelForces), and its
  /// tyre state.
  virtual const WheelForces& forces(std::size_t k) const = 0;
  virtual const WheelState& state(std::size_t k) const = 0;
  /// Engine::setWheelListener.
  virtual void setListener(WheelListener* listener) = 0;
  /// Engine::contactSeconds: the wall time WTC's plugin took.
  virtual double contactSeconds() const = 0;
  /// Called by the engine after each world step, before anyone reads the
  /// step's results.
  virtual void stepped() {}
};

}  // namespace wtc::sim

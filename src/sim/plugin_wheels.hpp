#pragma once
// WTC's wheels through an engine's plugin (wtc::bullet::Plugin,
// wtc::ode::Plugin): the WheelContacts strategy of a sim engine that runs
// WTC's tyre model, answering from the plugin. The engine's own class for
// its WTC wheels derives from it and registers them with the plugin, one
// per wheel body in body order, so that the plugin's WheelId k is wheel k.
#include <cstddef>

#include "sim/wheel_contacts.hpp"

namespace wtc::sim {

/// `Plugin` has applied(WheelId), state(WheelId), setListener and
/// contactSeconds, as both plugins do; `Base` is WheelContacts or an
/// engine's own strategy interface derived from it.
template <class Plugin, class Base = WheelContacts>
class PluginWheels : public Base {
 public:
  /// The plugin's applied(): the tyre model's forces in force mode, the
  /// forces the engine's solver applied at WTC's contacts in constraint mode.
  const WheelForces& forces(std::size_t k) const final { return plugin_.applied(static_cast<WheelId>(k)); }
  const WheelState& state(std::size_t k) const final { return plugin_.state(static_cast<WheelId>(k)); }
  void setListener(WheelListener* listener) final { plugin_.setListener(listener); }
  double contactSeconds() const final { return plugin_.contactSeconds(); }

 protected:
  explicit PluginWheels(Plugin& plugin) : plugin_(plugin) {}
  Plugin& plugin() const { return plugin_; }

 private:
  Plugin& plugin_;
};

}  // namespace wtc::sim

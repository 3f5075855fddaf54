#pragma once
// An engine's entries in the engine table (internal to wtc::sim and the
// engines). Each engine declared with wtc_add_engine(<name> ...)
// (cmake/WtcEngine.cmake) defines, in its own folder,
//
//   namespace wtc::<name> { std::span<const sim::EngineEntry> engineEntries(); }
//
// (plugins/bullet/sim/src/register.cpp), and the table's generated source
// names every such function, so that the linker keeps each engine's
// registration (an entry nothing referred to would be dropped from a static
// library). One engine may register several names: its own, and variants
// as <engine>_<variant> (ODE: ode, ode_quick); EngineTableTest holds the
// table to that.
#include <memory>
#include <span>
#include <string_view>

#include <Eigen/Geometry>

#include "wtc/sim/engine.hpp"

namespace wtc::sim {

struct EngineEntry {
  /// Builds `vehicle` on `terrain` (which outlives the engine) in this
  /// engine, its frame V at `placement`; validates the settings.
  using Make = std::unique_ptr<Engine> (*)(const EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement);

  std::string_view name;  ///< As scenes name it (EngineSettings::engine): "bullet".
  Make make = nullptr;
  /// The WTC contact modes the engine serves; empty: all three. (The
  /// engine's own wheels, EngineSettings::native_wheels, every engine serves.)
  std::span<const ContactMode> modes{};
  /// Why it serves no other mode: the reason makeEngine refuses one with.
  std::string_view other_modes{};
};

}  // namespace wtc::sim

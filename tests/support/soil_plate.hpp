#pragma once
// A belly plate on soft soil, shared by the tests of bodies on soil
// (wtc/tyre/body_soil.hpp; the core, the plugins, the sim engines): a slab
// of one named soil, and Bekker's sinkage of a flat plate on it.
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "wtc/terrain/soil_region.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {

/// A size_x x size_y slab of the named soil (top z = 0, centred on the
/// origin), remembering over `region` when given.
inline Terrain soilSlab(const std::string& soil, double size_x, double size_y,
                        const std::optional<SoilRegion>& region = std::nullopt) {
  TerrainBuilder builder;
  Material m;
  m.name = soil;
  m.soil = *namedSoil(soil);
  SlabParams slab;
  slab.size_x = size_x;
  slab.size_y = size_y;
  addSlab(builder, slab, builder.addMaterial(m));
  if (region) builder.addSoilRegion(*region);
  return std::move(builder).build();
}

/// Bekker's sinkage of a flat plate (length >= width = b) carrying `load`
/// (N) at rest: z = (W / (A (k_c / b + k_phi)))^(1/n) (m).
inline double bekkerPlateSinkage(const Soil& soil, double load, double length, double width) {
  return std::pow(load / (length * width * (soil.k_c / width + soil.k_phi)), 1.0 / soil.n);
}

}  // namespace wtc::testing

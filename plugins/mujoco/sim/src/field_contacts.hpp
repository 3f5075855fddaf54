#pragma once
// The vehicle bodies' contacts with a height field, held to normals the
// field's surface can give (sim::TerrainNormalCone), between mj_collision
// and mj_makeConstraint. MuJoCo meets a body with one prism a triangle of
// its height field: a box lying on the field along a grid line got contacts
// from the walls between prisms, tilted sideways, whose friction slowed and
// steered it (16 % of its sliding deceleration, docs/mujoco-plugin.md).
#include <span>
#include <vector>

#include <mujoco/mujoco.h>

#include "sim/terrain_normal_cone.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::mujoco {

class FieldContacts {
 public:
  /// `terrain` must outlive this; `engine_wheels`: the geoms of wheels the
  /// engine meets the ground with itself (the baseline), left as MuJoCo
  /// gives them.
  FieldContacts(const mjModel& m, const Terrain& terrain, std::span<const int> engine_wheels);

  /// Each contact of a body geom with a height field: its normal as the
  /// cone gives it (the tangents made anew around it), or excluded when the
  /// surface gives none.
  void hold(const mjModel& m, mjData& d);

 private:
  sim::TerrainNormalCone cone_;
  std::vector<char> field_;  // per geom: a height field of the world
  std::vector<char> held_;   // per geom: a body's, to be held
};

}  // namespace wtc::mujoco

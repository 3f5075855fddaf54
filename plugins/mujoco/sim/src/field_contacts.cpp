// A body's contacts with a height field (field_contacts.hpp).
#include "field_contacts.hpp"

#include <cmath>
#include <optional>

#include "src/conversions.hpp"

namespace wtc::mujoco {
namespace {

// A body geom as the engine-free rule sees it: MuJoCo's box (half sizes),
// sphere, cylinder (radius, half length, along its z); a mesh is kOther.
sim::PlacedShape placedShape(const mjModel& m, const mjData& d, int geom) {
  sim::PlacedShape shape;
  shape.pose.linear() = mat3(d.geom_xmat + 9 * geom);
  shape.pose.translation() = vec3(d.geom_xpos + 3 * geom);
  const mjtNum* size = m.geom_size + 3 * geom;
  switch (m.geom_type[geom]) {
    case mjGEOM_BOX:
      shape.kind = sim::PlacedShape::Kind::kBox;
      shape.half_extents = vec3(size);
      break;
    case mjGEOM_SPHERE:
      shape.kind = sim::PlacedShape::Kind::kSphere;
      shape.radius = size[0];
      break;
    case mjGEOM_CYLINDER:
      shape.kind = sim::PlacedShape::Kind::kCylinder;
      shape.radius = size[0];
      shape.half_length = size[1];
      break;
    default:
      break;
  }
  return shape;
}

// A contact frame's rows: the normal, then two tangents.
void setFrame(mjtNum* frame, const Eigen::Vector3d& n) {
  const Eigen::Vector3d least =
      std::abs(n.x()) < std::abs(n.y())
          ? (std::abs(n.x()) < std::abs(n.z()) ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ())
          : (std::abs(n.y()) < std::abs(n.z()) ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d t1 = n.cross(least).normalized(), t2 = n.cross(t1);
  for (int i = 0; i < 3; ++i) {
    frame[i] = n[i];
    frame[3 + i] = t1[i];
    frame[6 + i] = t2[i];
  }
}

}  // namespace

FieldContacts::FieldContacts(const mjModel& m, const Terrain& terrain, std::span<const int> engine_wheels)
    : cone_(terrain), field_(static_cast<std::size_t>(m.ngeom), 0), held_(static_cast<std::size_t>(m.ngeom), 0) {
  for (int g = 0; g < m.ngeom; ++g) {
    const bool world = m.body_weldid[m.geom_bodyid[g]] == 0;
    field_[static_cast<std::size_t>(g)] = world && m.geom_type[g] == mjGEOM_HFIELD;
    held_[static_cast<std::size_t>(g)] = !world;
  }
  for (const int g : engine_wheels) held_[static_cast<std::size_t>(g)] = 0;
}

void FieldContacts::hold(const mjModel& m, mjData& d) {
  for (int i = 0; i < d.ncon; ++i) {
    mjContact& c = d.contact[i];
    const auto g1 = static_cast<std::size_t>(c.geom1), g2 = static_cast<std::size_t>(c.geom2);
    const bool field_first = field_[g1] && held_[g2];
    if (!field_first && !(field_[g2] && held_[g1])) continue;
    // The frame's normal points from geom1 to geom2: out of the field when it is first.
    const double sign = field_first ? 1.0 : -1.0;
    const Eigen::Vector3d n_W = sign * vec3(c.frame), p_W = vec3(c.pos);
    const double depth = std::max(-c.dist, 0.0);
    const std::optional<Eigen::Vector3d> surface =
        cone_.normal(p_W, n_W, depth, placedShape(m, d, field_first ? c.geom2 : c.geom1));
    if (!surface) {
      c.exclude = 1;  // mj_instantiateContact skips it
    } else if (*surface != n_W) {
      setFrame(c.frame, sign * *surface);
    }
  }
}

}  // namespace wtc::mujoco

// A body's underside on soft soil (design in wtc/tyre/body_soil.hpp).
#include "wtc/tyre/body_soil.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ground_memory_access.hpp"
#include "wtc/base/error.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// A plane n . x = d met by the vertical line through (x, y): narrows the
// line's inside [lo, hi] (z, m), or empties it. `upward` is set to the plane
// that bounds it from above.
struct LineClip {
  double lo = -kInfinity, hi = kInfinity;
  int upward = -1;
  bool inside = true;

  void cut(const Eigen::Vector3d& n, double d, double x, double y, int face) {
    const double rest = d - n.x() * x - n.y() * y;
    if (n.z() > 0.0) {
      const double t = rest / n.z();
      if (t < hi) {
        hi = t;
        upward = face;
      }
    } else if (n.z() < 0.0) {
      lo = std::max(lo, rest / n.z());
    } else if (rest < 0.0) {
      inside = false;
    }
  }
  bool met() const { return inside && lo <= hi; }
};

bool finite(const BodySoilMotion& m) {
  return m.pose.matrix().allFinite() && m.velocity.allFinite() && m.angular_velocity.allFinite();
}

}  // namespace

BodyOnSoil::BodyOnSoil(std::vector<ConvexPolyhedron> hulls, double mass, const std::string& where)
    : hulls_(std::move(hulls)), mass_(mass) {
  if (hulls_.empty()) throw InvalidInputError(where + ": a body on soft soil needs at least one convex hull");
  for (std::size_t k = 0; k < hulls_.size(); ++k) {
    const ConvexPolyhedron& h = hulls_[k];
    bool finite_points = true;
    for (int v = 0; v < h.vertexCount(); ++v) finite_points = finite_points && h.vertex(v).allFinite();
    if (!finite_points || h.isFlat() || h.faceCount() < 4) {
      throw InvalidInputError(where + ": hull " + std::to_string(k) +
                              (finite_points ? " spans no volume" : " has a coordinate that is not finite"));
    }
  }
  if (!(mass > 0.0) || !std::isfinite(mass)) {
    throw InvalidInputError(where + ": mass " + std::to_string(mass) + " kg is not a positive finite number");
  }
}

BodySoilForces BodyOnSoil::step(const Terrain& terrain, GroundMemory* memory, const BodySoilMotion& motion,
                                double step_seconds) {
  BodySoilForces out;
  if (!finite(motion) || !(step_seconds > 0.0)) return out;
  const Eigen::Matrix3d rotation = motion.pose.linear();
  const Eigen::Vector3d origin = motion.pose.translation();

  // The hulls' faces and box in the world.
  planes_.clear();
  hull_faces_.clear();
  Aabb box{origin, origin};
  bool first = true;
  for (const ConvexPolyhedron& h : hulls_) {
    for (int f = 0; f < h.faceCount(); ++f) {
      const Eigen::Vector3d n = rotation * h.faceNormal(f);
      planes_.emplace_back(n.x(), n.y(), n.z(), h.faceOffset(f) + n.dot(origin));
    }
    hull_faces_.push_back(h.faceCount());
    for (int v = 0; v < h.vertexCount(); ++v) {
      const Eigen::Vector3d p = motion.pose * h.vertex(v);
      if (first) box = Aabb{p, p};
      box.include(p);
      first = false;
    }
  }

  // The pieces that may hold the surface under the body; none with a soil:
  // nothing to press.
  pieces_.clear();
  terrain.overlapping(box, pieces_);
  const bool any_soil =
      std::any_of(pieces_.begin(), pieces_.end(), [&](PieceId p) { return terrain.material(p).soil.has_value(); });
  if (!any_soil) return out;

  // The nodes under the body's box: a region's own where its footprint's
  // centre lies in one, else the fresh soil's lattice from the world origin.
  detail::SoilGrid* grid =
      memory != nullptr ? detail::GroundMemoryAccess::gridAt(*memory, box.center().x(), box.center().y()) : nullptr;
  const double s = grid != nullptr ? grid->spec().spacing : kBodySoilSpacingM;
  const Eigen::Vector2d lattice = grid != nullptr ? grid->spec().origin : Eigen::Vector2d::Zero();
  const auto index = [&](double v, double o, bool up) {
    const double u = (v - o) / s;
    return static_cast<int>(up ? std::floor(u) : std::ceil(u));
  };
  const int i0 = index(box.min.x(), lattice.x(), false), i1 = index(box.max.x(), lattice.x(), true);
  const int j0 = index(box.min.y(), lattice.y(), false), j1 = index(box.max.y(), lattice.y(), true);
  if (i1 < i0 || j1 < j0) return out;
  const int columns = i1 - i0 + 1;
  const std::size_t count = static_cast<std::size_t>(columns) * static_cast<std::size_t>(j1 - j0 + 1);

  // The terrain's top at each node: the highest piece over it, and the
  // face that bounds it from above (the surface's normal there).
  top_.assign(count, -kInfinity);
  top_piece_.assign(count, -1);
  top_face_.assign(count, -1);
  std::optional<ConvexPolyhedron> scratch;
  for (const PieceId id : pieces_) {
    const ConvexPolyhedron& piece = terrain.piece(id, scratch);
    const Aabb& b = piece.bounds();
    const int pi0 = std::max(i0, index(b.min.x(), lattice.x(), false));
    const int pi1 = std::min(i1, index(b.max.x(), lattice.x(), true));
    const int pj0 = std::max(j0, index(b.min.y(), lattice.y(), false));
    const int pj1 = std::min(j1, index(b.max.y(), lattice.y(), true));
    for (int j = pj0; j <= pj1; ++j) {
      for (int i = pi0; i <= pi1; ++i) {
        const double x = lattice.x() + s * i, y = lattice.y() + s * j;
        LineClip clip;
        for (int f = 0; f < piece.faceCount() && clip.inside; ++f) {
          clip.cut(piece.faceNormal(f), piece.faceOffset(f), x, y, f);
        }
        const std::size_t k = static_cast<std::size_t>(j - j0) * columns + static_cast<std::size_t>(i - i0);
        if (!clip.met() || !(clip.hi > top_[k])) continue;
        top_[k] = clip.hi;
        top_piece_[k] = id;
        top_face_[k] = clip.upward;
      }
    }
  }

  // The nodes whose soil the body's underside reaches below the surface
  // the ground remembers there.
  nodes_.clear();
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const std::size_t k = static_cast<std::size_t>(j - j0) * columns + static_cast<std::size_t>(i - i0);
      if (top_piece_[k] < 0 || top_face_[k] < 0) continue;
      const Material& material = terrain.material(top_piece_[k]);
      if (!material.soil) continue;
      const double x = lattice.x() + s * i, y = lattice.y() + s * j;
      double bottom = kInfinity;
      std::size_t plane = 0;
      for (const int faces : hull_faces_) {
        LineClip clip;
        for (int f = 0; f < faces; ++f) {
          const Eigen::Vector4d& p = planes_[plane + static_cast<std::size_t>(f)];
          clip.cut(p.head<3>(), p.w(), x, y, f);
        }
        plane += static_cast<std::size_t>(faces);
        if (clip.met()) bottom = std::min(bottom, clip.lo);
      }
      if (!std::isfinite(bottom)) continue;
      const double depth = top_[k] - bottom;
      const bool on_grid = grid != nullptr && i >= 0 && j >= 0 && i < grid->columns() && j < grid->rows();
      const SoilMemory memory_here = on_grid ? detail::memoryOf(grid->node(i, j)) : SoilMemory{};
      if (!(depth > (memory_here.fresh ? 0.0 : memory_here.plastic_sinkage))) continue;
      std::optional<ConvexPolyhedron> piece_scratch;
      const Eigen::Vector3d normal = terrain.piece(top_piece_[k], piece_scratch).faceNormal(top_face_[k]);
      nodes_.push_back({.i = i,
                        .j = j,
                        .top = top_[k],
                        .normal = normal,
                        .soil = &*material.soil,
                        .point = Eigen::Vector3d(x, y, bottom),
                        .depth = depth,
                        .sigma = 0.0});
    }
  }
  if (nodes_.empty()) return out;

  // Bekker's b: the smaller extent of the nodes that carry the body along
  // its own x and y, a cell included.
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kInfinity), hi = -lo;
  for (const Node& n : nodes_) {
    const Eigen::Vector2d along(rotation.col(0).dot(n.point), rotation.col(1).dot(n.point));
    lo = lo.cwiseMin(along);
    hi = hi.cwiseMax(along);
  }
  const double b = (hi - lo).minCoeff() + s;

  // The pressures with the soil's damping, and the shear's bound.
  const double cell = s * s;
  double shear_bound = 0.0;
  std::vector<double>& bound = top_;  // reused: per carrying node
  bound.assign(nodes_.size(), 0.0);
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    Node& n = nodes_[k];
    const bool on_grid = grid != nullptr && n.i >= 0 && n.j >= 0 && n.i < grid->columns() && n.j < grid->rows();
    const SoilMemory before = on_grid ? detail::memoryOf(grid->node(n.i, n.j)) : SoilMemory{};
    const double sigma = reloadStress(*n.soil, b, before, n.depth);
    const Eigen::Vector3d v = motion.velocity + motion.angular_velocity.cross(n.point - origin);
    const double damped = std::max(0.0, sigma - n.soil->damping * v.dot(n.normal));
    n.sigma = damped;
    const double unloaded = sigma > 0.0 ? std::min(1.0, damped / sigma) : 0.0;
    bound[k] = (n.soil->cohesion + sigma * std::tan(n.soil->friction_angle_deg * kPi / 180.0)) * unloaded * cell;
    shear_bound += bound[k];
    if (on_grid) {
      const SoilMemory after = pressedSoil(*n.soil, b, before, n.depth);
      const detail::SoilNode stored = grid->node(n.i, n.j);
      if (after.plastic_sinkage != before.plastic_sinkage || after.max_pressure > stored.max_pressure) {
        grid->set(n.i, n.j, {static_cast<float>(after.plastic_sinkage), static_cast<float>(after.max_pressure)});
      }
    }
  }
  const double ramp = std::max(kBodySoilSpeedFloorMps, step_seconds * shear_bound / (kBodySoilStability * mass_));

  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Node& n = nodes_[k];
    const Eigen::Vector3d v = motion.velocity + motion.angular_velocity.cross(n.point - origin);
    const Eigen::Vector3d sliding = v - v.dot(n.normal) * n.normal;
    const double speed = sliding.norm();
    Eigen::Vector3d f = n.sigma * cell * n.normal;
    if (speed > 0.0) f -= bound[k] * std::min(1.0, speed / ramp) / speed * sliding;
    out.force += f;
    out.torque += (n.point - origin).cross(f);
    out.normal_force += n.sigma * cell;
    out.deepest = std::max(out.deepest, n.depth);
  }
  out.nodes = static_cast<int>(nodes_.size());
  out.area = cell * static_cast<double>(nodes_.size());
  out.plate_width = b;
  return out;
}

}  // namespace wtc

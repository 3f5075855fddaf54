// A body's underside on soft soil (design in wtc/tyre/body_soil.hpp).
#include "wtc/tyre/body_soil.hpp"

#include <algorithm>
#include <array>
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

}  // namespace

// (Named, not in the anonymous namespace: BodyOnSoil::Scratch, a member
// of a class with linkage, holds it.)
namespace detail {

// A convex solid met by vertical lines: each face n . x <= d as a bound on
// z along the line through (x, y). A face turned up (n_z > 0) bounds it
// from above, z <= c - a x - b y with (a, b, c) = (n_x, n_y, d) / n_z; one
// turned down from below, z >= c - a x - b y; an upright one bounds (x, y),
// n_x x + n_y y <= d. Laid out once per solid and step, so that a node
// costs no division.
struct VerticalSolid {
  struct Bound {
    double a, b, c;
    int face;
  };
  std::vector<Bound> above, below, sides;  // sides: (n_x, n_y, d)

  void clear() {
    above.clear();
    below.clear();
    sides.clear();
  }
  void add(const Eigen::Vector3d& n, double d, int face) {
    if (n.z() > 0.0) {
      above.push_back({n.x() / n.z(), n.y() / n.z(), d / n.z(), face});
    } else if (n.z() < 0.0) {
      below.push_back({n.x() / n.z(), n.y() / n.z(), d / n.z(), face});
    } else {
      sides.push_back({n.x(), n.y(), d, face});
    }
  }
  // The line's inside [lo, hi] and the face of hi; false where it misses.
  bool clip(double x, double y, double& lo, double& hi, int& top_face) const {
    for (const Bound& s : sides) {
      if (s.a * x + s.b * y > s.c) return false;
    }
    lo = -kInfinity;
    hi = kInfinity;
    top_face = -1;
    for (const Bound& f : below) lo = std::max(lo, f.c - f.a * x - f.b * y);
    for (const Bound& f : above) {
      const double t = f.c - f.a * x - f.b * y;
      if (t < hi) {
        hi = t;
        top_face = f.face;
      }
    }
    return lo <= hi;
  }
};

}  // namespace detail
using detail::VerticalSolid;

namespace {

bool finite(const BodySoilMotion& m) {
  return m.pose.matrix().allFinite() && m.velocity.allFinite() && m.angular_velocity.allFinite();
}

}  // namespace

// One node under the body that the soil carries.
struct BodySoilNode {
  int i, j;
  Eigen::Vector3d normal;  // the fresh surface's
  const Soil* soil;
  Eigen::Vector3d point;  // on the underside
  double depth;           // Z (m)
  SoilMemory memory;      // what the ground remembers there before this step
};

struct BodyOnSoil::Scratch {
  std::vector<PieceId> pieces;
  std::vector<double> top;              // per node of the box: the terrain's top (m)
  std::vector<Eigen::Vector3d> normal;  // and the normal of the face there
  std::vector<const Soil*> soil;        // and its soil (null: hard ground)
  std::vector<VerticalSolid> hulls;     // the body's, in the world
  VerticalSolid piece;
  std::vector<BodySoilNode> nodes;
  std::vector<double> sigma, bound;            // per carrying node: the damped pressure (Pa), the shear's bound (N)
  std::vector<std::array<double, 3>> sliding;  // and its sliding velocity (m/s)
};

BodyOnSoil::BodyOnSoil(std::vector<ConvexPolyhedron> hulls, double mass, const std::string& where)
    : hulls_(std::move(hulls)), mass_(mass), scratch_(std::make_unique<Scratch>()) {
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
  scratch_->hulls.resize(hulls_.size());
}

BodyOnSoil::~BodyOnSoil() = default;
BodyOnSoil::BodyOnSoil(BodyOnSoil&&) noexcept = default;
BodyOnSoil& BodyOnSoil::operator=(BodyOnSoil&&) noexcept = default;

BodySoilForces BodyOnSoil::step(const Terrain& terrain, GroundMemory* memory, const BodySoilMotion& motion,
                                double step_seconds) {
  BodySoilForces out;
  if (!finite(motion) || !(step_seconds > 0.0)) return out;
  Scratch& w = *scratch_;
  const Eigen::Matrix3d rotation = motion.pose.linear();
  const Eigen::Vector3d origin = motion.pose.translation();

  // The body's box in the world (its hulls' vertices turned), and the
  // soil pieces that may hold the surface under it: none whose box reaches
  // above the body's lowest point, nothing to press and nothing more to
  // compute (a chassis above the ground costs this alone).
  Aabb box{origin, origin};
  bool first = true;
  for (const ConvexPolyhedron& h : hulls_) {
    for (int v = 0; v < h.vertexCount(); ++v) {
      const Eigen::Vector3d p = motion.pose * h.vertex(v);
      if (first) box = Aabb{p, p};
      box.include(p);
      first = false;
    }
  }
  w.pieces.clear();
  terrain.overlapping(box, w.pieces);
  const bool any_soil = std::any_of(w.pieces.begin(), w.pieces.end(), [&](PieceId p) {
    return terrain.material(p).soil.has_value() && terrain.pieceBounds(p).max.z() > box.min.z();
  });
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
  const auto at = [&](int i, int j) {
    return static_cast<std::size_t>(j - j0) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(i - i0);
  };

  // The terrain's top at each node: the highest piece over it, the normal
  // of the face that bounds it from above, and its soil.
  w.top.assign(count, -kInfinity);
  w.normal.resize(count);
  w.soil.assign(count, nullptr);
  std::optional<ConvexPolyhedron> scratch;
  for (const PieceId id : w.pieces) {
    const ConvexPolyhedron& piece = terrain.piece(id, scratch);
    const Material& material = terrain.material(id);
    const Soil* soil = material.soil ? &*material.soil : nullptr;
    w.piece.clear();
    for (int f = 0; f < piece.faceCount(); ++f) w.piece.add(piece.faceNormal(f), piece.faceOffset(f), f);
    const Aabb& b = piece.bounds();
    const int pi0 = std::max(i0, index(b.min.x(), lattice.x(), false));
    const int pi1 = std::min(i1, index(b.max.x(), lattice.x(), true));
    const int pj0 = std::max(j0, index(b.min.y(), lattice.y(), false));
    const int pj1 = std::min(j1, index(b.max.y(), lattice.y(), true));
    for (int j = pj0; j <= pj1; ++j) {
      for (int i = pi0; i <= pi1; ++i) {
        double lo, hi;
        int face;
        const std::size_t k = at(i, j);
        if (!w.piece.clip(lattice.x() + s * i, lattice.y() + s * j, lo, hi, face) || !(hi > w.top[k]) || face < 0) {
          continue;
        }
        w.top[k] = hi;
        w.normal[k] = piece.faceNormal(face);
        w.soil[k] = soil;
      }
    }
  }

  // The body's hulls in the world, as vertical solids.
  for (std::size_t h = 0; h < hulls_.size(); ++h) {
    VerticalSolid& solid = w.hulls[h];
    solid.clear();
    for (int f = 0; f < hulls_[h].faceCount(); ++f) {
      const Eigen::Vector3d n = rotation * hulls_[h].faceNormal(f);
      solid.add(n, hulls_[h].faceOffset(f) + n.dot(origin), f);
    }
  }

  // The nodes whose soil the body's underside reaches below the surface
  // the ground remembers there.
  w.nodes.clear();
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const std::size_t k = at(i, j);
      if (w.soil[k] == nullptr) continue;
      const double x = lattice.x() + s * i, y = lattice.y() + s * j;
      double bottom = kInfinity;
      for (const VerticalSolid& solid : w.hulls) {
        double lo, hi;
        int face;
        if (solid.clip(x, y, lo, hi, face)) bottom = std::min(bottom, lo);
      }
      if (!std::isfinite(bottom)) continue;
      const double depth = w.top[k] - bottom;
      const bool on_grid = grid != nullptr && i >= 0 && j >= 0 && i < grid->columns() && j < grid->rows();
      const SoilMemory remembered = on_grid ? detail::memoryOf(grid->node(i, j)) : SoilMemory{};
      if (!(depth > (remembered.fresh ? 0.0 : remembered.plastic_sinkage))) continue;
      w.nodes.push_back({.i = i,
                         .j = j,
                         .normal = w.normal[k],
                         .soil = w.soil[k],
                         .point = Eigen::Vector3d(x, y, bottom),
                         .depth = depth,
                         .memory = remembered});
    }
  }
  if (w.nodes.empty()) return out;

  // Bekker's b: the smaller extent of the nodes that carry the body along
  // its own x and y, a cell included.
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kInfinity), hi = -lo;
  for (const BodySoilNode& n : w.nodes) {
    const Eigen::Vector2d along(rotation.col(0).dot(n.point), rotation.col(1).dot(n.point));
    lo = lo.cwiseMin(along);
    hi = hi.cwiseMax(along);
  }
  const double b = (hi - lo).minCoeff() + s;

  // The pressures with the soil's damping, the shear's bounds, and the
  // nodes pressed. A node's velocity is V_0 + omega x p, V_0 = V - omega x O
  // (scalar arithmetic: Eigen's small temporaries went through the stack).
  const double cell = s * s;
  double shear_bound = 0.0;
  w.sigma.resize(w.nodes.size());
  w.bound.resize(w.nodes.size());
  w.sliding.resize(w.nodes.size());
  const Eigen::Vector3d& omega = motion.angular_velocity;
  const Eigen::Vector3d v0 = motion.velocity - omega.cross(origin);
  const Soil* tan_of = nullptr;
  double tan_phi = 0.0;
  for (std::size_t k = 0; k < w.nodes.size(); ++k) {
    const BodySoilNode& n = w.nodes[k];
    if (n.soil != tan_of) {
      tan_of = n.soil;
      tan_phi = std::tan(n.soil->friction_angle_deg * kPi / 180.0);
    }
    const double px = n.point.x(), py = n.point.y(), pz = n.point.z();
    const double vx = v0.x() + omega.y() * pz - omega.z() * py;
    const double vy = v0.y() + omega.z() * px - omega.x() * pz;
    const double vz = v0.z() + omega.x() * py - omega.y() * px;
    const double nx = n.normal.x(), ny = n.normal.y(), nz = n.normal.z();
    const double into = vx * nx + vy * ny + vz * nz;  // out of the soil: > 0
    w.sliding[k] = {vx - into * nx, vy - into * ny, vz - into * nz};
    const double sigma = reloadStress(*n.soil, b, n.memory, n.depth);
    w.sigma[k] = std::max(0.0, sigma - n.soil->damping * into);
    const double unloaded = sigma > 0.0 ? std::min(1.0, w.sigma[k] / sigma) : 0.0;
    w.bound[k] = (n.soil->cohesion + sigma * tan_phi) * unloaded * cell;
    shear_bound += w.bound[k];
    const bool on_grid = grid != nullptr && n.i >= 0 && n.j >= 0 && n.i < grid->columns() && n.j < grid->rows();
    if (!on_grid) continue;
    const SoilMemory after = pressedSoil(*n.soil, b, n.memory, n.depth);
    if (after.plastic_sinkage != n.memory.plastic_sinkage || after.max_pressure > n.memory.max_pressure) {
      grid->set(n.i, n.j, {static_cast<float>(after.plastic_sinkage), static_cast<float>(after.max_pressure)});
    }
  }
  const double ramp = std::max(kBodySoilSpeedFloorMps, step_seconds * shear_bound / (kBodySoilStability * mass_));

  double fx = 0.0, fy = 0.0, fz = 0.0, tx = 0.0, ty = 0.0, tz = 0.0, normal = 0.0, deepest = 0.0;
  for (std::size_t k = 0; k < w.nodes.size(); ++k) {
    const BodySoilNode& n = w.nodes[k];
    const std::array<double, 3>& slide = w.sliding[k];
    const double speed = std::sqrt(slide[0] * slide[0] + slide[1] * slide[1] + slide[2] * slide[2]);
    const double push = w.sigma[k] * cell, drag = speed > 0.0 ? w.bound[k] * std::min(1.0, speed / ramp) / speed : 0.0;
    const double gx = push * n.normal.x() - drag * slide[0];
    const double gy = push * n.normal.y() - drag * slide[1];
    const double gz = push * n.normal.z() - drag * slide[2];
    const double rx = n.point.x() - origin.x(), ry = n.point.y() - origin.y(), rz = n.point.z() - origin.z();
    fx += gx;
    fy += gy;
    fz += gz;
    tx += ry * gz - rz * gy;
    ty += rz * gx - rx * gz;
    tz += rx * gy - ry * gx;
    normal += push;
    deepest = std::max(deepest, n.depth);
  }
  out.force = {fx, fy, fz};
  out.torque = {tx, ty, tz};
  out.normal_force = normal;
  out.deepest = deepest;
  out.nodes = static_cast<int>(w.nodes.size());
  out.area = cell * static_cast<double>(w.nodes.size());
  out.plate_width = b;
  return out;
}

}  // namespace wtc

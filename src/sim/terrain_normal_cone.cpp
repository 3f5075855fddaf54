// A body contact's normal against the terrain's surface (terrain_normal_cone.hpp).
#include "sim/terrain_normal_cone.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim {

Eigen::Vector3d projectOntoCone(const Eigen::Vector3d& n, std::span<const Eigen::Vector3d> generators) {
  // Moreau: the projection q has q . (n - q) = 0, so |n - q|^2 = |n|^2 -
  // |q|^2. It is n's projection onto the span of the generators active at
  // it, with nonnegative weights (Caratheodory: at most three; three
  // independent ones span space, and then q = n). Every such candidate is
  // orthogonal to n minus itself, so the nearest is the longest.
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  const auto consider = [&](const Eigen::Vector3d& q) {
    if (q.squaredNorm() > best.squaredNorm()) best = q;
  };
  const std::size_t k = generators.size();
  for (std::size_t i = 0; i < k; ++i) {
    const double a = n.dot(generators[i]);
    if (a > 0.0) consider(a * generators[i]);
  }
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = i + 1; j < k; ++j) {
      const Eigen::Vector3d& gi = generators[i];
      const Eigen::Vector3d& gj = generators[j];
      const double c = gi.dot(gj);
      const double det = 1.0 - c * c;  // the Gram determinant of two unit vectors
      if (det <= kTerrainNormalSlack) continue;
      const double ni = n.dot(gi), nj = n.dot(gj);
      const double wi = (ni - c * nj) / det, wj = (nj - c * ni) / det;
      if (wi >= 0.0 && wj >= 0.0) consider(wi * gi + wj * gj);
    }
  }
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = i + 1; j < k; ++j) {
      for (std::size_t l = j + 1; l < k; ++l) {
        Eigen::Matrix3d m;
        m << generators[i], generators[j], generators[l];
        if (std::abs(m.determinant()) <= kTerrainNormalSlack) continue;
        const Eigen::Vector3d w = m.inverse() * n;
        if ((w.array() >= 0.0).all()) return n;
      }
    }
  }
  return best;
}

bool inCone(const Eigen::Vector3d& n, std::span<const Eigen::Vector3d> generators) {
  return (n - projectOntoCone(n, generators)).norm() <= kTerrainNormalToleranceRad;
}

TerrainNormalCone::TerrainNormalCone(const Terrain& terrain) : terrain_(terrain) {
  // A heightfield's grid point touches 6 prisms, each of 5 faces; room for more.
  constexpr std::size_t kPiecesAround = 16, kFacesAround = 96;
  pieces_.reserve(kPiecesAround);
  faces_.reserve(kFacesAround);
  generators_.reserve(kFacesAround);
}

double TerrainNormalCone::reach(const Eigen::Vector3d& p_W, double depth) {
  return std::max(depth, 0.0) + kTerrainFaceReachM + kTerrainFaceReachPerM * p_W.cwiseAbs().maxCoeff();
}

std::optional<Eigen::Vector3d> TerrainNormalCone::normal(const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W,
                                                         double depth, std::span<const Eigen::Vector3d> body_W) {
  const double within = reach(p_W, depth);
  collectFaces(p_W, within);
  collectExposedNormals(within);
  if (generators_.empty()) return n_W;
  if (generators_.size() > 1 && !body_W.empty()) {
    if (inCone(n_W, generators_) && inCone(n_W, body_W)) return n_W;
    std::optional<Eigen::Vector3d> best;
    const auto consider = [&](const Eigen::Vector3d& g, std::span<const Eigen::Vector3d> other) {
      if (inCone(g, other) && (!best || g.dot(n_W) > best->dot(n_W))) best = g;
    };
    for (const Eigen::Vector3d& b : body_W) consider(b, generators_);
    for (const Eigen::Vector3d& g : generators_) consider(g, body_W);
    if (best) return best;
  }
  const Eigen::Vector3d q = projectOntoCone(n_W, generators_);
  if ((n_W - q).norm() <= kTerrainNormalToleranceRad) return n_W;  // in the cone: as the engine gave it
  const double length = q.norm();
  if (length <= kTerrainNormalSlack) return std::nullopt;
  return q / length;
}

std::optional<Eigen::Vector3d> TerrainNormalCone::normal(const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W,
                                                         double depth, const PlacedShape& body) {
  SurfaceNormals inward = surfaceNormals(body, p_W, reach(p_W, depth));
  for (int k = 0; k < inward.count; ++k) inward.normals[static_cast<std::size_t>(k)] *= -1.0;  // out of the ground
  return normal(p_W, n_W, depth, inward.view());
}

// The faces of the pieces within `reach` of p whose planes pass within
// `reach` of it: with p inside every other face's plane (planeBound),
// those p is on.
void TerrainNormalCone::collectFaces(const Eigen::Vector3d& p_W, double reach) {
  pieces_.clear();
  faces_.clear();
  terrain_.overlapping({p_W.array() - reach, p_W.array() + reach}, pieces_);
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const ConvexPolyhedron& piece = terrain_.piece(pieces_[k], formed_);
    if (piece.planeBound(p_W) > reach) continue;
    for (int f = 0; f < piece.faceCount(); ++f) {
      const Eigen::Vector3d n = piece.faceNormal(f);
      const double d = piece.faceOffset(f);
      if (n.dot(p_W) - d >= -reach) faces_.push_back({.n = n, .d = d, .piece = static_cast<int>(k)});
    }
  }
}

// The normals of the faces no other piece covers at the point (a face of
// the same plane, facing the other way: the wall between two pieces), each
// once.
void TerrainNormalCone::collectExposedNormals(double reach) {
  generators_.clear();
  for (const Face& face : faces_) {
    const bool covered = std::any_of(faces_.begin(), faces_.end(), [&](const Face& other) {
      return other.piece != face.piece && face.n.dot(other.n) <= -1.0 + kTerrainNormalSlack &&
             std::abs(face.d + other.d) <= reach;
    });
    if (covered) continue;
    const bool known = std::any_of(generators_.begin(), generators_.end(), [&](const Eigen::Vector3d& g) {
      return g.dot(face.n) >= 1.0 - kTerrainNormalSlack;
    });
    if (!known) generators_.push_back(face.n);
  }
}

}  // namespace wtc::sim

#pragma once
// The WTC terrain as one static Bullet collision object: a compound of
// convex hulls, one per piece, so that every pair other than wheel-terrain
// (a chassis scraping the ledge) collides with the same ground through
// Bullet's own algorithms.
//
// Large terrains are a two-level compound: pieces in groups of
// kPiecesPerGroup, neighbours together (Morton order of their centres),
// each group a compound. btCompoundCollisionAlgorithm walks every child of
// its compound at every step, overlapping or not; two levels make that walk
// n / G + G instead of n (bench/sim_step_bench.cpp measures the step).
#include <memory>
#include <vector>

#include <btBulletCollisionCommon.h>

#include "wtc/terrain.hpp"

namespace wtc::bullet {

/// Collision margin of the pieces' hulls (m): Bullet's GJK wants a margin;
/// 1 mm moves a chassis contact by 1 mm and never touches WTC's wheels.
inline constexpr btScalar kTerrainMarginM = 0.001;
/// Pieces per group of a two-level terrain compound (count): about the
/// square root of a large terrain's piece count.
inline constexpr int kPiecesPerGroup = 64;

class TerrainObject {
 public:
  explicit TerrainObject(const Terrain& terrain);
  TerrainObject(const TerrainObject&) = delete;
  TerrainObject& operator=(const TerrainObject&) = delete;

  const Terrain& terrain() const { return terrain_; }
  /// The piece a child shape of this object stands for: each hull's user
  /// index is its piece id (a contact callback sees the child it met).
  static PieceId pieceOf(const btCollisionShape& hull) { return hull.getUserIndex(); }
  btCollisionObject& object() { return object_; }
  const btCollisionObject& object() const { return object_; }

 private:
  const Terrain& terrain_;
  std::vector<std::unique_ptr<btConvexHullShape>> hulls_;
  std::vector<std::unique_ptr<btCompoundShape>> groups_;
  std::unique_ptr<btCompoundShape> compound_;
  btCollisionObject object_;
};

}  // namespace wtc::bullet

#include "terrain_query.hpp"

#include "wtc/base/error.hpp"
#include "wtc/geometry/aabb.hpp"
#include "wtc/geometry/point_query.hpp"

namespace wtc::python {

TerrainPoint queryTerrain(const Terrain& terrain, const Eigen::Vector3d& p, double reach,
                          TerrainQueryScratch& scratch) {
  if (!isFinite(p)) throw InvalidInputError("wtc.Terrain.query: point " + formatVector(p) + " is not finite");
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(reach);
  scratch.candidates.clear();
  terrain.overlapping(Aabb{p - r, p + r}, scratch.candidates);
  QueryOptions options;
  options.max_distance = reach;
  TerrainPoint best;
  for (const PieceId id : scratch.candidates) {
    const PointQuery q = queryPoint(terrain.piece(id, scratch.formed), p, options);
    if (q.status == QueryStatus::kBeyond || q.signed_distance > reach) continue;
    if (q.signed_distance < best.distance || (q.signed_distance == best.distance && id < best.piece)) {
      best.distance = q.signed_distance;
      best.normal = q.normal;
      best.piece = id;
    }
  }
  return best;
}

}  // namespace wtc::python

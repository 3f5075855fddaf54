// The modified GJK point query. Reads top to bottom:
//   validate -> bounding-box bound -> face-plane bound (exact inside)
//   -> nearest face's region (exact) -> crossed edge's region (exact) -> GJK.
// See include/wtc/geometry/point_query.hpp for the conventions and docs/point-query.md
// for the design and its measurements.
#include "wtc/geometry/point_query.hpp"
#include "polyhedron_layout.hpp"

#include <cmath>
#include <string>

#include "box_kernel.hpp"
#include "feature_regions.hpp"
#include "piece_kernel.hpp"
#include "prism_kernel.hpp"
#include "signed_volumes.hpp"
#include "wtc/base/error.hpp"

namespace wtc {

using Layout = detail::PolyhedronLayout;
namespace {

using detail::FaceRegion;
using Eigen::Vector3d;

// Beyond this the squared norms GJK forms would overflow double (m).
constexpr double kMaxCoordinateM = 1e150;

[[gnu::always_inline]] inline void validate(const ConvexPolyhedron& poly, const Vector3d& p, const QueryOptions& o) {
  // One comparison catches NaN, infinity and overflow (NaN compares false);
  // the message tells them apart off the hot path.
  const Vector3d q = (p - poly.origin()).cwiseAbs();
  if (!(q.x() <= kMaxCoordinateM && q.y() <= kMaxCoordinateM && q.z() <= kMaxCoordinateM)) {
    throw InvalidInputError("wtc::queryPoint: query point p = " + formatVector(p) +
                            (isFinite(p) ? " is more than 1e150 m from the piece; its squared distance overflows double"
                                         : " is not finite"));
  }
  if (!(o.relative_tolerance > 0.0 && o.relative_tolerance < 1.0)) {
    throw InvalidInputError("wtc::queryPoint: options.relative_tolerance = " + formatNumber(o.relative_tolerance) +
                            " is not in (0, 1)");
  }
  if (o.max_iterations < 1) {
    throw InvalidInputError("wtc::queryPoint: options.max_iterations = " + std::to_string(o.max_iterations) +
                            " must be at least 1");
  }
  if (std::isnan(o.max_distance)) throw InvalidInputError("wtc::queryPoint: options.max_distance is NaN");
}

// Result on or inside face `face` of the plane bound: exact, since inside a
// convex polyhedron the nearest surface point lies on the nearest face plane.
// Inline and built in one piece: half the mixed set's queries end here, and
// a call and a default-built result written twice cost more than the body.
inline PointQuery fromPlane(const ConvexPolyhedron& poly, const Vector3d& p, double bound, int face,
                            QueryStatus status) {
  const Vector3d normal(Layout::nx(poly)[face], Layout::ny(poly)[face], Layout::nz(poly)[face]);
  // On the surface (to roundoff) the direction is the limit from outside.
  const bool on_surface = std::abs(bound) <= tolerance::kTouchingRelative * poly.size();
  const bool outward = status == QueryStatus::kInside && !on_surface;
  return PointQuery{.signed_distance = bound,
                    .closest_point = p - bound * normal,
                    .direction = outward ? normal : Vector3d(-normal),
                    .normal = normal,
                    .iterations = 0,
                    .status = status};
}

// A result from the vector v = closest point - p, of length dist > 0.
inline PointQuery toward(const Vector3d& p, const Vector3d& v, double dist, double signed_distance, QueryStatus status,
                         int iterations = 0) {
  const Vector3d direction = v / dist;
  return PointQuery{.signed_distance = signed_distance,
                    .closest_point = p + v,
                    .direction = direction,
                    .normal = -direction,
                    .iterations = iterations,
                    .status = status};
}

PointQuery beyondBox(const ConvexPolyhedron& poly, const Vector3d& p, double distance) {
  const Vector3d v = p.cwiseMax(poly.bounds().min).cwiseMin(poly.bounds().max) - p;
  return toward(p, v, distance, distance, QueryStatus::kBeyond);
}

// A simplex of the given polyhedron vertices, as points of poly - p.
detail::Simplex simplexOf(const ConvexPolyhedron& poly, const Vector3d& q, const std::int32_t* vertices, int count) {
  detail::Simplex s;
  s.count = count;
  for (int m = 0; m < count; ++m) {
    s.vertex[m] = vertices[m];
    s.point[m] = poly.vertexLocal(vertices[m]) - q;
  }
  return s;
}

bool validCache(const ConvexPolyhedron& poly, const QueryCache& cache) {
  if (cache.count < 1 || cache.count > 3) return false;
  for (int m = 0; m < cache.count; ++m) {
    if (cache.vertex[m] < 0 || cache.vertex[m] >= poly.vertexCount()) return false;
  }
  return true;
}

void store(const detail::Simplex& s, QueryCache* cache) {
  if (cache == nullptr) return;
  cache->count = s.count <= 3 ? s.count : 0;
  for (int m = 0; m < cache->count; ++m) cache->vertex[m] = s.vertex[m];
}

// The exact answer of an edge or vertex region: closest point `on` (local).
[[gnu::always_inline]] inline PointQuery fromFeature(const ConvexPolyhedron& poly, const Vector3d& p, const Vector3d& q,
                                                     const Vector3d& on, double plane, int face,
                                                     const FaceRegion& region, QueryCache* cache) {
  const Vector3d v = on - q;
  const double dist = v.norm();
  if (dist <= tolerance::kTouchingRelative * poly.size()) {
    return fromPlane(poly, p, std::max(plane, 0.0), face, QueryStatus::kOutside);
  }
  if (cache != nullptr) {
    cache->count = region.count;
    cache->vertex[0] = region.seed[0];
    cache->vertex[1] = region.seed[1];
  }
  return toward(p, v, dist, dist, QueryStatus::kOutside);
}

// GJK on poly - p from the seed simplex `s`, or from the cached simplex
// when that starts nearer; `plane` and `face` are the plane bound's.
PointQuery gjk(const ConvexPolyhedron& poly, const Vector3d& p, const Vector3d& q, double plane, int face,
               const QueryOptions& options, detail::Simplex& s, QueryCache* cache) {
  const double max_distance = options.max_distance;
  Vector3d v = detail::closestToOrigin(s);
  if (cache != nullptr) {
    if (validCache(poly, *cache)) {
      detail::Simplex warm = simplexOf(poly, q, cache->vertex, cache->count);
      const Vector3d v_warm = detail::closestToOrigin(warm);
      if (v_warm.squaredNorm() < v.squaredNorm()) {
        s = warm;
        v = v_warm;
      }
    }
  }
  double dist = v.norm();
  const double touching = tolerance::kTouchingRelative * poly.size();
  const double plane_slack = tolerance::kPlaneSlackRelative * (poly.size() + dist);
  const double tol = options.relative_tolerance;
  double lower = std::max(plane, 0.0);
  // |v - x*|^2 <= |v|^2 - |x*|^2 <= |v|^2 - lower^2 for the true closest
  // point x* of a convex set, so this bounds the closest point's error by
  // tol |v| (and the distance's by tol^2 |v| / 2).
  auto certified = [&] { return dist * dist - lower * lower <= (tol * dist) * (tol * dist); };
  // A triangle on the nearest face's plane whose closest point is interior:
  // v is the foot of the perpendicular on that face, exactly.
  auto onNearestFace = [&] {
    if (s.count != 3 || dist - plane > plane_slack) return false;
    const Vector3d n = poly.faceNormal(face);
    const double d = Layout::pd(poly)[face];
    for (int m = 0; m < 3; ++m) {
      if (n.dot(poly.vertexLocal(s.vertex[m])) < d - plane_slack) return false;
    }
    return true;
  };
  QueryStatus status = QueryStatus::kIterationLimit;
  int iterations = 0;
  for (;;) {
    if (s.count == 4 || dist <= touching) {
      // On the surface to roundoff: the face normal is the only stable direction.
      store(s, cache);
      PointQuery on = fromPlane(poly, p, std::max(plane, 0.0), face, QueryStatus::kOutside);
      on.iterations = iterations;
      return on;
    }
    if (onNearestFace() || certified()) {
      status = QueryStatus::kOutside;
      break;
    }
    if (iterations == options.max_iterations) break;
    const int next = Layout::supportLocal(poly, -v, s.vertex[0]);
    ++iterations;
    const Vector3d w = poly.vertexLocal(next) - q;
    lower = std::max(lower, v.dot(w) / dist);  // v . x >= v . w for all x in poly - p
    if (lower > max_distance) {
      status = QueryStatus::kBeyond;
      break;
    }
    bool known = false;
    for (int m = 0; m < s.count; ++m) known |= s.vertex[m] == next;
    if (known || certified()) {
      status = QueryStatus::kOutside;  // no new vertex: exact on a polytope
      break;
    }
    detail::Simplex grown = s;
    grown.point[grown.count] = w;
    grown.vertex[grown.count] = next;
    ++grown.count;
    const Vector3d v_next = detail::closestToOrigin(grown);
    const double dist_next = v_next.norm();
    if (!(dist_next < dist) && grown.count != 4) {
      // GJK decreases |v| strictly in exact arithmetic; no decrease means
      // roundoff has taken over (two coplanar triangles taking turns).
      status = QueryStatus::kOutside;
      break;
    }
    s = grown;
    v = v_next;
    dist = dist_next;
  }
  store(s, cache);
  return toward(p, v, dist, status == QueryStatus::kBeyond ? lower : dist, status, iterations);
}

// The query, compiled once per kernel (piece_kernel.hpp): each piece kind
// runs its own straight code, its steps chosen when it is compiled. Every
// kernel's piece is solid (the kernels are chosen only for solid pieces).
template <detail::PieceKernel K>
PointQuery queryWith(const ConvexPolyhedron& poly, const Vector3d& p, const QueryOptions& options, QueryCache* cache) {
  using detail::PieceKernel;
  constexpr bool box = K == PieceKernel::kAxisBox;
  constexpr bool upright = K == PieceKernel::kUprightPrism;
  constexpr bool prism = upright || K == PieceKernel::kPrism;
  constexpr bool labelled = K == PieceKernel::kLabelledPrism;
  validate(poly, p, options);
  const double max_distance = options.max_distance;

  // 1. Bounding box: the cheapest lower bound, for the wheel's early exit.
  if (max_distance < std::numeric_limits<double>::infinity()) {
    const double box2 = poly.bounds().squaredDistance(p);
    if (box2 > max_distance * max_distance) return beyondBox(poly, p, std::sqrt(box2));
  }

  // 2. Face planes: exact inside, a lower bound outside.
  const Vector3d q = p - poly.origin();
  int face = 0;
  double plane = 0.0;
  if constexpr (box) {
    plane = detail::boxPlaneBound(poly, q, &face);
  } else if constexpr (prism || labelled) {
    plane = Layout::planeBoundAt<detail::kPrismFaceCount>(detail::PrismLayout(poly).nx(), q, &face);
  } else {
    plane = Layout::planeBoundLocal(poly, q, &face);
  }
  if (plane <= 0.0 && (K != PieceKernel::kGeneral || !poly.isFlat())) {
    if (cache != nullptr) cache->count = 0;
    return fromPlane(poly, p, plane, face, QueryStatus::kInside);
  }
  if (plane > max_distance) return fromPlane(poly, p, plane, face, QueryStatus::kBeyond);

  if (!options.feature_regions) {
    // Plain GJK from the nearest face's first three vertices.
    detail::Simplex s = simplexOf(poly, q, poly.faceVertices(face).data(), 3);
    return gjk(poly, p, q, plane, face, options, s, cache);
  }

  // 3. The nearest face's region: inside it, the projection is exact.
  FaceRegion region;
  if constexpr (box) {
    region = detail::boxClassify(poly, q, face);
  } else if constexpr (upright) {
    region = detail::uprightPrismClassify(poly, q, face);
  } else if constexpr (prism) {
    region = detail::prismClassify(poly, q, face);
  } else if constexpr (labelled) {
    region = detail::labelledPrismClassify(poly, q, face);
  } else {
    region = detail::classify(poly, q, face);
  }
  if (region.inside) {
    if (cache != nullptr) cache->count = 0;
    // max: on a flat piece both faces can read -roundoff on the polygon.
    return fromPlane(poly, p, std::max(plane, 0.0), face, QueryStatus::kOutside);
  }

  // 4. The crossed edge's or vertex's region: its closest point is exact.
  Vector3d on_feature;
  bool on_edge = false;
  if constexpr (prism) {
    on_edge = detail::prismEdgeRegion(poly, q, region, &on_feature);
  } else if constexpr (labelled) {
    on_edge = detail::labelledPrismEdgeRegion(poly, q, region, &on_feature);
  } else {
    on_edge = detail::edgeRegion(poly, q, region, &on_feature);
  }
  auto onVertex = [&] {
    if constexpr (box) return detail::boxVertexRegion(poly, q, region, &on_feature);
    if constexpr (prism) return detail::prismVertexRegion(poly, q, region, &on_feature);
    if constexpr (labelled) return detail::labelledPrismVertexRegion(poly, q, region, &on_feature);
    return detail::vertexRegion(poly, q, region, &on_feature);
  };
  if (on_edge || onVertex()) return fromFeature(poly, p, q, on_feature, plane, face, region, cache);

  // 5. GJK on poly - p, from the crossed edge or vertex.
  detail::Simplex s = simplexOf(poly, q, region.seed, region.count);
  return gjk(poly, p, q, plane, face, options, s, cache);
}

PointQuery query(const ConvexPolyhedron& poly, const Vector3d& p, const QueryOptions& options, QueryCache* cache) {
  // The piece's own kernel where one fits (piece_kernel.hpp): the same
  // decisions and answers, fewer operations.
  using detail::PieceKernel;
  switch (static_cast<PieceKernel>(Layout::kernel(poly))) {
    case PieceKernel::kAxisBox:
      return queryWith<PieceKernel::kAxisBox>(poly, p, options, cache);
    case PieceKernel::kPrism:
      return queryWith<PieceKernel::kPrism>(poly, p, options, cache);
    case PieceKernel::kUprightPrism:
      return queryWith<PieceKernel::kUprightPrism>(poly, p, options, cache);
    case PieceKernel::kLabelledPrism:
      return queryWith<PieceKernel::kLabelledPrism>(poly, p, options, cache);
    case PieceKernel::kGeneral:
      break;
  }
  return queryWith<PieceKernel::kGeneral>(poly, p, options, cache);
}

}  // namespace

const char* toString(QueryStatus status) {
  switch (status) {
    case QueryStatus::kOutside:
      return "outside";
    case QueryStatus::kInside:
      return "inside";
    case QueryStatus::kBeyond:
      return "beyond";
    case QueryStatus::kIterationLimit:
      return "iteration-limit";
  }
  return "unknown";
}

PointQuery queryPoint(const ConvexPolyhedron& poly, const Vector3d& p, const QueryOptions& options) {
  return query(poly, p, options, nullptr);
}

PointQuery queryPoint(const ConvexPolyhedron& poly, const Vector3d& p, const QueryOptions& options, QueryCache& cache) {
  return query(poly, p, options, &cache);
}

}  // namespace wtc

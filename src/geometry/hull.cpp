// ConvexPolyhedron::fromPoints: the convex hull of a point set, by Qhull
// (Barber, Dobkin, Huhdanpaa, "The Quickhull algorithm for convex hulls",
// ACM TOMS 22(4), 1996), through its reentrant C interface.
//
// Before Qhull: points are checked, translated to their bounding-box centre
// (precision far from the origin), nearly duplicate points merged, and the
// set classified as solid, flat (coplanar) or degenerate (collinear).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc {
namespace {

constexpr const char* kWhere = "wtc::ConvexPolyhedron::fromPoints: ";

// Keeps one point of each cluster closer than `tol`; sorting by x makes the
// search a short window in practice.
std::vector<Eigen::Vector3d> mergeNearDuplicates(std::vector<Eigen::Vector3d> points, double tol) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); });
  std::vector<Eigen::Vector3d> kept;
  kept.reserve(points.size());
  for (const auto& p : points) {
    bool duplicate = false;
    for (auto it = kept.rbegin(); it != kept.rend() && p.x() - it->x() <= tol; ++it) {
      if ((p - *it).squaredNorm() <= tol * tol) {
        duplicate = true;
        break;
      }
    }
    if (!duplicate) kept.push_back(p);
  }
  return kept;
}

// Owns a Qhull run; the error stream is captured so that Qhull's own
// message reaches the exception.
class QhullRun {
 public:
  QhullRun() : err_(open_memstream(&err_text_, &err_size_)) { qh_zero(&qh_, err_); }
  ~QhullRun() {
    qh_freeqhull(&qh_, !qh_ALL);
    int curlong = 0;
    int totlong = 0;
    qh_memfreeshort(&qh_, &curlong, &totlong);
    if (err_ != nullptr) std::fclose(err_);
    std::free(err_text_);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;

  void run(int dim, std::vector<double>& coords) {
    char command[] = "qhull";
    const int npoints = static_cast<int>(coords.size()) / dim;
    if (qh_new_qhull(&qh_, dim, npoints, coords.data(), False, command, nullptr, err_) != 0) {
      std::fflush(err_);
      throw InvalidInputError(std::string(kWhere) +
                              "Qhull failed: " + std::string(err_text_ != nullptr ? err_text_ : "", err_size_));
    }
  }
  qhT* get() { return &qh_; }

 private:
  qhT qh_;
  char* err_text_ = nullptr;
  std::size_t err_size_ = 0;
  FILE* err_;
};

ConvexPolyhedron flatHull(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& n,
                          const Eigen::Vector3d& origin) {
  const Eigen::Vector3d u = n.unitOrthogonal();
  const Eigen::Vector3d v = n.cross(u);
  std::vector<double> coords;
  for (const auto& p : pts) {
    coords.push_back(u.dot(p));
    coords.push_back(v.dot(p));
  }
  QhullRun hull;
  hull.run(2, coords);
  qhT* qh = hull.get();
  std::vector<Eigen::Vector3d> vertices;
  vertexT* vertex;
  FORALLvertices { vertices.push_back(pts[qh_pointid(qh, vertex->point)] + origin); }
  // Hull vertices sorted by angle about their mean are in boundary order.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : vertices) mean += p;
  mean /= static_cast<double>(vertices.size());
  auto angle = [&](const Eigen::Vector3d& p) { return std::atan2(v.dot(p - mean), u.dot(p - mean)); };
  std::sort(vertices.begin(), vertices.end(), [&](const auto& a, const auto& b) { return angle(a) < angle(b); });
  std::vector<int> top(vertices.size());
  std::iota(top.begin(), top.end(), 0);  // counter-clockwise about n = u x v
  std::vector<int> bottom(top.rbegin(), top.rend());
  return ConvexPolyhedron::fromMesh(vertices, {top, bottom});
}

struct HullMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<Eigen::Vector3d> normals;
};

HullMesh solidHull(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& origin) {
  std::vector<double> coords;
  for (const auto& p : pts) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  QhullRun hull;
  hull.run(3, coords);
  qhT* qh = hull.get();
  std::vector<int> index_of(pts.size(), -1);
  HullMesh out;
  std::vector<Eigen::Vector3d>& vertices = out.vertices;
  vertexT* vertex;
  FORALLvertices {
    const int id = qh_pointid(qh, vertex->point);
    index_of[id] = static_cast<int>(vertices.size());
    vertices.push_back(pts[id] + origin);
  }
  facetT* facet;
  FORALLfacets {
    setT* ordered = qh_facet3vertex(qh, facet);
    std::vector<int> face;
    vertexT** vertexp;
    FOREACHvertex_(ordered) face.push_back(index_of[qh_pointid(qh, vertex->point)]);
    qh_settempfree(qh, &ordered);
    // Orient counter-clockwise seen from outside, checked against Qhull's
    // outward normal rather than trusting its ordering convention.
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < face.size(); ++k) {
      area += (vertices[face[k]] - origin).cross(vertices[face[(k + 1) % face.size()]] - origin);
    }
    const Eigen::Vector3d normal(facet->normal[0], facet->normal[1], facet->normal[2]);
    if (area.dot(normal) < 0.0) std::reverse(face.begin(), face.end());
    out.faces.push_back(std::move(face));
    out.normals.push_back(normal);
  }
  return out;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::fromPoints(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) throw InvalidInputError(std::string(kWhere) + "the point set is empty");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!isFinite(points[i])) {
      throw InvalidInputError(std::string(kWhere) + "point " + std::to_string(i) + " of " +
                              std::to_string(points.size()) + " = " + formatVector(points[i]) + " is not finite");
    }
  }
  const Aabb box = Aabb::of(points);
  const Eigen::Vector3d origin = box.center();
  const double size = box.extent().norm();
  std::vector<Eigen::Vector3d> local;
  local.reserve(points.size());
  for (const auto& p : points) local.push_back(p - origin);
  local = mergeNearDuplicates(std::move(local), tolerance::kHullMergeRelative * size);

  // Classify with three extreme points: a, b far apart, c far from line ab.
  auto degenerate = [&](const std::string& shape) {
    return InvalidInputError(std::string(kWhere) + "the " + std::to_string(points.size()) + " points are " + shape +
                             " (bounding box " + formatVector(box.min) + " to " + formatVector(box.max) +
                             "); a piece needs at least 3 non-collinear points");
  };
  if (local.size() < 3) throw degenerate(local.size() == 1 ? "all coincident" : "collinear");
  int axis = 0;
  box.extent().maxCoeff(&axis);
  auto [lo, hi] = std::minmax_element(local.begin(), local.end(),
                                      [axis](const auto& a, const auto& b) { return a[axis] < b[axis]; });
  const Eigen::Vector3d a = *lo;
  const Eigen::Vector3d ab = (*hi - a).normalized();
  Eigen::Vector3d c = a;
  double c_dist = 0.0;
  for (const auto& p : local) {
    const double d = ((p - a) - ab * ab.dot(p - a)).norm();
    if (d > c_dist) {
      c_dist = d;
      c = p;
    }
  }
  if (c_dist <= tolerance::kFlatRelative * size) throw degenerate("collinear");
  const Eigen::Vector3d n = ab.cross(c - a).normalized();
  double thickness = 0.0;
  for (const auto& p : local) thickness = std::max(thickness, std::abs(n.dot(p - a)));
  if (thickness <= tolerance::kFlatRelative * size) return flatHull(local, n, origin);
  const HullMesh hull = solidHull(local, origin);
  return assemble(hull.vertices, hull.faces, false, &hull.normals);
}

}  // namespace wtc

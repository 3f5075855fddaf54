// Triangle meshes as extruded prisms (design note in
// include/wtc/terrain/triangle_mesh.hpp). Per part: check the input, weld vertices
// by exact position to see whether the part is closed, fix an inside-out
// closed part, keep a closed convex part whole if asked, and otherwise
// extrude every non-degenerate triangle.
#include "wtc/terrain/triangle_mesh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <optional>
#include <unordered_map>

#include "builder_support.hpp"
#include "compact_mesh.hpp"
#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"

namespace wtc {
namespace {

constexpr const char* kWhere = "wtc::addTriangleMesh";

struct PositionHash {
  std::size_t operator()(const Eigen::Vector3d& p) const {
    std::size_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; ++i) h = (h ^ std::bit_cast<std::uint64_t>(p[i] + 0.0)) * 1099511628211ull;
    return h;
  }
};
struct PositionEqual {
  bool operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const { return a == b; }
};

// Ids of the distinct positions: two vertices with bit-identical coordinates
// (STL repeats every vertex per triangle) get one id.
std::vector<std::int32_t> weld(const std::vector<Eigen::Vector3d>& vertices) {
  std::unordered_map<Eigen::Vector3d, std::int32_t, PositionHash, PositionEqual> ids;
  ids.reserve(vertices.size());
  std::vector<std::int32_t> out(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    out[i] = ids.emplace(vertices[i], static_cast<std::int32_t>(ids.size())).first->second;
  }
  return out;
}

// Closed: every directed edge between distinct welded vertices occurs once,
// and so does its reverse.
bool isClosed(const TriangleMesh& mesh, const std::vector<std::int32_t>& id) {
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(3 * mesh.triangles.size());
  auto key = [](std::int32_t a, std::int32_t b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = id[t[k]], b = id[t[(k + 1) % 3]];
      if (a != b && ++directed[key(a, b)] > 1) return false;
    }
  }
  for (const auto& [edge, count] : directed) {
    if (!directed.contains((edge << 32) | (edge >> 32))) return false;
  }
  return !directed.empty();
}

// Signed enclosed volume (m^3), positive for outward winding, taken about
// the vertex mean to keep far-from-origin meshes precise.
double signedVolume(const TriangleMesh& mesh) {
  Eigen::Vector3d o = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) o += v;
  o /= static_cast<double>(mesh.vertices.size());
  double six_v = 0.0;
  for (const auto& t : mesh.triangles) {
    six_v += (mesh.vertices[t[0]] - o).dot((mesh.vertices[t[1]] - o).cross(mesh.vertices[t[2]] - o));
  }
  return six_v / 6.0;
}

double hullVolume(const ConvexPolyhedron& hull) {
  const Eigen::Vector3d o = hull.centroid();
  double six_v = 0.0;
  for (int f = 0; f < hull.faceCount(); ++f) {
    const auto face = hull.faceVertices(f);
    const Eigen::Vector3d a = hull.vertex(face[0]) - o;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      six_v += a.dot((hull.vertex(face[k]) - o).cross(hull.vertex(face[k + 1]) - o));
    }
  }
  return six_v / 6.0;
}

std::string partName(const TriangleMesh& mesh) {
  return std::string(kWhere) + ": " + (mesh.name.empty() ? "mesh" : mesh.name);
}

std::string triangleName(const TriangleMesh& mesh, std::size_t t) {
  return partName(mesh) + ", triangle " + std::to_string(t);
}

void checkInput(const TriangleMesh& mesh) {
  const auto n = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::int32_t i : mesh.triangles[t]) {
      if (i < 0 || i >= n) {
        throw InvalidInputError(triangleName(mesh, t) + " refers to vertex " + std::to_string(i) + ", but there are " +
                                std::to_string(n) + " vertices");
      }
      if (!mesh.vertices[i].allFinite()) {
        throw InvalidInputError(triangleName(mesh, t) + ": vertex " + std::to_string(i) + " = " +
                                formatVector(mesh.vertices[i]) + " is not finite");
      }
    }
  }
}

}  // namespace

void MeshBuildReport::append(const MeshBuildReport& other) {
  if (pieces.count == 0) pieces.first = other.pieces.first;
  pieces.count += other.pieces.count;
  triangles += other.triangles;
  degenerate_skipped += other.degenerate_skipped;
  convex_parts += other.convex_parts;
  flipped_parts += other.flipped_parts;
}

ConvexPolyhedron makeExtrudedTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                      double thickness) {
  return detail::makePrism({a, b, c}, detail::extrudedBottom(a, b, c, thickness));
}

MeshBuildReport addTriangleMesh(TerrainBuilder& builder, const TriangleMesh& mesh, MaterialId material,
                                const MeshExtrusionOptions& options) {
  requireLength(options.thickness, kWhere, "thickness");
  checkInput(mesh);
  MeshBuildReport report;
  report.pieces.first = static_cast<PieceId>(builder.pieceCount());
  report.triangles = static_cast<std::int64_t>(mesh.triangles.size());
  if (mesh.triangles.empty()) return report;

  const std::vector<std::int32_t> welded = weld(mesh.vertices);
  const bool closed = isClosed(mesh, welded);
  const double volume = closed ? signedVolume(mesh) : 0.0;
  const bool flip = closed && volume < 0.0;
  report.flipped_parts = flip ? 1 : 0;

  if (options.keep_convex_parts && closed) {
    try {
      std::vector<Eigen::Vector3d> used;
      used.reserve(3 * mesh.triangles.size());
      for (const auto& t : mesh.triangles) {
        for (std::int32_t i : t) used.push_back(mesh.vertices[i]);
      }
      ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(used);
      const double hull_volume = hullVolume(hull);
      if (!hull.isFlat() && std::abs(std::abs(volume) - hull_volume) <= kConvexPartVolumeRelative * hull_volume) {
        builder.addPiece(std::move(hull), material);
        report.pieces.count = 1;
        report.convex_parts = 1;
        return report;
      }
    } catch (const InvalidInputError&) {
      // No solid hull (all points coplanar): not a convex part; extrude.
    }
  }

  // The triangles that carry surface, wound outward: the pieces, in order.
  std::vector<std::array<std::int32_t, 3>> kept;
  std::vector<std::size_t> source;  // kept[i] is mesh.triangles[source[i]]
  kept.reserve(mesh.triangles.size());
  source.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<std::int32_t, 3> outward{tri[0], flip ? tri[2] : tri[1], flip ? tri[1] : tri[2]};
    const Eigen::Vector3d& a = mesh.vertices[outward[0]];
    const Eigen::Vector3d& b = mesh.vertices[outward[1]];
    const Eigen::Vector3d& c = mesh.vertices[outward[2]];
    const double longest = std::sqrt(std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
    const double scale = std::max(longest, options.thickness);
    // Altitude on the longest edge = |2 area| / longest.
    if (!(longest > 0.0) || (b - a).cross(c - a).norm() <= kDegenerateTriangleRelative * scale * longest) {
      ++report.degenerate_skipped;
      continue;
    }
    kept.push_back(outward);
    source.push_back(t);
  }

  if (options.compact) {
    if (kept.empty()) return report;
    // Only the vertices the kept triangles use, each distinct position
    // once (welded ids are dense, in first-seen order).
    TriangleMesh compact{mesh.name, {}, std::move(kept)};
    std::vector<std::int32_t> index_of(mesh.vertices.size(), -1);  // by welded id
    for (auto& tri : compact.triangles) {
      for (std::int32_t& i : tri) {
        std::int32_t& slot = index_of[welded[i]];
        if (slot < 0) {
          slot = static_cast<std::int32_t>(compact.vertices.size());
          compact.vertices.push_back(mesh.vertices[i]);
        }
        i = slot;
      }
    }
    report.pieces = detail::TerrainBuilderAccess::addFormedPieces(
        builder, std::make_shared<const detail::CompactTriangleMesh>(std::move(compact), options.thickness), material,
        partName(mesh));
    return report;
  }

  // Each prism is checked now, where the triangle can still be named, and
  // made when the terrain is built, where the terrain keeps it
  // (detail::PendingPrisms): makeExtrudedTriangle's piece, bit for bit, from
  // the same corners (makeCheckedPrism's word; CompactMeshTest).
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const Eigen::Vector3d& a = mesh.vertices[kept[i][0]];
    const Eigen::Vector3d& b = mesh.vertices[kept[i][1]];
    const Eigen::Vector3d& c = mesh.vertices[kept[i][2]];
    try {
      makeExtrudedTriangle(a, b, c, options.thickness);
    } catch (const InvalidInputError& e) {
      throw InvalidInputError(triangleName(mesh, source[i]) + " " + formatVector(a) + ", " + formatVector(b) + ", " +
                              formatVector(c) + ": " + e.what());
    }
  }
  struct Corners {
    std::vector<Eigen::Vector3d> top;  // three per prism
    double thickness;
  };
  auto corners = std::make_shared<Corners>(Corners{{}, options.thickness});
  corners->top.reserve(3 * kept.size());
  for (const auto& t : kept) {
    for (const std::int32_t v : t) corners->top.push_back(mesh.vertices[v]);
  }
  report.pieces = detail::TerrainBuilderAccess::addPendingPrisms(
      builder, kept.size(),
      [corners](std::size_t k, std::array<Eigen::Vector3d, 3>& top, std::array<Eigen::Vector3d, 3>& bottom) {
        top = {corners->top[3 * k], corners->top[3 * k + 1], corners->top[3 * k + 2]};
        bottom = detail::extrudedBottom(top[0], top[1], top[2], corners->thickness);
      },
      [material](std::size_t) { return material; }, partName(mesh));
  return report;
}

}  // namespace wtc

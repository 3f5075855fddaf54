// Heightfield cells as triangular prisms down to a flat base (design note in
// include/wtc/terrain/heightfield.hpp).
#include "wtc/terrain/heightfield.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "builder_support.hpp"
#include "compact_heightfield.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"

namespace wtc {
namespace {

constexpr const char* kWhere = "wtc::Heightfield";

// A cell_holes entry that marks a hole.
bool holeEntry(std::uint8_t h) { return h != 0; }

// The field's materials are registered: `material`, and each cell's own.
void requireCellMaterials(const TerrainBuilder& builder, const Heightfield& f, MaterialId material, const char* where) {
  builder.requireMaterial(material, where);
  for (std::size_t cell = 0; cell < f.cell_materials.size(); ++cell) {
    const MaterialId m = f.cell_materials[cell];
    if (m < 0 || m >= builder.materialCount()) {
      const auto per_row = static_cast<std::size_t>(f.cols - 1);
      throw InvalidInputError(std::string(where) + ": cell (row " + std::to_string(cell / per_row) + ", col " +
                              std::to_string(cell % per_row) + ") has material id " + std::to_string(m) +
                              ", which is not registered (" + std::to_string(builder.materialCount()) + " materials)");
    }
  }
}

// A point of the grid in cell coordinates: cell (r, c) and the fractions
// s (along x) and t (along y) across it, in [0, 1].
struct CellPoint {
  int r = 0, c = 0;
  double s = 0.0, t = 0.0;
};

// From column and row coordinates u in [0, cols - 1], v in [0, rows - 1];
// the far edges belong to the last cells.
CellPoint locate(const Heightfield& f, double u, double v) {
  const int c = std::min(static_cast<int>(u), f.cols - 2);
  const int r = std::min(static_cast<int>(v), f.rows - 2);
  return {r, c, u - c, v - r};
}

}  // namespace

bool Heightfield::hasHoles() const { return std::any_of(cell_holes.begin(), cell_holes.end(), holeEntry); }

std::size_t Heightfield::pieceCount() const {
  const auto holes = static_cast<std::size_t>(std::count_if(cell_holes.begin(), cell_holes.end(), holeEntry));
  return 2 * (cellCount() - std::min(holes, cellCount()));
}

double Heightfield::baseZ() const {
  const double lowest = heights.empty() ? 0.0 : *std::min_element(heights.begin(), heights.end());
  return origin.z() + lowest - base_depth;
}

void validate(const Heightfield& f) {
  requireAtLeast(f.rows, 2, kWhere, "rows");
  requireAtLeast(f.cols, 2, kWhere, "cols");
  requireLength(f.spacing_x, kWhere, "spacing_x");
  requireLength(f.spacing_y, kWhere, "spacing_y");
  requireLength(f.base_depth, kWhere, "base_depth");
  if (!f.origin.allFinite()) {
    throw InvalidInputError(std::string(kWhere) + ": origin = " + formatVector(f.origin) + " is not finite");
  }
  for (int k = 0; k < 3; ++k) requireAtMostMaxLength(f.origin[k], kWhere, "origin");
  const auto samples = static_cast<std::uint64_t>(f.rows) * static_cast<std::uint64_t>(f.cols);
  if (f.heights.size() != samples) {
    throw InvalidInputError(std::string(kWhere) + ": heights has " + std::to_string(f.heights.size()) +
                            " values, but rows x cols = " + std::to_string(f.rows) + " x " + std::to_string(f.cols) +
                            " = " + std::to_string(samples));
  }
  const auto cells = static_cast<std::uint64_t>(f.rows - 1) * static_cast<std::uint64_t>(f.cols - 1);
  if (!f.cell_materials.empty() && f.cell_materials.size() != cells) {
    throw InvalidInputError(std::string(kWhere) + ": cell_materials has " + std::to_string(f.cell_materials.size()) +
                            " ids, but the grid has (rows - 1) x (cols - 1) = " + std::to_string(cells) +
                            " cells (or give none)");
  }
  if (!f.cell_holes.empty() && f.cell_holes.size() != cells) {
    throw InvalidInputError(std::string(kWhere) + ": cell_holes has " + std::to_string(f.cell_holes.size()) +
                            " entries, but the grid has (rows - 1) x (cols - 1) = " + std::to_string(cells) +
                            " cells (or give none)");
  }
  const std::size_t pieces = f.pieceCount();
  if (pieces == 0) {
    throw InvalidInputError(std::string(kWhere) + ": every one of the " + std::to_string(cells) +
                            " cells is a hole; the field has no ground");
  }
  if (pieces > static_cast<std::size_t>(std::numeric_limits<PieceId>::max())) {
    throw InvalidInputError(std::string(kWhere) + ": " + std::to_string(f.rows) + " x " + std::to_string(f.cols) +
                            " samples make " + std::to_string(pieces) + " pieces, more than a PieceId can number");
  }
  for (int r = 0; r < f.rows; ++r) {
    for (int c = 0; c < f.cols; ++c) {
      if (!std::isfinite(f.height(r, c))) {
        throw InvalidInputError(std::string(kWhere) + ": height at (row " + std::to_string(r) + ", col " +
                                std::to_string(c) + ") = " + formatNumber(f.height(r, c)) + " is not finite");
      }
      if (std::abs(f.height(r, c)) > kMaxLengthM) {
        const std::string name = "height at (row " + std::to_string(r) + ", col " + std::to_string(c) + ")";
        requireAtMostMaxLength(f.height(r, c), kWhere, name.c_str());
      }
    }
  }
}

ConvexPolyhedron makeTriangularPrism(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                     double base_z) {
  return detail::makePrism({a, b, c}, {Eigen::Vector3d(a.x(), a.y(), base_z), Eigen::Vector3d(b.x(), b.y(), base_z),
                                       Eigen::Vector3d(c.x(), c.y(), base_z)});
}

PieceRange addHeightfield(TerrainBuilder& builder, const Heightfield& f, MaterialId material) {
  validate(f);
  const std::string where =
      "wtc::addHeightfield (" + std::to_string(f.rows) + " x " + std::to_string(f.cols) + " samples)";
  builder.requireRoomFor(f.pieceCount(), where);
  requireCellMaterials(builder, f, material, "wtc::addHeightfield");
  // The prisms are made when the terrain is built, each where the terrain
  // keeps it (detail::PendingPrisms), from the corners the compact field
  // gives: makeTriangularPrism's, bit for bit (CompactHeightfieldTest).
  // Each piece's material is the compact field's answer too.
  auto grid = std::make_shared<const detail::CompactHeightfield>(f);
  const PieceRange range = detail::TerrainBuilderAccess::addPendingPrisms(
      builder, grid->pieceCount(),
      [grid](std::size_t k, std::array<Eigen::Vector3d, 3>& top, std::array<Eigen::Vector3d, 3>& bottom) {
        grid->prismCorners(k, top, bottom);
      },
      [&](std::size_t k) { return grid->materialId(k, material); }, where);
  detail::TerrainBuilderAccess::noteFieldPrisms(builder, range);
  return range;
}

PieceRange addCompactHeightfield(TerrainBuilder& builder, Heightfield field, MaterialId material) {
  auto grid = std::make_shared<const detail::CompactHeightfield>(std::move(field));  // validates it
  requireCellMaterials(builder, grid->field(), material, "wtc::addCompactHeightfield");
  const std::string where = "wtc::addCompactHeightfield (" + std::to_string(grid->field().rows) + " x " +
                            std::to_string(grid->field().cols) + " samples)";
  return detail::TerrainBuilderAccess::addFormedPieces(builder, std::move(grid), material, where);
}

std::optional<PieceId> cellPiece(const PieceRange& range, const Heightfield& f, int r, int c, int k) {
  if (f.isHole(r, c)) return std::nullopt;
  const std::size_t cell = static_cast<std::size_t>(r) * (f.cols - 1) + c;
  std::size_t holes_before = 0;
  if (!f.cell_holes.empty()) {
    holes_before = static_cast<std::size_t>(
        std::count_if(f.cell_holes.begin(), f.cell_holes.begin() + static_cast<std::ptrdiff_t>(cell), holeEntry));
  }
  return range.first + static_cast<PieceId>(2 * (cell - holes_before)) + k;
}

std::optional<PieceId> pieceUnder(const PieceRange& range, const Heightfield& f, double x, double y) {
  const auto onGrid = [](double w, int samples) { return w > 0.0 ? std::min(w, samples - 1.0) : 0.0; };
  const CellPoint p =
      locate(f, onGrid((x - f.origin.x()) / f.spacing_x, f.cols), onGrid((y - f.origin.y()) / f.spacing_y, f.rows));
  return cellPiece(range, f, p.r, p.c, p.s >= p.t ? 0 : 1);
}

void holesAtMissingSamples(Heightfield& f, const std::vector<std::uint8_t>& missing) {
  const auto samples = static_cast<std::size_t>(f.rows) * static_cast<std::size_t>(f.cols);
  if (f.rows < 2 || f.cols < 2 || missing.size() != samples || f.heights.size() != samples) {
    throw InvalidInputError(std::string(kWhere) + ": holesAtMissingSamples needs one entry per sample (" +
                            std::to_string(samples) + ")");
  }
  const auto count = static_cast<std::size_t>(std::count_if(missing.begin(), missing.end(), holeEntry));
  if (count == 0) return;
  if (count == samples) {
    throw InvalidInputError(std::string(kWhere) + ": all " + std::to_string(samples) + " samples are missing: no ground");
  }
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < samples; ++k) {
    if (!missing[k]) lowest = std::min(lowest, f.heights[k]);
  }
  if (f.cell_holes.empty()) f.cell_holes.assign(f.cellCount(), 0);
  for (int r = 0; r + 1 < f.rows; ++r) {
    for (int c = 0; c + 1 < f.cols; ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * f.cols + c;
      if (missing[k] | missing[k + 1] | missing[k + f.cols] | missing[k + f.cols + 1]) {
        f.cell_holes[static_cast<std::size_t>(r) * (f.cols - 1) + c] = 1;
      }
    }
  }
  for (std::size_t k = 0; k < samples; ++k) {
    if (missing[k]) f.heights[k] = lowest;
  }
  if (f.pieceCount() == 0) {
    throw InvalidInputError(std::string(kWhere) + ": every cell touches a missing sample (" + std::to_string(count) +
                            " of " + std::to_string(samples) + " samples): no ground");
  }
}

TriangleMesh surfaceMesh(const Heightfield& f) {
  TriangleMesh m;
  m.vertices.reserve(f.heights.size());
  for (int r = 0; r < f.rows; ++r) {
    for (int c = 0; c < f.cols; ++c) m.vertices.push_back(f.sample(r, c));
  }
  m.triangles.reserve(f.pieceCount());
  for (int r = 0; r + 1 < f.rows; ++r) {
    for (int c = 0; c + 1 < f.cols; ++c) {
      if (f.isHole(r, c)) continue;
      const std::int32_t p00 = r * f.cols + c, p01 = p00 + 1, p10 = p00 + f.cols, p11 = p10 + 1;
      m.triangles.push_back({p00, p01, p11});  // addHeightfield's two triangles, in its order
      m.triangles.push_back({p00, p11, p10});
    }
  }
  return m;
}

std::optional<double> surfaceHeight(const Heightfield& f, double x, double y) {
  const double u = (x - f.origin.x()) / f.spacing_x;  // column coordinate
  const double v = (y - f.origin.y()) / f.spacing_y;  // row coordinate
  if (!(u >= 0.0 && v >= 0.0 && u <= f.cols - 1 && v <= f.rows - 1)) return std::nullopt;
  const auto [r, c, s, t] = locate(f, u, v);
  if (f.isHole(r, c)) return std::nullopt;
  const double h00 = f.height(r, c), h01 = f.height(r, c + 1);
  const double h10 = f.height(r + 1, c), h11 = f.height(r + 1, c + 1);
  // Below the diagonal (s >= t) lies triangle (p00, p01, p11), above it
  // (p00, p11, p10); barycentric interpolation on the one that holds (s, t).
  const double h = s >= t ? h00 + s * (h01 - h00) + t * (h11 - h01) : h00 + t * (h10 - h00) + s * (h11 - h10);
  return f.origin.z() + h;
}

}  // namespace wtc

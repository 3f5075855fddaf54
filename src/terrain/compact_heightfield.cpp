// Heightfield prisms formed on demand (design note in compact_heightfield.hpp).
#include "compact_heightfield.hpp"
#include "field_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace wtc::detail {

namespace {
// A tile's test takes a cell's margin (kCellSlack, field_cells.hpp): far above rounding.
constexpr double kTileSlack = kCellSlack;

// std::floor(v) without the library call (a wheel's walk takes a few dozen
// a step): exact below 2^52 in size, where a double's truncation to an
// integer is; std::floor beyond and for a NaN.
double floorOf(double v) {
  if (!(std::abs(v) < 0x1p52)) return std::floor(v);
  const auto t = static_cast<double>(static_cast<std::int64_t>(v));  // toward zero
  return t > v ? t - 1.0 : t;
}

// A float at or below (down) or at or above (up) `v`.
float floatDown(double v) {
  float f = static_cast<float>(v);
  if (static_cast<double>(f) > v) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
float floatUp(double v) {
  float f = static_cast<float>(v);
  if (static_cast<double>(f) < v) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

}  // namespace

CompactHeightfield::CompactHeightfield(Heightfield field) : field_(std::move(field)) {
  validate(field_);
  if (!field_.hasHoles()) field_.cell_holes.clear();
  field_.heights.shrink_to_fit();  // the samples and nothing more
  field_.cell_materials.shrink_to_fit();
  field_.cell_holes.shrink_to_fit();
  base_z_ = field_.baseZ();
  makeTiles();
  if (field_.cell_holes.empty()) {
    piece_count_ = 2 * field_.cellCount();
    // The corners' coordinates as sample() computes them; origin.z + h is
    // monotonic in h, so the highest sample gives the highest top.
    const double highest = *std::max_element(field_.heights.begin(), field_.heights.end());
    const Eigen::Vector3d far = field_.origin + Eigen::Vector3d((field_.cols - 1) * field_.spacing_x,
                                                                (field_.rows - 1) * field_.spacing_y, highest);
    bounds_ = {Eigen::Vector3d(field_.origin.x(), field_.origin.y(), base_z_), far};
    return;
  }
  const std::size_t cells = field_.cellCount();
  ground_before_.reserve((cells + kBlockCells - 1) / kBlockCells);
  std::uint32_t ground = 0;
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (cell % kBlockCells == 0) ground_before_.push_back(ground);
    if (field_.cell_holes[cell] == 0) ++ground;
  }
  piece_count_ = 2 * static_cast<std::size_t>(ground);
  // The union of the ground cells' pieces: their corners, down to the base.
  bool first = true;
  for (int r = 0; r + 1 < field_.rows; ++r) {
    for (int c = 0; c + 1 < field_.cols; ++c) {
      if (field_.isHole(r, c)) continue;
      for (const Eigen::Vector3d& p :
           {field_.sample(r, c), field_.sample(r, c + 1), field_.sample(r + 1, c), field_.sample(r + 1, c + 1)}) {
        if (first) bounds_ = {p, p};
        first = false;
        bounds_.include(p);
      }
    }
  }
  bounds_.min.z() = base_z_;
}

void CompactHeightfield::makeTiles() {
  const int cells_x = field_.cols - 1, cells_y = field_.rows - 1;
  tile_cols_ = (cells_x + kTileCells - 1) / kTileCells;
  const int tile_rows = (cells_y + kTileCells - 1) / kTileCells;
  tile_top_.assign(static_cast<std::size_t>(tile_rows) * static_cast<std::size_t>(tile_cols_),
                   -std::numeric_limits<float>::infinity());
  for (int r = 0; r < field_.rows; ++r) {
    for (int c = 0; c < field_.cols; ++c) {
      const float up = floatUp(field_.height(r, c));
      // A sample on a tile's side belongs to the tiles on both sides of it.
      for (int tr = std::max(0, (r - 1) / kTileCells); tr <= std::min(tile_rows - 1, r / kTileCells); ++tr) {
        for (int tc = std::max(0, (c - 1) / kTileCells); tc <= std::min(tile_cols_ - 1, c / kTileCells); ++tc) {
          float& top = tile_top_[static_cast<std::size_t>(tr) * tile_cols_ + tc];
          top = std::max(top, up);
        }
      }
    }
  }
  tile_top_.shrink_to_fit();
  makeTileFalls();
}

void CompactHeightfield::makeTileFalls() {
  const Heightfield& f = field_;
  const int cells_x = f.cols - 1, cells_y = f.rows - 1;
  const int tile_rows = (cells_y + kTileCells - 1) / kTileCells;
  tile_fall_.assign(tile_top_.size(), {0.0f, std::numeric_limits<float>::infinity()});
  for (int tr = 0; tr < tile_rows; ++tr) {
    for (int tc = 0; tc < tile_cols_; ++tc) {
      const int r0 = tr * kTileCells, r1 = std::min(r0 + kTileCells, cells_y) - 1;  // the tile's cells
      const int c0 = tc * kTileCells, c1 = std::min(c0 + kTileCells, cells_x) - 1;
      // Each cell a ground cell away from the field's edge, its neighbours
      // ground too (field_surface.cpp's exposed()).
      if (r0 < 1 || c0 < 1 || r1 + 2 >= f.rows || c1 + 2 >= f.cols) continue;
      bool holes = false;
      for (int r = r0 - 1; r <= r1 + 1 && !holes; ++r) {
        for (int c = c0 - 1; c <= c1 + 1 && !holes; ++c) holes = f.isHole(r, c);
      }
      if (holes) continue;
      // The samples of the tile's cells and their neighbours.
      double low = f.height(r0 - 1, c0 - 1), along_x = 0.0, along_y = 0.0;
      for (int i = r0 - 1; i <= r1 + 2; ++i) {
        for (int j = c0 - 1; j <= c1 + 2; ++j) {
          const double h = f.height(i, j);
          low = std::min(low, h);
          if (j <= c1 + 1) along_x = std::max(along_x, std::abs(f.height(i, j + 1) - h));
          if (i <= r1 + 1) along_y = std::max(along_y, std::abs(f.height(i + 1, j) - h));
        }
      }
      // A triangle's gradient takes one difference along each axis
      // (p01 - p00 and p11 - p01, or p11 - p10 and p10 - p00).
      const double gx = along_x / f.spacing_x, gy = along_y / f.spacing_y;
      tile_fall_[static_cast<std::size_t>(tr) * tile_cols_ + tc] = {floatDown(low),
                                                                    floatUp(std::sqrt(gx * gx + gy * gy))};
    }
  }
  tile_fall_.shrink_to_fit();
}

bool CompactHeightfield::tileBeyond(int tile_row, int tile_col, const Eigen::Vector3d& point, double reach2) const {
  const TileSides t = tileSides(tile_row, tile_col);
  const double dx = std::max({0.0, t.x0 - point.x(), point.x() - t.x1});
  const double dy = std::max({0.0, t.y0 - point.y(), point.y() - t.y1});
  const double dz = std::max(
      0.0, point.z() - tileTop(tile_row, tile_col));  // the pieces reach down to the base, below the point's ball
  // Beyond with a margin far above the rounding of these sums: the cells'
  // own test decides whatever this one lets through.
  return dx * dx + dy * dy + dz * dz > reach2 * (1.0 + kTileSlack) + kTileSlack;
}

std::size_t CompactHeightfield::piecesBefore(std::size_t cell) const {
  if (ground_before_.empty()) return 2 * cell;
  const std::size_t block = cell / kBlockCells;
  std::size_t ground = ground_before_[block];
  for (std::size_t i = block * kBlockCells; i < cell; ++i) ground += field_.cell_holes[i] == 0 ? 1 : 0;
  return 2 * ground;
}

std::size_t CompactHeightfield::cellOf(std::size_t k) const {
  if (ground_before_.empty()) return k / 2;
  // The last block with at most k / 2 ground cells before it holds ground
  // cell k / 2.
  const auto wanted = static_cast<std::uint32_t>(k / 2);
  const auto after = std::upper_bound(ground_before_.begin(), ground_before_.end(), wanted);
  const auto block = static_cast<std::size_t>(after - ground_before_.begin()) - 1;
  std::uint32_t ground = ground_before_[block];
  for (std::size_t cell = block * kBlockCells;; ++cell) {
    if (field_.cell_holes[cell] != 0) continue;
    if (ground == wanted) return cell;
    ++ground;
  }
}

void CompactHeightfield::prismCorners(std::size_t k, std::array<Eigen::Vector3d, 3>& top,
                                      std::array<Eigen::Vector3d, 3>& bottom) const {
  const std::size_t cell = cellOf(k);
  const auto cells_per_row = static_cast<std::size_t>(field_.cols - 1);
  const int r = static_cast<int>(cell / cells_per_row);
  const int c = static_cast<int>(cell % cells_per_row);
  // addHeightfield: (p00, p01, p11) first, then (p00, p11, p10), each
  // corner's foot on the base.
  top[0] = field_.sample(r, c);
  top[1] = k % 2 == 0 ? field_.sample(r, c + 1) : field_.sample(r + 1, c + 1);
  top[2] = k % 2 == 0 ? field_.sample(r + 1, c + 1) : field_.sample(r + 1, c);
  for (int i = 0; i < 3; ++i) bottom[i] = Eigen::Vector3d(top[i].x(), top[i].y(), base_z_);
}

namespace {

// The cells [first, last] along one axis whose span [x(i), x(i + 1)], with
// x(i) = origin + i spacing computed as Heightfield::sample does, meets
// [lo, hi]: exactly the cells whose pieces' boxes meet the box along that
// axis (both triangles of a cell span the whole cell). The division only
// guesses; the comparisons on x(i) decide. Empty when first > last.
void cellSpan(double lo, double hi, double origin, double spacing, int cells, int& first, int& last) {
  const auto x = [&](int i) { return origin + i * spacing; };
  const double guess_lo = floorOf((lo - origin) / spacing);
  const double guess_hi = floorOf((hi - origin) / spacing);
  first = static_cast<int>(std::clamp(guess_lo, 0.0, static_cast<double>(cells - 1)));
  last = static_cast<int>(std::clamp(guess_hi, 0.0, static_cast<double>(cells - 1)));
  while (first > 0 && x(first) >= lo) --first;           // cell first - 1 may still reach lo
  while (first < cells && x(first + 1) < lo) ++first;    // ends before lo
  while (last + 1 < cells && x(last + 1) <= hi) ++last;  // starts within hi
  while (last >= 0 && x(last) > hi) --last;              // starts after hi
}

// Relative and absolute widening of a row's chord (m): far above rounding.
constexpr double kChordSlack = 1e-9;

}  // namespace

void CompactHeightfield::overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const {
  const Heightfield& f = field_;
  int c0, c1, r0, r1;
  if (!cellsUnder(box, c0, c1, r0, r1)) return;
  const auto cells_per_row = static_cast<std::size_t>(f.cols - 1);
  const double lowest = box.min.z();
  for (int r = r0; r <= r1; ++r) {
    const std::size_t row = static_cast<std::size_t>(r) * cells_per_row;
    for (int c = c0; c <= c1;) {
      // A tile whose highest sample lies below the box has no piece in it
      // (tileTop rounds up): a body above a fine field is passed by its
      // tiles, not its cells.
      const int tile_end = std::min(c1, (c / kTileCells + 1) * kTileCells - 1);
      if (lowest > tileTop(r / kTileCells, c / kTileCells)) {
        c = tile_end + 1;
        continue;
      }
      std::size_t k = piecesBefore(row + c);  // the next ground cell's first piece
      for (; c <= tile_end; ++c) {
        if (f.isHole(r, c)) continue;
        const auto id = first + static_cast<PieceId>(k);
        const std::array<double, 2> top = pieceTops(r, c);
        if (lowest <= top[0]) out.push_back(id);
        if (lowest <= top[1]) out.push_back(id + 1);
        k += 2;
      }
    }
  }
}

bool CompactHeightfield::cellsUnder(const Aabb& box, int& c0, int& c1, int& r0, int& r1) const {
  // Every piece reaches down to the base: a box below it meets none. A
  // box with a NaN meets nothing (every comparison fails), as in
  // Terrain::overlapping.
  if (!(box.max.z() >= base_z_) || box.min.hasNaN() || box.max.hasNaN()) return false;
  const Heightfield& f = field_;
  cellSpan(box.min.x(), box.max.x(), f.origin.x(), f.spacing_x, f.cols - 1, c0, c1);
  cellSpan(box.min.y(), box.max.y(), f.origin.y(), f.spacing_y, f.rows - 1, r0, r1);
  return true;
}

std::array<double, 2> CompactHeightfield::pieceTops(int r, int c) const {
  return {prismTop(field_, r, c, 0), prismTop(field_, r, c, 1)};
}

template <typename Run, typename Falls>
void CompactHeightfield::walkRuns(const Eigen::Vector3d& point, double reach, Run&& run, Falls&& falls) const {
  const Heightfield& f = field_;
  const Aabb cube{point.array() - reach, point.array() + reach};
  // overlapping()'s tests on the cube, then each box's distance.
  int c0, c1, r0, r1;
  if (!cellsUnder(cube, c0, c1, r0, r1)) return;
  const auto y = [&](int i) { return f.origin.y() + i * f.spacing_y; };  // as sample() computes them
  const double reach2 = reach * reach;
  const double slack2 = reach2 * (1.0 + kTileSlack) + kTileSlack;  // reach^2 with the tiles' margin
  // Every cell under the cube lies at least as far below the point as the
  // cube's highest tile: the rows and columns beyond the ball's cut at that
  // height meet nothing (a wheel above a fine field: most of the cube's),
  // and the cells' own tests decide the rest.
  {
    double top = -std::numeric_limits<double>::infinity();
    for (int tr = r0 / kTileCells; tr <= r1 / kTileCells; ++tr) {
      for (int tc = c0 / kTileCells; tc <= c1 / kTileCells; ++tc) top = std::max(top, tileTop(tr, tc));
    }
    const double dz = std::max(0.0, point.z() - top);
    const double rest = slack2 - dz * dz;
    if (rest < 0.0) return;
    const double half = std::sqrt(rest) * (1.0 + kChordSlack) + kChordSlack;
    int cut0, cut1;
    cellSpan(point.x() - half, point.x() + half, f.origin.x(), f.spacing_x, f.cols - 1, cut0, cut1);
    c0 = std::max(c0, cut0), c1 = std::min(c1, cut1);
    cellSpan(point.y() - half, point.y() + half, f.origin.y(), f.spacing_y, f.rows - 1, cut0, cut1);
    r0 = std::max(r0, cut0), r1 = std::min(r1, cut1);
    if (c0 > c1 || r0 > r1) return;
  }
  const auto cells_per_row = static_cast<std::size_t>(f.cols - 1);
  // Each tile is tested once for the rows it spans: the answers of a tile
  // row's first 64 tiles from c0 on are kept in two masks.
  const int first_tile = c0 / kTileCells;
  int tile_row = -1;
  std::uint64_t asked = 0, beyond = 0, asked_fall = 0, whole = 0;
  std::array<double, 64> fall{};  // falls() of the tile row's first 64 tiles, as asked_fall marks
  const auto tileSkipped = [&](int tc) {
    const int bit = tc - first_tile;
    if (bit >= 64) return tileBeyond(tile_row, tc, point, reach2);
    const std::uint64_t mask = std::uint64_t{1} << bit;
    if ((asked & mask) == 0) {
      asked |= mask;
      if (tileBeyond(tile_row, tc, point, reach2)) beyond |= mask;
    }
    return (beyond & mask) != 0;
  };
  // A tile's falls(), and whether the whole tile lies beyond it (its cells
  // all pass): asked once a tile.
  const auto passesWhole = [&](int tc, double far) {
    if (!(far < reach)) return false;
    const TileSides t = tileSides(tile_row, tc);
    const double dx = std::max({0.0, t.x0 - point.x(), point.x() - t.x1});
    const double dy_tile = std::max({0.0, t.y0 - point.y(), point.y() - t.y1});
    return dx * dx + dy_tile * dy_tile > far * far;
  };
  const auto tileFalls = [&](int tc, bool& passes) {
    const int bit = tc - first_tile;
    if (bit >= 64) {
      const double far = falls(tile_row, tc);
      passes = passesWhole(tc, far);
      return far;
    }
    const std::uint64_t mask = std::uint64_t{1} << bit;
    if ((asked_fall & mask) == 0) {
      asked_fall |= mask;
      const double far = falls(tile_row, tc);
      fall[static_cast<std::size_t>(bit)] = far;
      if (passesWhole(tc, far)) whole |= mask;
    }
    passes = (whole & mask) != 0;
    return fall[static_cast<std::size_t>(bit)];
  };
  // The cells along x that a chord of half-width `half` about the point may
  // meet, within [lo, hi]: a guess one cell wide of the division's, as each
  // cell's own test decides.
  // (A product with the spacing's inverse, not a division: the guess's
  // cell of margin holds its rounding.)
  const double per_x = 1.0 / f.spacing_x, u = (point.x() - f.origin.x()) * per_x;
  const auto span = [&](double half, int lo, int hi, int& from, int& to) {
    const double u0 = floorOf(u - half * per_x) - 1.0;
    const double u1 = floorOf(u + half * per_x) + 1.0;
    from = static_cast<int>(std::clamp(u0, static_cast<double>(lo), static_cast<double>(hi) + 1.0));
    to = static_cast<int>(std::clamp(u1, static_cast<double>(lo) - 1.0, static_cast<double>(hi)));
  };
  double row_dz = 0.0;  // the point's height above the current tile row's highest tile (m), or 0
  for (int r = r0; r <= r1; ++r) {
    const double dy = std::max({0.0, y(r) - point.y(), point.y() - y(r + 1)});
    if (dy * dy > reach2) continue;
    if (r / kTileCells != tile_row) {
      tile_row = r / kTileCells, asked = 0, beyond = 0, asked_fall = 0, whole = 0;
      // A tile row whose tiles on the disc all lie beyond the reach is
      // passed at once (on a fine field most of the disc's rows).
      const int last = std::min(r1, (tile_row + 1) * kTileCells - 1);
      const double dy_tiles = std::max({0.0, y(tile_row * kTileCells) - point.y(), point.y() - y(last + 1)});
      int from, to;
      span(std::sqrt(std::max(0.0, reach2 - dy_tiles * dy_tiles)) * (1.0 + kChordSlack) + kChordSlack, c0, c1, from,
           to);
      bool any = false;
      for (int tile = from / kTileCells; tile <= to / kTileCells && from <= to && !any; ++tile) {
        any = !tileSkipped(tile);
      }
      if (!any) {
        r = last;  // the loop's ++r moves on to the next tile row
        continue;
      }
      // Every cell of the tile row lies at least this far below the point:
      // a wheel above the ground meets it in a small patch, and the rows and
      // columns beyond that patch are passed here, not tile by tile below.
      double top = -std::numeric_limits<double>::infinity();
      for (int tile = c0 / kTileCells; tile <= c1 / kTileCells; ++tile) top = std::max(top, tileTop(tile_row, tile));
      row_dz = std::max(0.0, point.z() - top);
    }
    // The row's chord of the ball's cut at the tile row's highest tile, a
    // little wider than computed: it holds every tile's chord below.
    const double rest_row = slack2 - dy * dy - row_dz * row_dz;
    if (rest_row < 0.0) continue;
    int from, to;
    span(std::sqrt(rest_row) * (1.0 + kChordSlack) + kChordSlack, c0, c1, from, to);
    const std::size_t row = static_cast<std::size_t>(r) * cells_per_row;
    for (int c = from; c <= to;) {
      const int tile = c / kTileCells, tile_end = std::min(to, (tile + 1) * kTileCells - 1);
      const int next = tile_end + 1;
      if (tileSkipped(tile)) {
        c = next;
        continue;
      }
      // This row's chord narrowed by the tile's highest sample: its cells
      // lie at least that far below the point.
      const double dz = std::max(0.0, point.z() - tileTop(tile_row, tile));
      const double rest = slack2 - dy * dy - dz * dz;
      if (rest < 0.0) {
        c = next;
        continue;
      }
      // A tile whose cells all pass goes whole (the caller tests a cell
      // when it asks for it).
      bool passes = false;
      const double far = tileFalls(tile, passes);
      if (passes) {
        run(r, c, tile_end, piecesBefore(row + c), far, true);
        c = next;
        continue;
      }
      int lo, hi;
      span(std::sqrt(rest), c, tile_end, lo, hi);
      if (lo > hi) {
        c = next;
        continue;
      }
      run(r, lo, hi, piecesBefore(row + lo), far, false);
      c = next;
    }
  }
}

void CompactHeightfield::within(const Eigen::Vector3d& point, double reach, PieceId first,
                                std::vector<PieceId>& out) const {
  walkRuns(
      point, reach,
      [&](int r, int lo, int hi, std::size_t k, double, bool) {
        // The cell's box (both pieces' union) first: one test turns both
        // pieces away; their own boxes decide the rest.
        forEachCellNear(field_, r, lo, hi, first + static_cast<PieceId>(k), point, reach, [&](int c, PieceId id) {
          for (int t = 0; t < 2; ++t) {
            if (prismBoxWithin(field_, r, c, t, base_z_, point, reach)) out.push_back(id + t);
          }
        });
      },
      [](int, int) { return std::numeric_limits<double>::infinity(); });
}

void CompactHeightfield::surfaceWithin(const Eigen::Vector3d& point, double reach, PieceId first, int part,
                                       std::vector<SurfaceRun>& runs) const {
  walkRuns(
      point, reach,
      [&](int r, int lo, int hi, std::size_t k, double far, bool passed) {
        const PieceId id = first + static_cast<PieceId>(k);
        if (passed || !(far < std::numeric_limits<double>::infinity())) {  // passed whole, or searched whole
          runs.push_back({id, part, r, lo, hi, passed});
        } else {
          splitRun(point, far, r, lo, hi, id, part, runs);
        }
      },
      [&](int tile_row, int tile_col) {
        // fallingFrom(), or infinite when no cell of the tile can pass (its
        // farthest corner is within it): rough ground asks no more.
        const TileSides t = tileSides(tile_row, tile_col);
        const double fx = std::max(std::abs(point.x() - t.x0), std::abs(point.x() - t.x1));
        const double fy = std::max(std::abs(point.y() - t.y0), std::abs(point.y() - t.y1));
        const double far = fallingFrom(point, tile_row, tile_col, fx * fx + fy * fy);
        return far * far < fx * fx + fy * fy ? far : std::numeric_limits<double>::infinity();
      });
}

double CompactHeightfield::fallingFrom(const Eigen::Vector3d& point, int tile_row, int tile_col, double enough2) const {
  const TileFall& fall = tile_fall_[static_cast<std::size_t>(tile_row) * tile_cols_ + tile_col];
  const double slope = fall.slope;
  if (!(slope < std::numeric_limits<double>::infinity())) return slope;  // none passes (a hole or the edge near)
  // From the lowest sample alone, a lower bound: rough ground stops here.
  const double low = field_.origin.z() + fall.low;
  const double least = kFallMargin * std::abs(point.z() - low) * slope + kFallMarginM;
  if (least * least >= enough2) return least;
  // The ring's samples lie in the tiles around (a passing tile is never on
  // the field's edge: they all exist), each tile's top holding its sides'.
  double high = -std::numeric_limits<double>::infinity();
  for (int tr = tile_row - 1; tr <= tile_row + 1; ++tr) {
    for (int tc = tile_col - 1; tc <= tile_col + 1; ++tc) high = std::max(high, tileTop(tr, tc));
  }
  const double height = std::max(std::abs(point.z() - low), std::abs(point.z() - high));
  return kFallMargin * height * slope + kFallMarginM;
}

void CompactHeightfield::splitRun(const Eigen::Vector3d& point, double far, int r, int lo, int hi, PieceId id, int part,
                                  std::vector<SurfaceRun>& runs) const {
  const Heightfield& f = field_;
  // The cells farther than `far` (m) from the point's vertical pass
  // (fallingFrom()); those within it, a cell wider each side, are
  // searched: [a, b], none when a > b.
  const double dy =
      std::max({0.0, f.origin.y() + r * f.spacing_y - point.y(), point.y() - (f.origin.y() + (r + 1) * f.spacing_y)});
  int a = hi + 1, b = hi;
  if (dy <= far) {
    const double u = (point.x() - f.origin.x()) / f.spacing_x, half = std::sqrt(far * far - dy * dy) / f.spacing_x;
    a = static_cast<int>(std::clamp(floorOf(u - half) - 1.0, static_cast<double>(lo), static_cast<double>(hi) + 1.0));
    b = static_cast<int>(std::clamp(floorOf(u + half) + 1.0, static_cast<double>(lo) - 1.0, static_cast<double>(hi)));
  }
  if (a > b) {
    runs.push_back({id, part, r, lo, hi, true});
    return;
  }
  // No holes in the tile: a cell's pieces follow the previous cell's.
  if (a > lo) runs.push_back({id, part, r, lo, a - 1, true});
  runs.push_back({id + 2 * (a - lo), part, r, a, b});
  if (b < hi) runs.push_back({id + 2 * (b + 1 - lo), part, r, b + 1, hi, true});
}

std::size_t CompactHeightfield::memoryBytes() const {
  return sizeof(*this) + field_.heights.capacity() * sizeof(double) + tile_top_.capacity() * sizeof(float) +
         tile_fall_.capacity() * sizeof(TileFall) + field_.cell_materials.capacity() * sizeof(MaterialId) +
         field_.cell_holes.capacity() + ground_before_.capacity() * sizeof(std::uint32_t);
}

}  // namespace wtc::detail

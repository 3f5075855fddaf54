#pragma once
// A tile of a compact heightfield as Bullet's heightfield shape (internal
// to wtc::bullet): what TerrainObject builds a compact field from, and what
// FieldBodyAlgorithm recognises a body's contact with a field by.
#include <algorithm>
#include <cstddef>

#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>

#include "wtc/terrain/heightfield.hpp"

namespace wtc::bullet::detail {

// A tile of a compact field (kFieldTileCells cells a side, fewer at the far
// edges) as Bullet's heightfield shape over the field's own samples:
// Bullet asks for sample (x, y) of the tile, this reads sample (row0 + y,
// col0 + x) of the field. Columns along x (Bullet's width), rows along y, z
// up; flipQuadEdges splits each cell along p00-p11, the prisms' diagonal
// (wtc/terrain/heightfield.hpp). Its box reaches only its own samples'
// heights.
class FieldTile final : public btHeightfieldTerrainShape {
 public:
  FieldTile(const Heightfield& f, int row0, int col0, int rows, int cols, double lo, double hi)
      : btHeightfieldTerrainShape(cols, rows, f.heights.data(), lo, hi, /*upAxis=*/2, /*flipQuadEdges=*/true),
        field_(f),
        row0_(row0),
        col0_(col0) {}
  btScalar getRawHeightFieldValue(int x, int y) const override {
    return field_.heights[static_cast<std::size_t>(row0_ + y) * field_.cols + (col0_ + x)];
  }
  int row0() const { return row0_; }
  int col0() const { return col0_; }

  // btHeightfieldTerrainShape::processAllTriangles (Bullet 3.24) for this
  // tile's layout (z up, each cell split along p00-p11, no other
  // subdivision, Bullet's winding): the same triangles with the same
  // vertices, bit for bit, in the same order, to `callback`, the samples read
  // without a virtual call (the class is final; Bullet's getVertex makes
  // one a corner). `filter` may leave
  // cells out first, as long as it leaves out only cells neither of whose
  // triangles the callback would take:
  //   filter.narrowRow(x0, step, y0, y1, z0, z1, from, to) narrows the
  //   cells [from, to) of a row, cell i spanning [x0 + i step, x0 + (i + 1)
  //   step] along x, [y0, y1] along y and at most [z0, z1] along z (m, the
  //   tile's frame);
  //   filter.cellNear(corners) turns away a cell by its four corners.
  // Bullet's own walk answers any other layout.
  template <typename Filter>
  void walkTriangles(btTriangleCallback* callback, const btVector3& aabb_min, const btVector3& aabb_max,
                     const Filter& filter) const {
    if (m_upAxis != 2 || !m_flipQuadEdges || m_useDiamondSubdivision || m_useZigzagSubdivision ||
        m_flipTriangleWinding) {
      processAllTriangles(callback, aabb_min, aabb_max);
      return;
    }
    // The box in the grid's units, as Bullet scales, shifts, clamps and
    // rounds it, one cell wider each way.
    const btVector3 inverse(1.f / m_localScaling[0], 1.f / m_localScaling[1], 1.f / m_localScaling[2]);
    btVector3 low = aabb_min * inverse, high = aabb_max * inverse;
    low += m_localOrigin, high += m_localOrigin;
    low.setMax(m_localAabbMin), low.setMin(m_localAabbMax);
    high.setMax(m_localAabbMin), high.setMin(m_localAabbMax);
    const auto quantized = [](btScalar v) { return v < 0.0 ? static_cast<int>(v - 0.5) : static_cast<int>(v + 0.5); };
    const int start_x = std::max(0, quantized(low.getX()) - 1);
    const int end_x = std::min(m_heightStickWidth - 1, quantized(high.getX()) + 1);
    const int start_j = std::max(0, quantized(low.getY()) - 1);
    const int end_j = std::min(m_heightStickLength - 1, quantized(high.getY()) + 1);
    const Range up(aabb_min[2], aabb_max[2]);
    // getVertex(x, y), as Bullet computes it.
    const auto vertex = [&](int x, int y) {
      return btVector3((-m_width / btScalar(2.0)) + x, (-m_length / btScalar(2.0)) + y,
                       getRawHeightFieldValue(x, y) - m_localOrigin.getZ()) *
             m_localScaling;
    };
    const btScalar x0 = (-m_width / btScalar(2.0)) * m_localScaling[0], step = m_localScaling[0];
    const btScalar z0 = (m_minHeight - m_localOrigin.getZ()) * m_localScaling[2];
    const btScalar z1 = (m_maxHeight - m_localOrigin.getZ()) * m_localScaling[2];
    for (int j = start_j; j < end_j; ++j) {
      int from = start_x, to = end_x;
      filter.narrowRow(x0, step, ((-m_length / btScalar(2.0)) + j) * m_localScaling[1],
                       ((-m_length / btScalar(2.0)) + (j + 1)) * m_localScaling[1], z0, z1, from, to);
      for (int x = from; x < to; ++x) {
        btVector3 corners[4] = {vertex(x, j), vertex(x, j + 1), vertex(x + 1, j + 1), vertex(x + 1, j)};
        if (!filter.cellNear(corners)) continue;
        // (p00, p10, p11), then (p00, p11, p01) with the cell's four heights
        // as the second's range (Bullet's).
        btVector3 triangle[3] = {corners[0], corners[1], corners[2]};
        Range range(btMin(corners[0][2], btMin(corners[1][2], corners[2][2])),
                    btMax(corners[0][2], btMax(corners[1][2], corners[2][2])));
        if (range.overlaps(up)) callback->processTriangle(triangle, 2 * x, j);
        triangle[1] = corners[2];
        triangle[2] = corners[3];
        range.min = btMin(range.min, corners[3][2]);
        range.max = btMax(range.max, corners[3][2]);
        if (range.overlaps(up)) callback->processTriangle(triangle, 2 * x + 1, j);
      }
    }
  }

 private:
  const Heightfield& field_;
  int row0_, col0_;
};

}  // namespace wtc::bullet::detail

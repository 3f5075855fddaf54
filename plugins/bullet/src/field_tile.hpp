#pragma once
// A tile of a compact heightfield as Bullet's heightfield shape (internal
// to wtc::bullet): what TerrainObject builds a compact field from, and what
// FieldBodyAlgorithm recognises a body's contact with a field by.
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

 private:
  const Heightfield& field_;
  int row0_, col0_;
};

}  // namespace wtc::bullet::detail

#pragma once
// Builders for the simple grounds of the scenarios: slabs, inclines, ledges,
// stairs and boxes, added to a TerrainBuilder as convex pieces. No file I/O
// (the YAML terrain files of wtc::io call these).
//
// Frames. Each primitive is described in its own local frame L and placed in
// the world W by `pose_WL` (a rigid transform: rotation + translation, no
// scale). In L, +z is up, the walking surface of the primitive starts at
// z = 0 and obstacles face the -x side, so a vehicle driving along +x meets
// them. An incline plane is a slab whose pose is rotated about the y axis;
// a ledge along any direction is a ledge rotated about z.
//
// Validation. Every size is checked (finite, and > 0 or >= 0 as its comment
// says) and the pose must be finite and rigid; a violation throws
// InvalidInputError naming the function, the parameter and its value.
#include <Eigen/Geometry>
#include <cstdint>

#include "wtc/terrain/terrain.hpp"

namespace wtc {

/// A flat slab, optionally tessellated into tiles_x x tiles_y equal boxes
/// (tessellated ground is the test case of the contact seam rule).
/// In L: x in [-size_x/2, size_x/2], y in [-size_y/2, size_y/2],
/// z in [-thickness, 0] (the top face at z = 0).
struct SlabParams {
  double size_x = 10.0;    ///< Length along x (m, > 0).
  double size_y = 10.0;    ///< Width along y (m, > 0).
  double thickness = 0.5;  ///< Depth below the top face (m, > 0).
  int tiles_x = 1;         ///< Boxes along x (count, >= 1).
  int tiles_y = 1;         ///< Boxes along y (count, >= 1).
  Eigen::Isometry3d pose_WL = Eigen::Isometry3d::Identity();
};

/// A ramp (wedge): the foot line is the y axis of L at z = 0; the surface
/// rises toward +x at `angle` over the horizontal run `length`, then an
/// optional flat top of `top_length` follows. Everything reaches down to
/// z = -thickness. Pieces: the wedge, then the top block if top_length > 0.
struct InclineParams {
  double angle = 0.1745329251994330;  ///< Slope (rad, in (0, pi/2)); default 10 deg.
  double length = 10.0;               ///< Horizontal run of the ramp along x (m, > 0).
  double width = 4.0;                 ///< Along y, centred on y = 0 (m, > 0).
  double thickness = 0.5;             ///< Depth below the foot line z = 0 (m, > 0).
  double top_length = 0.0;            ///< Flat top after the ramp (m, >= 0; 0 = none).
  Eigen::Isometry3d pose_WL = Eigen::Isometry3d::Identity();
};

/// A ledge (step up): ground for x in [-approach_length, 0] with its top at
/// z = 0, then a block for x in [0, top_length] with its top at z = height.
/// The block's vertical face is the plane x = 0 of L. Both reach down to
/// z = -thickness. Pieces: the ground tiles (approach_tiles, along x), then
/// the block. The spec's ledge: height 0.65 m (LedgeParams{} defaults).
struct LedgeParams {
  double height = 0.65;          ///< Step height (m, >= 0).
  double approach_length = 4.0;  ///< Ground in front of the face (m, > 0).
  double top_length = 4.0;       ///< Block length behind the face (m, > 0).
  double width = 3.0;            ///< Along y, centred on y = 0 (m, > 0).
  double thickness = 0.5;        ///< Depth below the ground top z = 0 (m, > 0).
  int approach_tiles = 1;        ///< Boxes the ground is split into along x (>= 1).
  /// 0: boxes. > 0: the same ledge as a heightfield of square cells of
  /// this size (m), as a scan of it would be: samples every spacing from
  /// x = 0 (approach_length and top_length rounded to whole cells), those
  /// at x >= 0 on the top, so the face becomes a slope across the cell in
  /// front of x = 0. Needs a pose without rotation (heightfields are
  /// axis-aligned).
  double heightfield_spacing = 0.0;
  /// With heightfield_spacing: keep the samples (addCompactHeightfield: the
  /// same prisms, formed when a wheel needs them, and the engines' own
  /// heightfield shapes for the bodies) instead of every prism.
  bool compact_heightfield = false;
  Eigen::Isometry3d pose_WL = Eigen::Isometry3d::Identity();
};

/// Stairs going up toward +x: step i (0-based) occupies
/// x in [i run, (i+1) run] with its tread at z = (i+1) rise; the last step
/// is extended by top_length. Ground level is z = 0 in front of x = 0 (not
/// built: add a slab). Each step is one box reaching down to z = -thickness.
struct StairsParams {
  int steps = 5;            ///< Number of steps (count, >= 1).
  double rise = 0.17;       ///< Height of each step (m, > 0).
  double run = 0.29;        ///< Depth of each tread (m, > 0).
  double width = 1.2;       ///< Along y, centred on y = 0 (m, > 0).
  double thickness = 0.5;   ///< Depth below z = 0 (m, > 0).
  double top_length = 0.0;  ///< Extra length of the last tread (m, >= 0).
  Eigen::Isometry3d pose_WL = Eigen::Isometry3d::Identity();
};

/// A box of the given size centred on the origin of L (a rock, a kerb).
struct BoxParams {
  Eigen::Vector3d size{1.0, 1.0, 1.0};  ///< Edge lengths along x, y, z of L (m, > 0).
  Eigen::Isometry3d pose_WL = Eigen::Isometry3d::Identity();
};

PieceRange addSlab(TerrainBuilder& builder, const SlabParams& params, MaterialId material);
PieceRange addIncline(TerrainBuilder& builder, const InclineParams& params, MaterialId material);
PieceRange addLedge(TerrainBuilder& builder, const LedgeParams& params, MaterialId material);
PieceRange addStairs(TerrainBuilder& builder, const StairsParams& params, MaterialId material);
PieceRange addBox(TerrainBuilder& builder, const BoxParams& params, MaterialId material);

/// The box [min, max] of frame L placed by pose_WL: an axis-aligned box when
/// the pose has no rotation, a general hexahedron otherwise.
ConvexPolyhedron makeBox(const Eigen::Vector3d& min_L, const Eigen::Vector3d& max_L, const Eigen::Isometry3d& pose_WL);

}  // namespace wtc

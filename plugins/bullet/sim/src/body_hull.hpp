#pragma once
// A vehicle body's convex hull (a URDF mesh) as Bullet's collision shape,
// exact on its faces.
//
// Bullet's GJK wants a margin, and btConvexHullShape puts it outside the
// hull's points: with the default 0.04 m, a mesh chassis was 4 cm larger
// than its mesh all round (a wheel on a mesh plate rested 41 mm high, a mesh
// nose stopped 41 mm short of a ledge: issue 57 row 1). Here the hull is
// first eroded by the margin (every face plane moved inward by m) and the
// margin put back outside by Bullet: the shape's faces are the mesh's faces,
// its edges and corners rounded with radius m. Boxes and cylinders need
// nothing of this: Bullet keeps their margins inside.
#include <memory>
#include <vector>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <Eigen/Core>

namespace wtc::bullet {

/// Collision margin of a body's hull (m): Bullet's GJK on rounded corners
/// is better conditioned with a larger one; the hull's faces do not move
/// with it (they are eroded first). Smaller on a thin hull: at most
/// kBodyHullMarginShare of the smallest distance from the hull's centroid to
/// a face, so that the eroded hull keeps a volume.
inline constexpr double kBodyHullMarginM = 0.01;
inline constexpr double kBodyHullMarginShare = 0.25;

/// The hull of `points` (a body's, in its frame, m) as a Bullet shape whose
/// surface is the hull's faces, within rounding: the eroded hull with the
/// margin. Throws InvalidInputError for points that span no volume.
std::unique_ptr<btConvexHullShape> makeBodyHull(const std::vector<Eigen::Vector3d>& points);

}  // namespace wtc::bullet

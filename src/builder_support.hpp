#pragma once
// Shared by the terrain builders (primitives, heightfields, triangle meshes):
// parameter checks whose messages name the function, the parameter and its
// value, and the prism every surface triangle becomes. Internal to wtc.
#include <Eigen/Geometry>
#include <array>
#include <string>

#include "wtc/convex_polyhedron.hpp"

namespace wtc::detail {

/// Throws InvalidInputError "<where>: <name> = <value> must be finite and > 0 (<unit>)".
void requirePositive(double value, const char* where, const char* name, const char* unit);
/// As requirePositive, for >= 0.
void requireNonNegative(double value, const char* where, const char* name, const char* unit);
/// Throws InvalidInputError "<where>: <name> = <value> m is beyond the
/// largest length a description may give, 1e+06 m" if |value| > kMaxLengthM.
void requireAtMostMaxLength(double value, const char* where, const char* name);
/// A length (m): requirePositive, then requireAtMostMaxLength.
void requireLength(double value, const char* where, const char* name);
/// As requireLength, for >= 0.
void requireNonNegativeLength(double value, const char* where, const char* name);
/// Throws unless value >= min.
void requireAtLeast(long long value, long long min, const char* where, const char* name);
/// Throws unless the pose is finite and rigid (orthonormal rotation,
/// determinant +1 within 1e-9: a scale or a mirror would break the faces'
/// outward orientation), with its translation within kMaxLengthM of the
/// origin on every axis.
void requireRigid(const Eigen::Isometry3d& pose, const char* where, const char* name);

/// The prism with triangle `top` (counter-clockwise seen from outside, i.e.
/// from the side its normal (top1 - top0) x (top2 - top0) points to) and
/// `bottom`, bottom[i] lying under top[i]. Precondition: the six points
/// bound a convex solid whose side faces are planar (a right prism, or a
/// vertical prism cut by two planes). Built with the trusted
/// ConvexPolyhedron::fromMesh path, which still validates the result.
ConvexPolyhedron makePrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom);
/// makePrism's piece, bit for bit, for corners already checked (finite, the
/// top above the bottom): the prism's topology is copied from a reference
/// prism instead of matched anew. For prisms formed on demand.
ConvexPolyhedron makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top,
                                  const std::array<Eigen::Vector3d, 3>& bottom);
/// The same prism made into `into`, reusing its buffers (a prism's).
void makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom,
                      ConvexPolyhedron& into);

}  // namespace wtc::detail

#pragma once
// Parameter checks whose messages name the function, the parameter and its
// value, shared by every builder and reader of WTC (and open to an engine
// adapter's): each throws InvalidInputError.
#include <Eigen/Geometry>

namespace wtc {

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

}  // namespace wtc

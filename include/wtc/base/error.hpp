#pragma once
#include <stdexcept>
#include <string>

#include <Eigen/Core>

namespace wtc {

/// Bad user input: a non-finite coordinate, a degenerate or non-convex piece,
/// a malformed file. The message names the offending value and where it came
/// from, e.g. "wtc::queryPoint: query point p = (nan, 0, 1) is not finite".
class InvalidInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// "(x, y, z)" with full precision, for error messages.
std::string formatVector(const Eigen::Vector3d& v);

/// A number for an error message: 9 significant digits, never "0.000000"
/// for a small value (std::to_string's trap).
std::string formatNumber(double value);

/// True when all three coordinates are finite.
inline bool isFinite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace wtc

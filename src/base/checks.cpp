#include "wtc/base/checks.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"

namespace wtc {
namespace {

[[noreturn]] void failBound(double value, const char* where, const char* name, const char* unit, const char* bound) {
  throw InvalidInputError(std::string(where) + ": " + name + " = " + formatNumber(value) + " must be finite and " +
                          bound + " (" + unit + ")");
}

}  // namespace

void requireAtMostMaxLength(double value, const char* where, const char* name) {
  if (std::abs(value) > kMaxLengthM) {
    throw InvalidInputError(std::string(where) + ": " + name + " = " + formatNumber(value) +
                            " m is beyond the largest length a description may give, " + formatNumber(kMaxLengthM) +
                            " m (wtc::kMaxLengthM)");
  }
}

void requirePositive(double value, const char* where, const char* name, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0)) failBound(value, where, name, unit, "> 0");
}

void requireNonNegative(double value, const char* where, const char* name, const char* unit) {
  if (!(std::isfinite(value) && value >= 0.0)) failBound(value, where, name, unit, ">= 0");
}

void requireLength(double value, const char* where, const char* name) {
  requirePositive(value, where, name, "m");
  requireAtMostMaxLength(value, where, name);
}

void requireNonNegativeLength(double value, const char* where, const char* name) {
  requireNonNegative(value, where, name, "m");
  requireAtMostMaxLength(value, where, name);
}

void requireAtLeast(long long value, long long min, const char* where, const char* name) {
  if (value < min) {
    throw InvalidInputError(std::string(where) + ": " + name + " = " + std::to_string(value) +
                            " must be >= " + std::to_string(min));
  }
}

void requireRigid(const Eigen::Isometry3d& pose, const char* where, const char* name) {
  // Tolerance on R^T R - I and det R - 1 (dimensionless): loose enough for a
  // rotation typed with 10 digits or composed from a few others, tight
  // enough that no visible scale or shear passes.
  constexpr double kRigidTolerance = 1e-9;
  const Eigen::Matrix3d r = pose.linear();
  const bool finite = pose.matrix().allFinite();
  if (!finite || (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > kRigidTolerance ||
      std::abs(r.determinant() - 1.0) > kRigidTolerance) {
    std::ostringstream out;
    out.precision(17);
    out << where << ": " << name << " must be a finite rigid transform (rotation + translation), got\n"
        << pose.matrix();
    throw InvalidInputError(out.str());
  }
  if (!(pose.translation().cwiseAbs().maxCoeff() <= kMaxLengthM)) {
    throw InvalidInputError(std::string(where) + ": " + name + " places it at " + formatVector(pose.translation()) +
                            " m, beyond " + formatNumber(kMaxLengthM) + " m of the origin (wtc::kMaxLengthM)");
  }
}

}  // namespace wtc

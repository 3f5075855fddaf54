#include "builder_support.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "wtc/constants.hpp"
#include "wtc/error.hpp"

namespace wtc::detail {
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

namespace {

// Vertices 0-2 the top triangle, 3-5 the bottom one. The top keeps its
// winding, the bottom is reversed (seen from below), and the side quad on
// edge i -> j runs i, i', j', j: with the top normal up, (i' - i) x (j' - i)
// points away from the third vertex, i.e. outward.
const std::vector<std::vector<int>> kPrismFaces = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};

// One scratch list per thread: a heightfield adds 10^6 prisms, and this
// keeps the builder to the allocations of the piece itself.
const std::vector<Eigen::Vector3d>& prismVertices(const std::array<Eigen::Vector3d, 3>& top,
                                                  const std::array<Eigen::Vector3d, 3>& bottom) {
  thread_local std::vector<Eigen::Vector3d> vertices(6);
  for (int i = 0; i < 3; ++i) {
    vertices[i] = top[i];
    vertices[i + 3] = bottom[i];
  }
  return vertices;
}

}  // namespace

ConvexPolyhedron makePrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom) {
  return ConvexPolyhedron::fromMesh(prismVertices(top, bottom), kPrismFaces);
}

namespace {

// The prism whose topology every checked prism copies.
const ConvexPolyhedron& referencePrism() {
  static const ConvexPolyhedron kReference =
      makePrism({Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0, 1, 1)},
                {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)});
  return kReference;
}

}  // namespace

// referencePrism() is called before prismVertices: its first call builds
// the reference through the same per-thread vertex list.
ConvexPolyhedron makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top,
                                  const std::array<Eigen::Vector3d, 3>& bottom) {
  const ConvexPolyhedron& like = referencePrism();
  return sameTopologyAs(like, prismVertices(top, bottom), kPrismFaces);
}

void makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom,
                      ConvexPolyhedron& into) {
  const ConvexPolyhedron& like = referencePrism();
  sameTopologyInto(into, like, prismVertices(top, bottom), kPrismFaces);
}

}  // namespace wtc::detail

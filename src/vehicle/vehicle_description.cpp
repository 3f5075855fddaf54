#include "wtc/vehicle/vehicle_description.hpp"

#include <cmath>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc::vehicle {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what, const std::string& problem) {
  throw InvalidInputError(where + ": " + what + ": " + problem);
}

void requirePositive(double value, const std::string& where, const std::string& what) {
  if (!std::isfinite(value) || value <= 0.0) fail(where, what, formatNumber(value) + " must be finite and > 0");
}

// A size (m): > 0 and at most kMaxLengthM (a value like 1e300 would
// otherwise surface as an infinite inertia).
void requireLength(double value, const std::string& where, const std::string& what) {
  requirePositive(value, where, what);
  if (value > kMaxLengthM) {
    fail(where, what,
         formatNumber(value) + " m is beyond the largest length a description may give, " + formatNumber(kMaxLengthM) +
             " m (wtc::kMaxLengthM)");
  }
}

void requireNonNegative(const Eigen::Vector3d& v, const std::string& where, const std::string& what) {
  if (!v.allFinite() || (v.array() < 0.0).any()) fail(where, what, formatVector(v) + " must be finite and >= 0");
}

void normaliseAxis(Eigen::Vector3d& axis, const std::string& where, const std::string& what) {
  const double norm = axis.norm();
  if (!axis.allFinite() || norm < tolerance::kMinAxleNorm) {
    fail(where, what, formatVector(axis) + " is not a direction (non-finite or zero)");
  }
  axis /= norm;
}

const char* jointName(JointType type) {
  switch (type) {
    case JointType::kRevolute:
      return "revolute";
    case JointType::kPrismatic:
      return "prismatic";
    case JointType::kBall:
      return "ball";
    case JointType::kFixed:
      return "fixed";
  }
  return "?";
}

void validateShape(const Shape& s, const std::string& where, const std::string& what) {
  if (s.kind == Shape::Kind::kBox) {
    for (int k = 0; k < 3; ++k) requireLength(s.box_size[k], where, what + " box[" + std::to_string(k) + "]");
  }
  if (s.kind == Shape::Kind::kCylinder || s.kind == Shape::Kind::kSphere)
    requireLength(s.radius, where, what + " radius");
  if (s.kind == Shape::Kind::kCylinder) {
    requireLength(s.length, where, what + " length");
    if (s.cylinder_axis < 0 || s.cylinder_axis > 2) fail(where, what + " axis", std::to_string(s.cylinder_axis));
  }
  if (s.kind == Shape::Kind::kHull) {
    // Fewer than 4 points span no volume: no hull.
    if (s.hull_vertices.size() < 4) fail(where, what, "a hull needs at least 4 vertices");
    for (const Eigen::Vector3d& p : s.hull_vertices) {
      if (!p.allFinite()) fail(where, what + " hull vertex", formatVector(p) + " is not finite");
    }
  }
}

void validateJoint(Joint& joint, const std::string& where) {
  if (!joint.anchor.allFinite()) fail(where, "joint anchor", formatVector(joint.anchor) + " is not finite");
  const bool has_coordinate = joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic;
  if (has_coordinate) normaliseAxis(joint.axis, where, "joint axis");
  if (joint.limits) {
    if (!has_coordinate) fail(where, "joint limits", std::string("a ") + jointName(joint.type) + " joint has none");
    const JointLimits& l = *joint.limits;
    if (!std::isfinite(l.lower) || !std::isfinite(l.upper) || l.lower > l.upper) {
      // Built by appending: GCC 12 warns of an overlapping memcpy in
      // operator+(const char*, std::string&&), a false positive (its bug 105651).
      std::string range = "[";
      range.append(formatNumber(l.lower)).append(", ").append(formatNumber(l.upper));
      fail(where, "joint limits", range + "] must be finite with lower <= upper");
    }
  }
  if (joint.actuator) {
    if (!has_coordinate) fail(where, "actuator", std::string("a ") + jointName(joint.type) + " joint cannot be driven");
    requirePositive(joint.actuator->max_effort, where, "actuator max_effort");
    requirePositive(joint.actuator->max_speed, where, "actuator max_speed");
    requirePositive(joint.actuator->position_gain, where, "actuator position_gain");
  }
  if (joint.mimic) {
    if (!has_coordinate) fail(where, "mimic", std::string("a ") + jointName(joint.type) + " joint cannot mimic");
    if (!std::isfinite(joint.mimic->multiplier) || !std::isfinite(joint.mimic->offset)) {
      fail(where, "mimic",
           "multiplier " + formatNumber(joint.mimic->multiplier) + " and offset " + formatNumber(joint.mimic->offset) +
               " must be finite");
    }
  }
}

}  // namespace

void validate(Body& body, int index, const std::string& where) {
  requirePositive(body.mass, where, "mass");
  // The sizes before the inertia: the inertia of a shape or wheel with a
  // size of 0 or 1e300 is 0 or inf, and the size is what the user typed.
  if (!body.pose.matrix().allFinite()) fail(where, "pose", "is not finite");
  if (!(body.pose.translation().cwiseAbs().maxCoeff() <= kMaxLengthM)) {
    fail(where, "translation",
         formatVector(body.pose.translation()) + " m is beyond " + formatNumber(kMaxLengthM) +
             " m of the origin (wtc::kMaxLengthM)");
  }
  if (body.wheel) {
    validate(body.wheel->geometry, where.c_str());
    validate(body.wheel->tyre, where.c_str());
    normaliseAxis(body.wheel->axle, where, "wheel axle");
  }

  validateShape(body.shape, where, "shape");
  for (std::size_t k = 0; k < body.compound.size(); ++k) {
    const ShapePart& part = body.compound[k];
    const std::string what = "compound[" + std::to_string(k) + "]";
    if (part.shape.kind == Shape::Kind::kNone) fail(where, what, "a compound's part needs a shape");
    validateShape(part.shape, where, what);
    if (!part.pose_BS.matrix().allFinite()) fail(where, what + " pose", "is not finite");
  }

  const Eigen::Vector3d& i = body.inertia;
  if (!i.allFinite() || (i.array() <= 0.0).any()) fail(where, "inertia", formatVector(i) + " must be finite and > 0");
  // Principal moments of a real body obey the triangle inequality.
  const double slack = 1e-9 * i.sum();
  if (i.x() + i.y() < i.z() - slack || i.y() + i.z() < i.x() - slack || i.z() + i.x() < i.y() - slack) {
    fail(where, "inertia", formatVector(i) + " violates the triangle inequality (no rigid body has it)");
  }
  if (body.parent >= index) {
    fail(where, "parent", "index " + std::to_string(body.parent) + " must name a body listed before it");
  }
  if (body.parent >= 0) validateJoint(body.joint, where);
}

Eigen::Vector3d solidInertia(const Shape& shape, double mass) {
  switch (shape.kind) {
    case Shape::Kind::kBox: {
      const Eigen::Vector3d sq = shape.box_size.cwiseAbs2();
      return mass / 12.0 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y());
    }
    case Shape::Kind::kCylinder: {
      // Axial m r^2 / 2, transverse m (3 r^2 + l^2) / 12.
      const double r2 = shape.radius * shape.radius;
      Eigen::Vector3d moments = Eigen::Vector3d::Constant(mass * (3.0 * r2 + shape.length * shape.length) / 12.0);
      moments[shape.cylinder_axis] = 0.5 * mass * r2;
      return moments;
    }
    case Shape::Kind::kSphere:
      return Eigen::Vector3d::Constant(0.4 * mass * shape.radius * shape.radius);
    case Shape::Kind::kNone:
    case Shape::Kind::kHull:
      break;
  }
  throw InvalidInputError("wtc::vehicle::solidInertia: a body without a shape needs its inertia given");
}

int VehicleDescription::find(const std::string& body_name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == body_name) return static_cast<int>(i);
  }
  return -1;
}

double VehicleDescription::totalMass() const {
  double sum = 0.0;
  for (const Body& b : bodies) sum += b.mass;
  return sum;
}

std::vector<int> VehicleDescription::wheels() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].wheel) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<int> VehicleDescription::actuated() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].parent >= 0 && bodies[i].joint.actuator) out.push_back(static_cast<int>(i));
  }
  return out;
}

void validate(VehicleDescription& vehicle, const std::string& where) {
  if (vehicle.bodies.empty()) throw InvalidInputError(where + ": a vehicle needs at least one body");
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i) {
    Body& body = vehicle.bodies[i];
    const std::string here = where + ": body '" + body.name + "'";
    if (body.name.empty()) throw InvalidInputError(where + ": body " + std::to_string(i) + " has no name");
    if (vehicle.find(body.name) != static_cast<int>(i)) fail(here, "name", "is used twice");
    validate(body, static_cast<int>(i), here);
    if (body.parent >= 0 && body.joint.mimic) {
      const int m = body.joint.mimic->master;
      const int n = static_cast<int>(vehicle.bodies.size());
      if (m < 0 || m >= n || m == static_cast<int>(i) || vehicle.bodies[m].parent < 0 ||
          (vehicle.bodies[m].joint.type != JointType::kRevolute &&
           vehicle.bodies[m].joint.type != JointType::kPrismatic)) {
        fail(here, "mimic", "its master must be another body's revolute or prismatic joint");
      }
    }
  }
  if (vehicle.hitch) {
    Hitch& h = *vehicle.hitch;
    const int n = static_cast<int>(vehicle.bodies.size());
    if (h.body_a < 0 || h.body_a >= n || h.body_b < 0 || h.body_b >= n || h.body_a == h.body_b) {
      throw InvalidInputError(where + ": hitch: body_a and body_b must name two different bodies");
    }
    if (!h.point_a.allFinite() || !h.point_b.allFinite()) {
      throw InvalidInputError(where + ": hitch: points " + formatVector(h.point_a) + " and " + formatVector(h.point_b) +
                              " must be finite");
    }
    requireNonNegative(h.stiffness, where + ": hitch", "stiffness");
    requireNonNegative(h.damping, where + ": hitch", "damping");
  }
}

}  // namespace wtc::vehicle

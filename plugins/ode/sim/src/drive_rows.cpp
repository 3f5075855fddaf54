// The drives' rows taken as equations first (drive_rows.hpp has the design
// note).
#include "drive_rows.hpp"

#include <cmath>

#include "wtc/base/tolerances.hpp"

namespace wtc::ode {
namespace {

bool isAngular(dJointID motor) { return dJointGetType(motor) == dJointTypeAMotor; }

double cap(dJointID motor) {
  return isAngular(motor) ? dJointGetAMotorParam(motor, dParamFMax) : dJointGetLMotorParam(motor, dParamFMax);
}

void setCap(dJointID motor, double fmax) {
  if (isAngular(motor)) {
    dJointSetAMotorParam(motor, dParamFMax, fmax);
  } else {
    dJointSetLMotorParam(motor, dParamFMax, fmax);
  }
}

}  // namespace

double motorForce(dJointID motor, const dJointFeedback& feedback) {
  dVector3 a;
  if (isAngular(motor)) {
    dJointGetAMotorAxis(motor, 0, a);
    return feedback.t1[0] * a[0] + feedback.t1[1] * a[1] + feedback.t1[2] * a[2];
  }
  dJointGetLMotorAxis(motor, 0, a);
  return feedback.f1[0] * a[0] + feedback.f1[1] * a[1] + feedback.f1[2] * a[2];
}

void DriveRows::add(dJointID motor, const dJointFeedback* feedback) {
  drives_.push_back({.motor = motor, .feedback = feedback});
}

bool DriveRows::release() {
  bool any = false;
  for (Drive& d : drives_) {
    d.cap = cap(d.motor);
    // Off (fmax 0: ODE adds no row) or at its cap last step: as it is.
    d.released = d.cap > 0.0 && std::isfinite(d.cap) && !d.capped;
    if (!d.released) continue;
    setCap(d.motor, dInfinity);
    any = true;
  }
  return any;
}

bool DriveRows::restore() {
  bool within = true;
  for (Drive& d : drives_) {
    if (!d.released) continue;
    setCap(d.motor, d.cap);
    d.released = false;
    if (std::abs(motorForce(d.motor, *d.feedback)) > d.cap) {
      d.capped = true;
      within = false;
    }
  }
  return within;
}

void DriveRows::noteCaps() {
  for (Drive& d : drives_) {
    const double fmax = cap(d.motor);
    d.capped =
        fmax > 0.0 && std::abs(motorForce(d.motor, *d.feedback)) >= fmax * (1.0 - tolerance::kDriveAtCapRelative);
  }
}

}  // namespace wtc::ode

// The drives' rows taken as equations first (drive_rows.hpp has the design
// note).
#include "drive_rows.hpp"

#include <cmath>

#include "wtc/base/tolerances.hpp"

namespace wtc::ode {
namespace {

// A drive at its cap stays capped this long after its last step there (s):
// a drive working at its cap (a fold lifting a section onto the ledge)
// comes off it for a few milliseconds at a time and back, and each return
// of a released drive over its cap is a step solved twice. Capped, a drive
// costs its pivot, as before (what the hold saves: docs/performance.md).
constexpr double kCappedHoldS = 0.02;

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
    // Off (fmax 0: ODE adds no row) or at its cap lately: as it is.
    d.released = d.cap > 0.0 && std::isfinite(d.cap) && d.capped_for <= 0.0;
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
      d.capped_for = kCappedHoldS;
      within = false;
    }
  }
  return within;
}

void DriveRows::noteCaps(double h) {
  for (Drive& d : drives_) {
    const double fmax = cap(d.motor);
    const bool at_cap =
        fmax > 0.0 && std::abs(motorForce(d.motor, *d.feedback)) >= fmax * (1.0 - tolerance::kDriveAtCapRelative);
    d.capped_for = at_cap ? kCappedHoldS : d.capped_for - h;
  }
}

}  // namespace wtc::ode

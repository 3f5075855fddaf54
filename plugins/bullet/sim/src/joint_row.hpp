#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

namespace wtc::bullet {

class WheelDriveResponses;

// Appends the solver row of one joint coordinate of `body` alone, as
// btMultiBodyConstraint::fillMultiBodyConstraint makes it for Bullet's
// joint motors and limits but without their body B (the same multibody
// again, with a zero Jacobian, which costs Bullet a second articulated-body
// solve per row and B terms in every sweep):
//   Jacobian J = sign e_dof, response M^-1 J^T (one articulated-body solve),
//   effective mass 1 / (J M^-1 J^T), zero when singular (Bullet's),
//   the reaction recorded on the link along the joint's axis.
// The row starts from zero impulse and solves for what is not yet
// applied: with `applied` (N s) already given as a joint force (a warm
// start), its bounds are [lower - applied, upper - applied], so that the
// total stays in [lower, upper]. The caller sets the right-hand side.
// `sign` is +1 or -1; `origin` and `origin_row` name the constraint and row
// the solver writes the impulse back to. Returns the joint rate along the
// row, J qdot, in `rate`. With `shared`, the response comes from there
// (wheel_drive_responses.hpp: a wheel's drive, one solve for two wheels).
btMultiBodySolverConstraint& appendJointRow(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                            btMultiBody& body, int link, double sign, double lower, double upper,
                                            double applied, btMultiBodyConstraint& origin, int origin_row, double& rate,
                                            WheelDriveResponses* shared = nullptr);

// The island the solver files a constraint on `body` under: its base
// collider's, else its first link collider's (Bullet's joint constraints'
// rule), -1 without colliders.
int islandOf(const btMultiBody& body);

}  // namespace wtc::bullet

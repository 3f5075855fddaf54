#pragma once
// One WTC contact as an ODE contact joint's description (constraint mode;
// internal to wtc::ode). The physics is the core's (engine_contact.hpp):
// this file only says where each number goes in a dContact.
#include <ode/ode.h>

#include "wtc/adapter/solver_contact.hpp"

namespace wtc::ode {

/// The dContact of `contact` for a world step of `step_seconds`, between
/// `wheel` (body 1: the normal points into it) and `ground`. ODE subtracts
/// its contact surface layer from every depth; `surface_layer` (m) is added
/// back so that the spring sees the tyre's deflection Z.
dContact toOdeContact(const SolverContact& contact, double step_seconds, double surface_layer, dGeomID wheel,
                      dGeomID ground);

/// The normal velocity (m/s) ODE's solver asks of the contact to remove its
/// depth, ERP Z / h: the quantity dWorldSetContactMaxCorrectingVel caps.
double correctingVelocity(const SolverContact& contact, double step_seconds);

}  // namespace wtc::ode

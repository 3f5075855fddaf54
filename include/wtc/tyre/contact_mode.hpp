#pragma once
// How a tyre's contacts act on the engine (docs/tyre-model.md):
//
// Force mode: the tyre model's forces (R at P, M_r about the axle) are
// applied to the wheel body at every internal step. Exact laws; the normal
// spring is explicit, stable only for h sqrt(c/m) < 2 (sqrt(1+zeta^2) - zeta).
//
// Constraint mode: each contact becomes a row of the engine's solver whose
// softness is the tyre's spring-damper, solved implicitly by the engine,
// with rigid Coulomb friction at the coefficient the slip law gives this
// step; rolling resistance stays an explicit moment (the adapters' kit,
// src/adapter/solver_contact.hpp, has the mapping).
//
// Implicit mode: the tyre model itself, solved by the engine. The normal
// row as in constraint mode; the tread's tangential spring-damper as
// compliant friction rows fed by the tread state (implicit Euler of the
// tread over the step), bounded by the slip law's mu R_z. It tends to
// force mode's answer as the step shrinks and stays stable at any step.
#include <string_view>

namespace wtc {

enum class ContactMode {
  kForce,       ///< The tyre model's forces, applied explicitly.
  kConstraint,  ///< Engine contacts with the tyre's stiffness, damping and rigid friction.
  kImplicit,    ///< Engine contacts with the tyre's stiffness, damping and compliant tread.
};

/// "force", "constraint" or "implicit": the name scenes, summaries and
/// reports use.
constexpr std::string_view contactModeName(ContactMode mode) {
  switch (mode) {
    case ContactMode::kForce:
      return "force";
    case ContactMode::kConstraint:
      return "constraint";
    case ContactMode::kImplicit:
      return "implicit";
  }
  return "?";
}

/// Whether the engine's solver takes the contacts as rows (every mode but
/// force mode): the plugins then hand it engine contacts, not forces.
constexpr bool engineSolvesContacts(ContactMode mode) { return mode != ContactMode::kForce; }

}  // namespace wtc

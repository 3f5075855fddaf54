#pragma once
// How a tyre's contacts act on the engine (docs/tyre-model.md):
//
// Force mode: the tyre model's forces (R at P, M_r about the axle) are
// applied to the wheel body at every internal step. Exact laws; the normal
// spring is explicit, stable only for h sqrt(c/m) < 2 (sqrt(1+zeta^2) - zeta).
//
// Constraint mode: each contact becomes a row of the engine's solver whose
// softness is the tyre's spring-damper, solved implicitly by the engine,
// with Coulomb friction at the coefficient the slip law gives this step;
// rolling resistance stays an explicit moment (the adapters' kit,
// src/adapter/solver_contact.hpp, has the mapping).
#include <string_view>

namespace wtc {

enum class ContactMode {
  kForce,       ///< The tyre model's forces, applied explicitly.
  kConstraint,  ///< Engine contacts with the tyre's stiffness, damping and friction.
};

/// "force" or "constraint": the name scenes, summaries and reports use.
constexpr std::string_view contactModeName(ContactMode mode) {
  return mode == ContactMode::kForce ? "force" : "constraint";
}

}  // namespace wtc

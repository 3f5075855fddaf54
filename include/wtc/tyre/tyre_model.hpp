#pragma once
// The tyre model (wheel-terrain model, sections 3-6), assembled from the
// effects a scene asks for. Design note:
//
// Assembly. TyreModel's constructor picks, from a table of kernels compiled
// for every combination of the force effects (damping x traction law x
// rolling resistance), the one for its EffectSet; contact-level effects
// (multiple contacts, tread truncation) become the contact options. A step
// then runs one indirect call per wheel and no per-contact test of any
// effect: what is off is not evaluated. Nothing is allocated for an effect
// that is off (the tread memory stays empty without traction).
//
// One wheel step reads top to bottom (TyreModel::step):
//   contacts (WheelContactFinder: index -> queries -> seam rule -> tread)
//   -> per contact: velocities, normal force, traction, rolling resistance
//   -> totals: wrench about O, axial/bearing split, stability report.
// Applying the result to bodies is the engine adapter's job.
//
// Standstill (spec section 6). The slip law acts through a tread deflection
// u per contact (a brush tyre's bristles), with relaxation length
// sigma = mu'(0) R_z / k_t:
//   du/dt = V_s - (max(V_t, eps) / sigma) u,   |u| <= sigma s_sat,
//   F = -R_z mu(|x| / sigma) x / |x|,   x = u + tau V_s,
// integrated exactly over the step for constant V_s. In steady state
// u = sigma V_s / max(V_t, eps), so |x| / sigma is the spec's slip ratio and
// F is the spec's force exactly (once tau has faded); at V_t = 0 it is a
// spring of stiffness k_t that holds a parked vehicle with a creep of
// s_eq eps (0.4 mm in 10 s on 15 deg). The stiffness is capped to the step
// and the wheel's mass, k_t <= (kappa / h)^2 m, and tau =
// 2 zeta_t sqrt(m / k_t) (1 - V_t / v_fade)+ damps it critically at rest, so
// the force's gain in V_s stays below (kappa^2 + 2 zeta_t kappa) m / h: an
// explicit engine step neither explodes nor oscillates. Coulomb friction
// uses the same spring, without relaxation, capped at mu_max R_z.
// Rolling resistance ramps sign(omega_rel . a) over a width that keeps its
// gain below kappa I / h. docs/tyre-model.md has the derivations and tests.
#include <cstdint>
#include <span>
#include <vector>

#include "wtc/contact/wheel_contact.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/contact_mode.hpp"
#include "wtc/tyre/effects.hpp"
#include "wtc/tyre/tyre_parameters.hpp"
#include "wtc/tyre/wheel_forces.hpp"

namespace wtc {

class GroundMemory;

/// One contact's tread deflection, carried from step to step.
struct TreadState {
  Eigen::Vector3d e{Eigen::Vector3d::UnitZ()};       ///< The contact's direction toward the ground.
  Eigen::Vector3d u{Eigen::Vector3d::Zero()};        ///< The slip law's tread state (its slip memory), normal to e (m).
  Eigen::Vector3d elastic{Eigen::Vector3d::Zero()};  ///< The tread's elastic deflection, normal to e (m).
};

/// Per-wheel state: contact search caches, tread deflections, the last
/// result and counters. One per wheel; reused every step, it allocates
/// nothing once warm.
class WheelState {
 public:
  /// Reserves the memory a step needs (see wtc/scratch_capacity.hpp).
  WheelState();

  /// The last step's result (no contacts before the first step).
  const WheelForces& result() const { return result_; }
  /// The tread deflections after the last step (empty without traction).
  std::span<const TreadState> tread() const { return tread_; }
  /// Steps run, and steps whose tyre spring exceeded its explicit stability
  /// limit (see WheelForces::normal_stability for the numbers).
  std::uint64_t steps() const { return steps_; }
  std::uint64_t unstableSteps() const { return unstable_steps_; }
  /// Steps an engine adapter skipped because the wheel's pose or motion was
  /// not finite (TyreModel::stepInEngine), and whether the last one was.
  std::uint64_t nonFiniteSteps() const { return non_finite_steps_; }
  bool lastStepSkipped() const { return last_skipped_; }
  /// True when the last step was the wheel's first beyond its explicit
  /// stability limit (adapters tell their listener once per wheel).
  bool firstUnstableStep() const { return first_unstable_; }
  /// Steps in which a contact on soft soil reached the axle (sinkage >= r):
  /// the soil could not carry the wheel (the soft_soil effect).
  std::uint64_t sunkSteps() const { return sunk_steps_; }
  /// The last step's contacts on the wheel's cut caps (no tyre force; see
  /// WheelContactFinder::capContacts).
  std::span<const WheelContact> capContacts() const { return finder_.capContacts(); }
  /// Forgets the tread deflections (a wheel teleported by the user).
  void resetTread() { tread_.clear(); }
  /// The ground's memory this wheel reads and presses on soft soil (not
  /// owned; it must outlive its use here), or null: the soil forgets, each
  /// step loading a fresh surface. The engine plugins set their world's.
  void setGroundMemory(GroundMemory* memory) { ground_memory_ = memory; }
  GroundMemory* groundMemory() const { return ground_memory_; }

 private:
  friend class TyreModel;
  WheelContactFinder finder_;
  std::vector<ContactForce> forces_;
  std::vector<TreadState> tread_, next_tread_;
  WheelForces result_;
  GroundMemory* ground_memory_ = nullptr;
  std::uint64_t steps_ = 0, unstable_steps_ = 0, non_finite_steps_ = 0, sunk_steps_ = 0;
  bool last_skipped_ = false, first_unstable_ = false;
};

class TyreModel {
 public:
  /// Assembles the model for `effects`. Throws InvalidInputError if both
  /// slip_traction and coulomb_friction are asked for. `mode` says who
  /// integrates the normal spring: in constraint mode the engine solves it
  /// implicitly, so no step exceeds its stability limit (the report keeps
  /// h sqrt(c/m) with an infinite limit, and unstableSteps() stays 0).
  explicit TyreModel(EffectSet effects = EffectSet::full(), ContactMode mode = ContactMode::kForce);

  EffectSet effects() const { return effects_; }
  ContactMode mode() const { return mode_; }
  /// What the contact-level effects ask of WheelContactFinder.
  ContactOptions contactOptions() const { return contact_options_; }

  /// One wheel step of length `step_seconds` (> 0): contacts, then forces.
  /// The result stays valid until the state's next step. Throws
  /// InvalidInputError for invalid parameters, a non-finite pose or motion,
  /// or a non-positive step.
  const WheelForces& step(const Terrain& terrain, const WheelDescription& wheel, const WheelPose& pose,
                          const WheelMotion& motion, double step_seconds, WheelState& state) const;

  /// The step an engine adapter runs inside the engine's own step, where an
  /// exception would leave the engine's world half-stepped. A wheel whose
  /// pose or motion is not finite (its body's state went NaN or infinite in
  /// the engine) is skipped instead: its result is empty (no contacts, a
  /// zero wrench, so no force or engine contact is applied), its tread
  /// deflections are forgotten, state.lastStepSkipped() is true and
  /// state.nonFiniteSteps() counts it; the adapter reports it to its
  /// listener. Invalid parameters or step still throw, as in step (the
  /// adapters check both before the engine steps).
  const WheelForces& stepInEngine(const Terrain& terrain, const WheelDescription& wheel, const WheelPose& pose,
                                  const WheelMotion& motion, double step_seconds, WheelState& state) const;

  /// The second half of step, for contacts found elsewhere (an engine's own
  /// contact search, tests). `materials` are indexed by contact.material.
  const WheelForces& forces(std::span<const Material> materials, const WheelDescription& wheel, const WheelPose& pose,
                            const WheelMotion& motion, double step_seconds, std::span<const WheelContact> contacts,
                            WheelState& state) const;

 private:
  EffectSet effects_;
  ContactMode mode_;
  ContactOptions contact_options_;
  int kernel_ = 0;  // the force kernel compiled for effects_ (src/tyre/tyre_kernels.hpp)
};

}  // namespace wtc

#pragma once
// Effects: the pieces of physics a scene asks for (docs/tyre-model.md).
//
// A scene, or the code that uses the library, names the effects it wants;
// the tyre model is assembled from that set once (TyreModel's constructor
// picks a kernel compiled for exactly those effects), so an effect that is
// off is never evaluated, never branched on per contact, never allocated.
//
// The set is open: an effect is an enumerator plus one row of the name
// table in effects.cpp. Wheel-level effects are read by TyreModel; effects
// of other levels (a vehicle's hitch damping, actuator limits) are read by
// the code of that level from the same set, without any change here beyond
// their row. The elastic normal force c Z is not an effect: it is the model.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace wtc {

enum class Effect : std::uint8_t {
  kNormalDamping,      ///< b v_z in the normal force.
  kSlipTraction,       ///< Tangential force from the slip law mu(s) (spec section 4).
  kCoulombFriction,    ///< Tangential force mu_max R_z (comparison law; excludes kSlipTraction).
  kRollingResistance,  ///< M_r = -f_r R_z r_0 sign(omega_rel . a) a.
  kMultipleContacts,   ///< Every contact of a wheel (off: only the deepest).
  kTreadTruncation,    ///< The wheel is a sphere cut at +-w/2 (off: the full sphere).
  kSoftSoil,           ///< A contact on a material with a soil: the soil's stresses (wheel_soil.hpp).
  kCount
};

/// The scene name of an effect ("normal_damping", ...).
std::string_view effectName(Effect effect);

class EffectSet {
 public:
  constexpr EffectSet() = default;
  constexpr EffectSet(std::initializer_list<Effect> effects) {
    for (const Effect e : effects) bits_ |= bit(e);
  }
  /// The elastic normal force alone.
  static constexpr EffectSet minimal() { return {}; }
  /// Everything the spec's model has: damping, the slip law, rolling
  /// resistance, multiple contacts, tread truncation.
  static constexpr EffectSet full() {
    return {Effect::kNormalDamping, Effect::kSlipTraction, Effect::kRollingResistance, Effect::kMultipleContacts,
            Effect::kTreadTruncation};
  }
  /// From names as a scene writes them: "full", "minimal", or effect names
  /// (see effectName); names add up ("minimal" contributes nothing). Throws
  /// InvalidInputError naming an unknown name, the known ones and `where`.
  static EffectSet parse(const std::vector<std::string>& names, const std::string& where);

  constexpr bool has(Effect e) const { return (bits_ & bit(e)) != 0; }
  constexpr EffectSet with(Effect e) const { return EffectSet(bits_ | bit(e)); }
  constexpr EffectSet without(Effect e) const { return EffectSet(bits_ & ~bit(e)); }
  constexpr bool operator==(const EffectSet&) const = default;

  /// The names of the effects in the set, in enumerator order ("minimal" if none).
  std::string toString() const;

 private:
  explicit constexpr EffectSet(std::uint32_t bits) : bits_(bits) {}
  static constexpr std::uint32_t bit(Effect e) { return std::uint32_t{1} << static_cast<unsigned>(e); }
  std::uint32_t bits_ = 0;
};

}  // namespace wtc

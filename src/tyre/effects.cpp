#include "wtc/tyre/effects.hpp"

#include <array>

#include "wtc/base/error.hpp"

namespace wtc {
namespace {

// The registry: one row per effect, in enumerator order.
constexpr std::array<std::string_view, static_cast<std::size_t>(Effect::kCount)> kNames = {
    "normal_damping",     "slip_traction",     "coulomb_friction",
    "rolling_resistance", "multiple_contacts", "tread_truncation", "soft_soil"};

std::string knownNames() {
  std::string text = "full, minimal";
  for (const std::string_view name : kNames) text += ", " + std::string(name);
  return text;
}

}  // namespace

std::string_view effectName(Effect effect) { return kNames[static_cast<std::size_t>(effect)]; }

EffectSet EffectSet::parse(const std::vector<std::string>& names, const std::string& where) {
  EffectSet set;
  for (const std::string& name : names) {
    if (name == "full") {
      set = EffectSet(set.bits_ | full().bits_);
      continue;
    }
    if (name == "minimal") continue;
    bool known = false;
    for (std::size_t k = 0; k < kNames.size(); ++k) {
      if (name == kNames[k]) {
        set = set.with(static_cast<Effect>(k));
        known = true;
      }
    }
    if (!known) {
      throw InvalidInputError(where + ": unknown effect '" + name + "' (known: " + knownNames() + ")");
    }
  }
  return set;
}

std::string EffectSet::toString() const {
  std::string text;
  for (std::size_t k = 0; k < kNames.size(); ++k) {
    if (!has(static_cast<Effect>(k))) continue;
    if (!text.empty()) text += ", ";
    text += kNames[k];
  }
  return text.empty() ? "minimal" : text;
}

}  // namespace wtc

#pragma once
// What the ground remembers along a wheel's travel, made up for a test
// (wtc/tyre/wheel_soil.hpp, SoilMemoryProfile): the same memory everywhere
// (a rut longer and wider than the wheel), or any function of the place.
#include <functional>
#include <utility>

#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::testing {

/// The same memory at every point (fresh by default).
class UniformProfile final : public SoilMemoryProfile {
 public:
  explicit UniformProfile(const SoilMemory& memory = {}) : memory_(memory) {}
  SoilMemory at(double) const override { return memory_; }

 private:
  SoilMemory memory_;
};

/// memory(ahead, aside): `ahead` along the travel from below the rim's
/// lowest point, `aside` along the axle laid on the surface.
class FunctionProfile final : public SoilMemoryProfile {
 public:
  explicit FunctionProfile(std::function<SoilMemory(double ahead, double aside)> memory)
      : memory_(std::move(memory)) {}
  SoilMemory at(double ahead) const override { return memory_(ahead, 0.0); }
  SoilMemory beside(double ahead, double aside) const override { return memory_(ahead, aside); }

 private:
  std::function<SoilMemory(double, double)> memory_;
};

}  // namespace wtc::testing

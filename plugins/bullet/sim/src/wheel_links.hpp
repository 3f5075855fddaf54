#pragma once
// A wheel body of the Bullet sim engine as its wheel strategies see it
// (wtc_wheels.hpp, native_wheels.hpp): every wheel is a link of a
// btMultiBody, with a collider.
class btMultiBody;
class btMultiBodyLinkCollider;

namespace wtc::bullet {

struct WheelLink {
  btMultiBody* multibody = nullptr;
  int link = -1;
  btMultiBodyLinkCollider* collider = nullptr;
};

}  // namespace wtc::bullet

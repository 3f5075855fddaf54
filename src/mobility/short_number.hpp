#pragma once
// A number in the mobility reports' text (internal to wtc::mobility): four
// significant digits unless told, "%g" (0.1234, 1.235e+04).
#include <cstdio>
#include <string>

namespace wtc::mobility {

inline std::string shortNumber(double v, int digits = 4) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

}  // namespace wtc::mobility

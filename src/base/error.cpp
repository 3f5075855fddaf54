#include "wtc/base/error.hpp"

#include <charconv>

namespace wtc {

// Shortest text that reads back to the same double: exact, and "0.1" rather
// than "0.10000000000000001" or to_string's "0.000000" for 1e-9.
std::string formatNumber(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, result.ptr);
}

std::string formatVector(const Eigen::Vector3d& v) {
  std::string text = "(";
  text.append(formatNumber(v.x())).append(", ").append(formatNumber(v.y())).append(", ");
  text.append(formatNumber(v.z())).append(")");
  return text;
}

}  // namespace wtc

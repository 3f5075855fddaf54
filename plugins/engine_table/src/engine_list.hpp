#pragma once
// Every engine's entries (internal to the engine table). Defined in
// engine_list.cpp, which CMake generates from engine_list.cpp.in and the
// engines declared with wtc_add_engine (cmake/WtcEngine.cmake).
#include <span>

#include "sim/engine_entry.hpp"

namespace wtc::sim::detail {

/// The entries of every engine, in the order the engines were declared.
std::span<const EngineEntry> engineList();

}  // namespace wtc::sim::detail

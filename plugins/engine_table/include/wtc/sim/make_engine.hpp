#pragma once
// makeEngine's former header, kept for programs that include it: the engine
// table's header is wtc/sim/engine_table.hpp.
#include "wtc/sim/engine_table.hpp"

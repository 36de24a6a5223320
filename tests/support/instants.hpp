#pragma once
// Test support: a floating instant (kernel/answer.hpp Instant) from a double: its decimal with 17 significant
// digits as approx, the double as value, no bracket (what a floating pipeline or an external engine reports).
#include "kernel/answer.hpp"

namespace eccd::test {

inline Instant dec(double t) { return rounded_instant(t); }  // kernel/answer.hpp: "%.17g", the double as value

}  // namespace eccd::test

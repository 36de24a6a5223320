#pragma once
// Test support: a floating instant (kernel/answer.hpp Instant) from a double: its decimal with 17 significant
// digits as approx, the double as value, no bracket (what a floating pipeline or an external engine reports).
#include "kernel/answer.hpp"

#include <cstdio>

namespace eccd::test {

inline Instant dec(double t) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", t);
  Instant i;
  i.approx = b;
  i.value = t;
  return i;
}

}  // namespace eccd::test

#pragma once
// A small, portable random generator for seeded scene construction.
//
// splitmix64 (Steele, Lea, Flood 2014). std:: distributions differ between
// standard libraries, and the numbers of a seeded scene must not, so the
// generator (compare/scene_generator.cpp) and the tests that derive
// parameters from a printed seed use this instead.
// Requirements: none; rationals are exact and canonical.
#include "number/rational_traits.hpp"

#include <cstdint>

namespace eccd {

struct SeededRng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform whole number in [lo, hi].
  long uniform(long lo, long hi) { return lo + long(next() % std::uint64_t(hi - lo + 1)); }
  // uniform(lo, hi) / den, canonical (gmpxx's (num, den) constructor does not canonicalize).
  Rational frac(long lo, long hi, long den) {
    Rational q(uniform(lo, hi), den);
    q.canonicalize();
    return q;
  }
};

}  // namespace eccd

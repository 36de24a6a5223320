#pragma once
// Answer: the result of continuous collision detection for one scene, shared
// by every pipeline (double, MPFR, exact) so that the harness compares answers,
// not log lines.
//
// Statement (../shared/spec/scene-format.md, "The answer"): the collision set
// C = { t in [0,1] : A(t) ∩ B(t) ≠ ∅ } (closed objects, touching counts) is a
// finite union of closed intervals. An answer gives `collides`, the maximal
// `intervals` of C, `first_contact` = min C, and `contacts`, the instants of
// external tangency. Each instant carries a decimal approximation and, when
// certified, a rational bracket [lo, hi] that provably contains it and no
// other instant of its list (0 and 1 are written exactly).
// Beyond the spec's four keys, `contact_intervals` (docs/answer-format.md):
// the maximal intervals of positive length on which the objects touch
// externally the whole time (continuous touching, e.g. 2D Δ ≡ 0 with a
// negative double root, 003 Corollary 7 and section VI-B). Such an interval
// is part of C, so it is also inside a collision interval and `collides` is
// true (the spec: touching counts as collision); its instants are not listed
// in `contacts`, which keeps the isolated instants of external tangency.
// Without contact_intervals a continuous touch would read as an overlap.
#include <gmpxx.h>
#include <mpfr.h>

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eccd {

struct Instant {
  std::string approx;              // decimal, for people and plots
  std::optional<mpq_class> lo, hi;  // present iff certified
  // The approximation as a double (for display and reports; never used to
  // decide): filled wherever approx is, NaN where nothing filled it.
  double value = std::numeric_limits<double>::quiet_NaN();
  bool certified() const { return lo.has_value() && hi.has_value(); }
};

struct ContactPoint {  // Lemma 5 of 003: the touching point (display only)
  std::vector<std::string> x;
};

struct Answer {
  bool collides = false;
  std::vector<std::pair<Instant, Instant>> intervals;
  std::optional<Instant> first_contact;
  std::vector<Instant> contacts;
  std::vector<std::pair<Instant, Instant>> contact_intervals;  // continuous touching; JSON key optional, default []
  // Extras: not part of the stored answer, reported by `eccd solve --json`.
  std::vector<ContactPoint> contact_points;      // one per contact
  std::vector<Instant> undecided;                 // floating: instants it could not classify
};

// A decimal approximation of an exact rational with `digits` significant
// digits, for display (rounded by MPFR at 256 bits; never used to decide).
inline std::string decimal_string(const mpq_class& q, int digits = 20) {
  mpfr_t r;
  mpfr_init2(r, 256);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
  char* s = nullptr;
  mpfr_asprintf(&s, "%.*Rg", digits, r);
  std::string out(s);
  mpfr_free_str(s);
  mpfr_clear(r);
  return out;
}

// The double nearest to an exact rational (MPFR rounding to nearest), for
// Instant::value: display and reports only, never a decision.
inline double nearest_double(const mpq_class& q) {
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
  double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

// An instant with an exact bracket [lo, hi]: approx and value from `mid`.
inline Instant bracketed_instant(const mpq_class& mid, const mpq_class& lo, const mpq_class& hi) {
  return Instant{decimal_string(mid), lo, hi, nearest_double(mid)};
}

}  // namespace eccd

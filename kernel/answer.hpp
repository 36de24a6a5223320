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
#include "number/double_traits.hpp"
#include "number/scalar_traits.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace eccd {

struct Instant {
  std::string approx;               // decimal, for people and plots
  std::optional<mpq_class> lo, hi;  // present iff certified
  // The approximation as a double (for display and reports; never used to
  // decide): filled wherever approx is, NaN where nothing filled it.
  double value = std::numeric_limits<double>::quiet_NaN();
  bool certified() const { return lo.has_value() && hi.has_value(); }
};

struct ContactPoint {  // Lemma 5 of 003: the touching point (display only)
  std::vector<std::string> x;
  // The common normal there: A's unit outward normal (pointing from a to b;
  // b's is its negative), decimals, display only (kernel/contact_geometry.hpp).
  std::vector<std::string> normal;
};

struct Answer {
  bool collides = false;
  std::vector<std::pair<Instant, Instant>> intervals;
  std::optional<Instant> first_contact;
  std::vector<Instant> contacts;
  std::vector<std::pair<Instant, Instant>> contact_intervals;  // continuous touching; JSON key optional, default []
  // Extras: not part of the stored answer, reported by `eccd solve --json`.
  std::vector<ContactPoint> contact_points;  // one per contact
  std::vector<Instant> undecided;            // floating: instants it could not classify
  // Independent motions (scene-format.md, "Independent motions"; a scene with
  // "parameters": "independent"): the answer is `collides`, `s_intervals`
  // (the maximal closed intervals of { s : A(s) meets B(t) for some t }) and
  // `t_intervals` (likewise for t); intervals, first_contact, contacts and
  // contact_intervals stay empty. `undecided` then holds values of s or t
  // (the reasons say which).
  bool independent = false;
  std::vector<std::pair<Instant, Instant>> s_intervals, t_intervals;
};

// What an answer claims about `collides`. An answer that leaves a stretch
// undecided (Answer::undecided non-empty) has not proved that the objects
// never meet there, so it may claim a collision only where one is proved
// (an interval: true) and otherwise nothing: nullopt, written `null` in
// JSON ("unknown"). Only a complete answer (nothing undecided) claims false.
// Answer::collides stays a bool (the intervals' summary); every writer of a
// claim (solution JSON, certificates, their checkers) goes through this.
inline std::optional<bool> collides_claim(const Answer& a) {
  if (a.collides) return true;
  if (!a.undecided.empty()) return std::nullopt;
  return false;
}

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

// A double for display with 17 significant digits (round-trips): the string decimal_string(mpq_class(x), 17)
// gives, by the C library (correctly rounded, as MPFR's), without the 256-bit detour; -0 prints as 0, as a
// rational would.
inline std::string decimal_string_of_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x == 0 ? 0.0 : x);
  return buf;
}

// The double nearest to an exact rational (rounded to nearest: scalar_traits<double>::from_rational, the one
// conversion), for Instant::value: display and reports only, never a decision.
inline double nearest_double(const mpq_class& q) { return scalar_traits<double>::from_rational(q); }

// How many significant digits an instant's approx carries: what
// the instant supports, no more. This is the one rule; every pipeline makes
// its instants through bracketed_instant or rounded_instant below.
//  - An instant with a bracket [lo, hi] (exact, certified): the digits the
//    bracket's width w supports, floor(-log10 w) + 1, at least 3 and at most 20
//    (a point bracket, an exact rational: 20, as decimal_string always gave).
//    For t in [0, 1) the rounding error of the mid-point is then below
//    10^-floor(-log10 w) / 20 < w / 2, so the approx stays inside its bracket.
//  - A floating instant of precision B bits: ceil(B log10 2) + 1 (53 bits: 17,
//    the digits that round-trip a double), at most 40. Why 40 (133 bits): the
//    precision bounds only the last rounding, not the run's error, which the
//    root's conditioning sets; every consumer reads an instant as a double
//    (Instant::value) and the harness's tolerances are >= 1e-16, so digits past
//    40 only print noise (mpfr:4096 printed 1 234 of them).
inline int bracket_digits(const mpq_class& lo, const mpq_class& hi) {
  const mpq_class w = hi - lo;
  if (sgn(w) <= 0) return 20;
  mpfr_t r;
  mpfr_init2(r, 64);
  mpfr_set_q(r, w.get_mpq_t(), MPFR_RNDN);
  mpfr_log10(r, r, MPFR_RNDN);
  const double l = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  const double d = std::floor(-l) + 1;
  return d < 3 ? 3 : d > 20 ? 20 : int(d);
}
inline int precision_digits(int bits) {
  if (bits <= 53) return 17;
  const int d = int(std::ceil(bits * 0.30102999566398120)) + 1;  // log10(2)
  return d > 40 ? 40 : d;
}
// A decimal text (as a scalar type prints it, e.g. "1.25e-05", "inf") rounded
// to `digits` significant digits (MPFR, nearest); text MPFR cannot read is kept.
inline std::string round_decimal(const std::string& text, int digits) {
  mpfr_t r;
  mpfr_init2(r, mpfr_prec_t(64 + 4 * text.size()));
  std::string out = text;
  if (mpfr_set_str(r, text.c_str(), 10, MPFR_RNDN) == 0 && mpfr_number_p(r)) {
    char* s = nullptr;
    mpfr_asprintf(&s, "%.*Rg", digits, r);
    out = s;
    mpfr_free_str(s);
  }
  mpfr_clear(r);
  return out;
}

// An instant with an exact bracket [lo, hi]: approx (bracket_digits) and value from `mid`.
inline Instant bracketed_instant(const mpq_class& mid, const mpq_class& lo, const mpq_class& hi) {
  return Instant{decimal_string(mid, bracket_digits(lo, hi)), lo, hi, nearest_double(mid)};
}

// A floating instant (no bracket) at t computed in T: approx to
// precision_digits of T's precision, value the double nearest t.
// Cost: for T = double or a double with a running error bound
// (its to_string prints the value with "%.17g"), the text already has the 17
// significant digits precision_digits(53) asks for, and round_decimal gives it
// back unchanged (checked over every power of two, its predecessor and 4
// million random doubles, NaN and infinities included:
// tests/kernel/test_answer.cpp), so the MPFR round trip (about 1 µs per instant,
// 9 % of an animation frame) is skipped.
template <class T>
constexpr bool prints_as_double() {
  if constexpr (std::is_same_v<T, double>)
    return true;
  else if constexpr (requires(const T& x) { x.value(); })
    return std::is_same_v<std::decay_t<decltype(std::declval<const T&>().value())>, double>;
  else
    return false;
}

template <class T>
Instant rounded_instant(const T& t) {
  if constexpr (prints_as_double<T>())
    if (precision_digits(scalar_traits<T>::precision(t)) == 17)
      return Instant{scalar_traits<T>::to_string(t), std::nullopt, std::nullopt, scalar_traits<T>::to_double(t)};
  return Instant{round_decimal(scalar_traits<T>::to_string(t), precision_digits(scalar_traits<T>::precision(t))),
                 std::nullopt, std::nullopt, scalar_traits<T>::to_double(t)};
}

}  // namespace eccd

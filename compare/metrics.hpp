#pragma once
// Metrics of the robustness report: how far a floating pipeline's
// coefficients and answer are from the exact ones.
//
// Statement.
//  * Coefficient error (docs/architecture.md, "What the workbench measures"; 003 VI-C and 002 IV measure the
//    same loss): the normwise relative error  max_i |ã_i - a_i| / max_i |a_i|
//    of a list of coefficients ã against the exact list a in the same basis,
//    computed exactly in rationals (every double and MPFR value is a dyadic
//    rational) and rounded once to a double at the end. A set of polynomials
//    (g_0..g_n) counts as one vector. Polynomials in Bernstein form of
//    different degrees are compared after exact degree elevation of the lower
//    one (elevation does not change the polynomial). If the exact list is
//    all zero the error is the absolute max |ã_i|.
//  * Coefficient error in a common basis (`coef_err_common`): the
//    error above depends on the basis it is measured in, so the errors of a
//    power-form and a Bernstein-form pipeline are not comparable (a power
//    coefficient a_i and a Bernstein coefficient b_k are different numbers,
//    with different magnitudes). The common measure takes the pipeline's
//    floating coefficients as they are, converts them exactly to rationals,
//    changes basis exactly to the Bernstein basis on [0, 1] (kernel/bernstein.hpp,
//    to_bernstein: the one basis conversion) and compares with the exact
//    Bernstein coefficients by the same normwise relative error. For a
//    pipeline that holds Bernstein coefficients it equals the coefficient
//    error itself.
//  * Answer comparison against the exact answer (typed answers; the counts
//    come from api/answer_difference.hpp, the one comparison of answers):
//    the outcome of `collides` (correct, false_positive = reports a collision
//    that does not happen, false_negative = misses one, undecided = the
//    pipeline said it could not classify an instant: never folded into right
//    or wrong, error = the pipeline threw); the numbers of intervals; missed
//    and false contacts (matched one to one within `tol`); the first-contact
//    error and the largest interval-end error (only when the interval counts
//    agree; 0 without intervals; independent motions: the s- and t-intervals
//    count together, as api/answer_difference.hpp counts them); structure_ok = correct, the same intervals
//    one to one (ends matching), the same contacts and contact intervals;
//    exact_touch = the exact answer touches without overlapping (an interval
//    of one instant, or continuous touching): a double root that rounded
//    arithmetic cannot prove, counted apart by the guard's record.
//    This follows the habit of CCD benchmarks against an exact ground truth
//    (Wang et al., ACM TOG 2021: false positives, false negatives, time).
// Requirements: T is double, eccd::Mpfr or mpq_class (exact_value below).
#include "api/answer_difference.hpp"
#include "number/rational_traits.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "kernel/bernstein.hpp"
#include "kernel/bivariate_bernstein.hpp"
#include "kernel/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace eccd {

// A non-finite value (an overflow: ±inf or NaN) has no exact value; GMP would
// raise SIGFPE on it. It is recorded here and makes the error +inf.
struct NonFinite {
  static bool& seen() {
    thread_local bool s = false;
    return s;
  }
};
inline mpq_class exact_value(double x) {
  if (!std::isfinite(x)) {
    NonFinite::seen() = true;
    return mpq_class(0);
  }
  return mpq_class(x);
}
inline mpq_class exact_value(const Mpfr& x) {
  if (!mpfr_number_p(x.get())) {
    NonFinite::seen() = true;
    return mpq_class(0);
  }
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), x.get());
  return q;
}
inline mpq_class exact_value(const mpq_class& x) { return x; }

// max |approx_i - exact_i| / max |exact_i| (missing entries count as 0).
// +inf if a value of the approximate list was not finite (see NonFinite).
inline double normwise_relative_error(const std::vector<mpq_class>& approx, const std::vector<mpq_class>& exact) {
  if (NonFinite::seen()) {
    NonFinite::seen() = false;
    return std::numeric_limits<double>::infinity();
  }
  mpq_class num = 0, den = 0;
  for (std::size_t i = 0; i < std::max(approx.size(), exact.size()); ++i) {
    mpq_class a = i < approx.size() ? approx[i] : mpq_class(0);
    mpq_class e = i < exact.size() ? exact[i] : mpq_class(0);
    mpq_class d = abs(a - e), m = abs(e);
    if (d > num) num = d;
    if (m > den) den = m;
  }
  if (den == 0) return num.get_d();
  mpq_class r = num / den;
  return r.get_d();
}

// Coefficient lists, in the basis each polynomial is held in.
template <class T>
void append_coefficients(const Poly<T>& p, std::vector<mpq_class>& out, int degree) {
  for (int i = 0; i <= degree; ++i) out.push_back(i < int(p.c.size()) ? exact_value(p.c[i]) : mpq_class(0));
}
template <class T>
Bern<mpq_class> exact_bernstein(const Bern<T>& b) {
  Bern<mpq_class> r;
  for (const auto& x : b.b) r.b.push_back(exact_value(x));
  return r;
}

// Power form: coefficient i against coefficient i (the longer list decides the length).
template <class T>
double coefficient_error(const std::vector<Poly<T>>& approx, const std::vector<Poly<mpq_class>>& exact) {
  std::vector<mpq_class> a, e;
  for (std::size_t k = 0; k < exact.size(); ++k) {
    int n = std::max(exact[k].degree(), k < approx.size() ? approx[k].degree() : -1);
    append_coefficients(exact[k], e, n);
    if (k < approx.size())
      append_coefficients(approx[k], a, n);
    else
      for (int i = 0; i <= n; ++i) a.push_back(0);
  }
  return normwise_relative_error(a, e);
}

// Bernstein form on [0, 1]: both at the larger of the two degrees.
template <class T>
double coefficient_error(const std::vector<Bern<T>>& approx, const std::vector<Bern<mpq_class>>& exact) {
  std::vector<mpq_class> a, e;
  for (std::size_t k = 0; k < exact.size() && k < approx.size(); ++k) {
    Bern<mpq_class> x = exact_bernstein(approx[k]), y = exact[k];
    int n = std::max(x.degree(), y.degree());
    x = elevate(x, n - x.degree());
    y = elevate(y, n - y.degree());
    a.insert(a.end(), x.b.begin(), x.b.end());
    e.insert(e.end(), y.b.begin(), y.b.end());
  }
  return normwise_relative_error(a, e);
}
template <class T>
double coefficient_error(const Bern<T>& approx, const Bern<mpq_class>& exact) {
  return coefficient_error(std::vector<Bern<T>>{approx}, std::vector<Bern<mpq_class>>{exact});
}

// Power form measured in the common (Bernstein on [0, 1]) basis: each approximate
// polynomial converted exactly to rationals, then exactly to Bernstein form of its
// degree, against the exact Bernstein coefficients (see the prose at the top).
template <class T>
double coefficient_error_common(const std::vector<Poly<T>>& approx, const std::vector<Bern<mpq_class>>& exact) {
  std::vector<Bern<mpq_class>> a;
  for (const auto& p : approx) {
    std::vector<mpq_class> c;
    for (const auto& x : p.c) c.push_back(exact_value(x));
    a.push_back(to_bernstein(Poly<mpq_class>(std::move(c))));
  }
  return coefficient_error(a, exact);
}

// Tensor Bernstein F(u, t): the u-rows as Bernstein polynomials in t.
template <class T>
double coefficient_error(const BiBern<T>& approx, const BiBern<mpq_class>& exact) {
  std::vector<Bern<T>> a;
  std::vector<Bern<mpq_class>> e;
  for (const auto& row : approx.b) {
    Bern<T> b;
    b.b = row;
    a.push_back(b);
  }
  for (const auto& row : exact.b) {
    Bern<mpq_class> b;
    b.b = row;
    e.push_back(b);
  }
  return coefficient_error(a, e);
}

// ---- answers -------------------------------------------------------------

struct AnswerMetrics {
  std::string outcome;  // correct | false_positive | false_negative | undecided | error
  std::optional<bool> collides;
  bool exact_collides = false;
  // The exact answer touches without overlapping: a collision interval of one instant (an isolated touch) or a
  // stretch of continuous touching (contact_intervals). Rounded arithmetic cannot prove such a double root, so a
  // guarded run is undecided there by design; the report's guard record counts those scenes apart.
  bool exact_touch = false;
  int intervals = 0, exact_intervals = 0;
  int missed_contacts = 0, false_contacts = 0;
  std::optional<double> first_contact_err, endpoint_err;
  bool structure_ok = false;
};

// got: a pipeline's answer (nullptr: the pipeline failed); exact: the exact
// answer. The counts come from the one answer comparison
// (api/answer_difference.hpp).
inline AnswerMetrics answer_metrics(const Answer* got, const Answer& exact, double tol = 1e-6) {
  AnswerMetrics m;
  m.exact_collides = exact.collides;
  m.exact_touch =
      !exact.contact_intervals.empty() ||
      std::any_of(exact.intervals.begin(), exact.intervals.end(),
                  [](const auto& iv) {  // one instant: the same bracket (certified) or the same value
                    const Instant &a = iv.first, &b = iv.second;
                    return a.certified() && b.certified() ? *a.lo == *b.lo && *a.hi == *b.hi : a.value == b.value;
                  });
  m.exact_intervals =
      int(exact.independent ? exact.s_intervals.size() + exact.t_intervals.size() : exact.intervals.size());
  if (!got) {
    m.outcome = "error";
    return m;
  }
  DifferenceOptions o;
  o.tol = tol;
  AnswerDifference d = answer_difference(*got, exact, o);
  m.collides = got->collides;
  m.intervals = d.intervals;
  m.exact_intervals = d.reference_intervals;  // independent motions: s- and t-intervals together
  if (!got->undecided.empty())
    m.outcome = "undecided";
  else if (!d.collides_differs)
    m.outcome = "correct";
  else
    m.outcome = got->collides ? "false_positive" : "false_negative";
  m.missed_contacts = d.missed_contacts;
  m.false_contacts = d.false_contacts;
  m.first_contact_err = d.first_contact_error;
  if (m.intervals == m.exact_intervals) {  // matched one to one, else interval k against interval k
    if (d.max_endpoint_error) {
      m.endpoint_err = d.max_endpoint_error;
    } else {
      double e = 0;
      for (std::size_t k = 0; k < exact.intervals.size(); ++k)
        e = std::max({e, std::abs(got->intervals[k].first.value - exact.intervals[k].first.value),
                      std::abs(got->intervals[k].second.value - exact.intervals[k].second.value)});
      m.endpoint_err = e;
    }
  }
  m.structure_ok = m.outcome == "correct" && m.intervals == m.exact_intervals && d.split == 0 && d.merged == 0 &&
                   d.endpoints_off == 0 && m.missed_contacts == 0 && m.false_contacts == 0 &&
                   d.contact_intervals_differ == 0;
  return m;
}

}  // namespace eccd

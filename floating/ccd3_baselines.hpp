#pragma once
// The two baselines of 3D continuous collision detection: temporal sampling
// with the static test (`sampling:N`) and marching squares on F(u, t)
// (`marching:N`). Approximate by construction; the harness measures the
// certified pipeline (kernel/ccd_projection.hpp) against them.
//
// Statement. Both start like every 3D pipeline: A(t), B(t) (kernel/quadric.hpp),
// f(λ;t) = det(λA(t) - B(t)) = sum g_k(t) λ^k (kernel/characteristic_polynomial.hpp),
// and both end like every pipeline: a timeline instant, cell, ..., instant
// over [0, 1] turned into an Answer by assemble_answer
// (kernel/collision_timeline.hpp). No instant is certified (Instant{decimal,
// nullopt, nullopt}), even with exact T: the instants are sample or grid
// positions, not brackets of the true events.
//
// sampling:N — "what a user who samples would report". The static test
// (002 Theorem 1, kernel/quartic_status.hpp: Sturm count of the negative
// roots of f(.;t_k)) at the N + 1 instants t_k = k/N.
//   Timeline: the instants are the samples, with their statuses. Between two
//   consecutive samples lies one cell, whose status is a rule, not an
//   evaluation (cell_between_samples below): in collision iff both end
//   samples are (touching iff both touch, else overlapping); separate iff one
//   end is separate; otherwise (an uncertain end, the other not separate)
//   uncertain. So the transition instants ARE the samples: a collision
//   interval is a maximal run of colliding samples [t_k, t_e], reported with
//   its first and last colliding samples as endpoints (a run of one sample
//   is the isolated instant [t_k, t_k]); `critical` lists those run ends that
//   have a separate neighbouring sample. With exact statuses at the samples
//   the reported intervals lie inside the true collision set: each start is
//   late and each end early by less than 1/N (when only one event falls
//   between two samples). `contacts` are the samples that the static test
//   finds exactly touching (t = k/N must hit the touch: an isolated touch at
//   1/2 is seen for even N and missed for odd N, a property of sampling, not
//   a bug; in rounded T even a sample on the touch may be called separate or
//   overlapping, since the double root splits or vanishes: see
//   tests/kernel/test_fast_quartic.cpp). check_isolated_instants is not applied: a lone overlapping
//   sample between separate samples is a legitimate sampling observation
//   (a short overlap), not a contradiction of the theory.
//   first_contact_only: sampling stops at the first separate sample after a
//   colliding one (that sample is kept: it is what ends the run).
//
// marching:N — 002 section IV: "a marching square technique applied to a
// regular grid of 100×100 cells" (N = 100 there). F(u, t) = det((u-1)A(t) -
// uB(t)) in tensor Bernstein form (kernel/ellipsoid_function.hpp) is evaluated
// at the (N+1)² grid points (u_i, t_j) = (i/N, j/N). At t the pair is separate
// iff F(., t) > 0 somewhere in (0, 1); the positive set there is one u-interval
// (u1(t), u2(t)), u = 1/(1 - λ) for the two negative roots λ of f.
//   Rows: row j is separate iff some grid value F(u_i, t_j) > 0, otherwise in
//   collision, reported as overlapping (the grid cannot tell a touch from an
//   overlap), or uncertain if no value is positive and some sign is
//   uncertain. `cells` lists the rows with these statuses.
//   Transitions: marching squares classifies a grid point as inside (F > 0)
//   or outside (F <= 0) and places the contour F = 0 on every cell edge whose
//   end points differ, at the zero of the linear interpolant. In a strip
//   [t_j, t_{j+1}] whose rows are separate and in collision, the collision
//   row has no inside point, so it has no contour crossing and every inside
//   point of the separate row starts a vertical edge that the contour crosses
//   at
//       c_i = t_j + (t_{j+1} - t_j) F(u_i,t_j) / (F(u_i,t_j) - F(u_i,t_{j+1})).
//   These are the only contour points strictly inside the strip (horizontal
//   crossings lie on the separate row itself), so the extreme t of the contour
//   in the strip is an extreme c_i. The rule:
//     separate -> collision: c = max c_i over the inside points of row j, the
//       top of the contour loop: where the last of the separate region closes;
//     collision -> separate: c = min c_i over the inside points of row j+1,
//       the bottom of the contour loop: where the separate region opens.
//   c is a timeline instant with status touching (a change of status passes
//   through an external touch, 002 Theorem 1); it splits the strip into two
//   cells with the statuses of their rows, and is listed in `critical` and,
//   through assemble_answer, in `contacts`. If c falls on the collision row
//   itself (a grid value exactly 0 there), that row is the transition: it is
//   marked touching and the strip is one separate cell. Strips with equal or
//   uncertain rows get the sampling rule above. first_contact_only: the scan
//   stops at the first transition collision -> separate (or the first
//   separate row after a colliding one).
//   What is approximate (002 IV: "there is some danger of missing small loops"):
//   - a row is separate only if a grid point lands in (u1(t), u2(t)); when
//     that interval is narrower than 1/N (within O(N^-2) of a generic touch,
//     or all along a near-touching motion) the row is wrongly in collision,
//     which moves a transition by up to one strip or reports a false
//     collision. Rows reported separate are proved so with exact T; rows in
//     collision are not (unlike sampling:N, whose statuses are exact).
//   - anything strictly between two rows of the same status is invisible: a
//     collision shorter than 1/N between separate rows (an isolated touch
//     between rows is missed), and a separation shorter than 1/N between
//     colliding rows (a small loop of the zero set). A strip with several
//     transitions reports one. An isolated touch exactly at a row instant
//     t_j is seen, but as a short interval [c, c'] around t_j with two
//     contacts: F(., t_j) <= 0 puts the row in collision (its maximum 0 is
//     between grid points).
//   - c is the zero of a linear interpolant; the extreme is attained at the
//     grid line u_i nearest the tip of the loop. For a generic tip
//     (F ≈ -a(t - t0) - b(u - u*)²) its error is O(N^-2) (the u-offset
//     b δu²/a with δu <= 1/(2N), plus the curvature of F(u_i, .) along the
//     edge), and never more than the strip while the rows are right.
//   - in rounded T the grid values carry the rounding error of the whole
//     construction; signs near F = 0 can be wrong (uncertain only for NaN).
//     That error does not shrink with N: on cases/paper002/example (g_i of
//     degree 36 in t, built in double in the power basis) det A(0.856) is
//     off by 1.7 %, and marching in double misplaces the last endpoint by
//     2.6e-4 for N = 1000 and 3000 alike, where MPFR at 256 bits converges
//     (error 6e-7 at N = 3000).
//
// Requirements on T: a field (the static test divides, c_i divides),
// comparison between T values, scalar_traits<T>; used with double and Mpfr
// and compiles with mpq_class. N >= 1.
// Known failure modes: those listed above; cost sampling O(N · Sturm of a
// quartic), marching O(N · (deg_t F)² + N²).
// Termination: g is scaled by a power of two first (a non-finite
// coefficient: undecided on [0, 1] with the reason); at most kBaselineWork
// status tests (sampling) or values of F (marching) per run, and the run's
// deadline (kernel/budget.hpp) is asked per sample or row. When either is hit,
// the rest of [0, 1] is one undecided cell ending in an undecided instant 1.
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "kernel/answer.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "number/pow2_scaling.hpp"
#include "kernel/budget.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/quartic_status.hpp"

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

namespace baseline_detail {

// Display of an instant: decimal for exact T, the arithmetic's own string otherwise.
template <class T>
Instant uncertified_instant(const T& t) {
  if constexpr (scalar_traits<T>::is_exact)
    return Instant{decimal_string(t), std::nullopt, std::nullopt, nearest_double(t)};
  else
    return rounded_instant(t);
}

// k / N in the run's arithmetic.
template <class T>
T grid_value(int k, int n, const T& like) {
  mpq_class q(k, n);
  q.canonicalize();
  return scalar_traits<T>::from_rational(q, like);
}

// The midpoint of a cell: its display instant only (the baselines never evaluate there).
template <class T>
Instant cell_instant(const T& a, const T& b, const T& like) {
  T s = a + b;
  T m = scalar_traits<T>::from_rational(mpq_class(1, 2), like) * s;
  return uncertified_instant(m);
}

// The status of the cell between two observed instants (see the prose above).
inline Status cell_between_samples(Status l, Status r) {
  if (l == Status::separate || r == Status::separate) return Status::separate;
  if (l == Status::uncertain || r == Status::uncertain) return Status::uncertain;
  return l == r ? l : Status::overlapping;  // both in collision
}

// Floating: g scaled by a power of two (number/pow2_scaling.hpp); "" or why nothing can be decided.
template <class T>
std::string prepare_g(std::vector<Bern<T>>& g) {
  if constexpr (scalar_traits<T>::is_exact)
    return {};
  else {
    if (!normalise_pow2<T>([&](auto f) {
          for (auto& gi : g)
            for (auto& x : gi.b) f(x);
        }))
      return "overflow: a non-finite coefficient of f (g_k)";
    return {};
  }
}

// The rest of [0, 1] from the last observed instant `from` is undecided (work bound or deadline).
template <class T>
void rest_undecided(std::vector<TimelineNode>& seq, PipelineResult<T>& res, const T& from, const T& like,
                    const std::string& why) {
  T one = scalar_traits<T>::from_rational(mpq_class(1), like);
  seq.push_back({cell_instant(from, one, like), Status::uncertain, true});
  seq.push_back({uncertified_instant(one), Status::uncertain, false});
  res.undecided_reasons.push_back(why);
}

// Work bound of the baselines: status tests (sampling) or values of F (marching) per run.
constexpr long kBaselineWork = 50'000'000;

inline void check_grid(int n) {
  if (n < 1) throw std::invalid_argument("baseline grid size N must be at least 1, got " + std::to_string(n));
}

// The start of both baselines: the grid checked, g scaled (prepare_g), the
// result begun; false if nothing can be decided (res is then the answer).
template <class T>
bool begin_run(std::vector<Bern<T>>& g, const T& like, int N, bool first_contact_only, PipelineResult<T>& res) {
  check_grid(N);
  const std::string trouble = prepare_g(g);
  res = result_from_bernstein(g, first_contact_only);
  if (trouble.empty()) return true;
  undecided_everywhere(res, uncertified_instant(grid_value(0, 1, like)), uncertified_instant(grid_value(1, 1, like)),
                       trouble);
  return false;
}

// Marching (ccd_marching): a row's status from F's values on it (positive somewhere: separate).
template <class T>
Status marching_row_status(const std::vector<T>& v) {
  bool unsure = false;
  for (const auto& x : v) {
    Sign s = sign(x);
    if (s == Sign::positive) return Status::separate;
    if (s == Sign::uncertain) unsure = true;
  }
  return unsure ? Status::uncertain : Status::overlapping;
}

// The zero of the linear interpolant on the vertical edge u = u_i (f0 and f1 of opposite classes).
template <class T>
T marching_crossing(const T& t0, const T& t1, const T& f0, const T& f1) {
  T d = f0 - f1;
  T r = f0 / d;
  T h = t1 - t0;
  T off = h * r;
  T c = t0 + off;
  return c;
}

// The extreme t of the contour in the strip between rows t0 (values v0) and t1 (values v1) where a collision
// starts (the latest crossing) or ends (the earliest) (see the prose block).
template <class T>
std::optional<T> contour_extreme(bool starts, const T& t0, const T& t1, const std::vector<T>& v0,
                                 const std::vector<T>& v1) {
  const std::vector<T>& inside = starts ? v0 : v1;
  std::optional<T> c;
  for (std::size_t i = 0; i < inside.size(); ++i) {
    if (sign(inside[i]) != Sign::positive) continue;
    T ci = marching_crossing(t0, t1, v0[i], v1[i]);
    if (!c || (starts ? *c < ci : ci < *c)) c = ci;
  }
  return c;
}

// The timeline over the strip from row j (t0, status s0; seq.back()) to row j + 1 (t1, s1) where a collision
// starts or ends at the contour's extreme t = c. Returns true when the run stops there (first_contact_only).
template <class T>
bool march_transition(std::vector<TimelineNode>& seq, PipelineResult<T>& res, bool starts, bool ends, const T& t0,
                      const T& t1, Status s0, Status s1, const T& c, int j, int& last_critical_row,
                      bool first_contact_only, const T& like) {
  const bool on_row = starts ? !(c < t1) : !(t0 < c);  // c is the collision row itself
  if (on_row && starts) {                              // c == t_{j+1}: row j+1 is where the collision starts
    seq.push_back({cell_instant(t0, t1, like), Status::separate, true});
    seq.push_back({uncertified_instant(t1), Status::touching, false});
    res.critical.push_back({seq.back().t, Status::touching, 0});
    last_critical_row = j + 1;
    return false;
  }
  if (on_row) {  // c == t_j: row j (seq.back()) is where the collision ends
    seq.back().status = Status::touching;
    if (last_critical_row != j) res.critical.push_back({seq.back().t, Status::touching, 0});
    last_critical_row = j;
    if (first_contact_only) return true;
    seq.push_back({cell_instant(t0, t1, like), Status::separate, true});
    seq.push_back({uncertified_instant(t1), s1, false});
    return false;
  }
  seq.push_back({cell_instant(t0, c, like), s0, true});
  seq.push_back({uncertified_instant(c), Status::touching, false});
  res.critical.push_back({seq.back().t, Status::touching, 0});
  if (ends && first_contact_only) return true;
  seq.push_back({cell_instant(c, t1, like), s1, true});
  seq.push_back({uncertified_instant(t1), s1, false});
  return false;
}
}  // namespace baseline_detail

template <class T>
PipelineResult<T> ccd_sampling(const std::vector<Bern<T>>& g, const T& like, int N, bool first_contact_only) {
  using namespace baseline_detail;
  auto start = std::chrono::steady_clock::now();
  std::vector<Bern<T>> gs = g;
  PipelineResult<T> res;
  if (!begin_run(gs, like, N, first_contact_only, res)) return res;

  std::vector<TimelineNode> seq;
  std::vector<Status> st;  // status of sample k (== seq[2k].status)
  bool seen_collision = false;
  std::optional<T> prev;
  for (int k = 0; k <= N; ++k) {
    if (prev && (deadline_passed() || k > kBaselineWork)) {
      rest_undecided(seq, res, *prev, like,
                     deadline_passed() ? deadline_reason() : "sampling stopped at its work bound");
      break;
    }
    T t = grid_value(k, N, like);
    Status s = quartic_status_at(gs, t);
    if (k == 0) res.status_at_0 = s;
    res.cells.push_back({uncertified_instant(t), s});
    if (prev) seq.push_back({cell_instant(*prev, t, like), cell_between_samples(st.back(), s), true});
    seq.push_back({uncertified_instant(t), s, false});
    st.push_back(s);
    prev = t;
    if (first_contact_only && seen_collision && s == Status::separate) break;
    seen_collision = seen_collision || in_collision(s);
  }
  // The run ends with a separate neighbouring sample are the transitions found.
  for (std::size_t k = 0; k < st.size(); ++k) {
    if (!in_collision(st[k])) continue;
    bool before = k > 0 && st[k - 1] == Status::separate;
    bool after = k + 1 < st.size() && st[k + 1] == Status::separate;
    if (before || after) res.critical.push_back({seq[2 * k].t, st[k], 0});
  }
  assemble_answer(seq, res.answer, [](std::size_t) {});
  if (first_contact_only && res.answer.intervals.size() > 1) res.answer.intervals.resize(1);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

template <class T>
PipelineResult<T> ccd_marching(const std::vector<Bern<T>>& g, const T& like, int N, bool first_contact_only) {
  using namespace baseline_detail;
  auto start = std::chrono::steady_clock::now();
  std::vector<Bern<T>> gs = g;
  PipelineResult<T> res;
  if (!begin_run(gs, like, N, first_contact_only, res)) return res;
  const BiBern<T> F = ellipsoid_function(gs, like);

  std::vector<T> u;
  for (int i = 0; i <= N; ++i) u.push_back(grid_value(i, N, like));
  auto row_values = [&](const T& t) {
    const Bern<T> q = ellipsoid_function_at(F, t);  // F(., t), quartic in u
    std::vector<T> v;
    v.reserve(u.size());
    for (const auto& ui : u) v.push_back(q(ui));
    return v;
  };

  std::vector<TimelineNode> seq;
  T t0 = grid_value(0, N, like);
  std::vector<T> v0 = row_values(t0);
  Status s0 = marching_row_status(v0);
  res.status_at_0 = s0;
  res.cells.push_back({uncertified_instant(t0), s0});
  seq.push_back({uncertified_instant(t0), s0, false});
  bool seen_collision = in_collision(s0);
  int last_critical_row = -1;
  long work = long(N) + 1;
  for (int j = 0; j < N; ++j) {
    work += long(N) + 1;
    if (deadline_passed() || work > kBaselineWork) {
      rest_undecided(seq, res, t0, like,
                     deadline_passed()
                         ? deadline_reason()
                         : "marching stopped at its work bound of " + std::to_string(kBaselineWork) + " values of F");
      break;
    }
    T t1 = grid_value(j + 1, N, like);
    std::vector<T> v1 = row_values(t1);
    Status s1 = marching_row_status(v1);
    res.cells.push_back({uncertified_instant(t1), s1});
    const bool starts = s0 == Status::separate && in_collision(s1);
    const bool ends = in_collision(s0) && s1 == Status::separate;
    if (starts || ends) {
      const std::optional<T> c = contour_extreme(starts, t0, t1, v0, v1);
      if (march_transition(seq, res, starts, ends, t0, t1, s0, s1, *c, j, last_critical_row, first_contact_only, like))
        break;
    } else {
      seq.push_back({cell_instant(t0, t1, like), cell_between_samples(s0, s1), true});
      seq.push_back({uncertified_instant(t1), s1, false});
    }
    if (first_contact_only && seen_collision && s1 == Status::separate) break;
    seen_collision = seen_collision || in_collision(s1);
    t0 = t1;
    v0 = std::move(v1);
    s0 = s1;
  }
  assemble_answer(seq, res.answer, [](std::size_t) {});
  if (first_contact_only && res.answer.intervals.size() > 1) res.answer.intervals.resize(1);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

// The same from a moving pair, with f's coefficients built in power form
// (the setup the tests use; `eccd solve --basis` chooses the setup).
template <class T>
PipelineResult<T> ccd_sampling(const MovingPair3<T>& pair, int N, bool first_contact_only) {
  const T& like = pair.qa[0][0];
  return ccd_sampling(to_bernstein_all(characteristic_of(pair), like), like, N, first_contact_only);
}
template <class T>
PipelineResult<T> ccd_marching(const MovingPair3<T>& pair, int N, bool first_contact_only) {
  const T& like = pair.qa[0][0];
  return ccd_marching(to_bernstein_all(characteristic_of(pair), like), like, N, first_contact_only);
}

}  // namespace eccd

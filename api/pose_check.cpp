// The per-pose mode (see api/pose_check.hpp for the statement).
#include "api/pose_check.hpp"

#include "api/static_status.hpp"
#include "api/sweep_and_prune.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/fast_quartic.hpp"
#include "kernel/keyframe_motion.hpp"
#include "kernel/plane_frame_check.hpp"
#include "kernel/quartic_status.hpp"
#include "kernel/separating_plane.hpp"
#include "number/interval.hpp"
#include "number/rational_traits.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <thread>
#include <unordered_map>

namespace eccd {

namespace {

template <class T>
T enter(const Rational& r) {
  if constexpr (std::is_same_v<T, Interval>)
    return interval_of(r);
  else
    return r;
}

// M' = [[W R D, W c], [0, W]] of one key pose (statement), W·R by kernel/keyframe_motion.hpp's keyframe_rotation
// rule at one τ (3D the quaternion's matrix, 2D [[w² - z², -2wz], [2wz, w² - z²]]).
template <class T, int H>
Matrix<T, H> pose_matrix(const KeyPose& p) {
  constexpr int d = H - 1;
  const T zero = T(0);
  std::array<std::array<T, d>, d> wr;
  T W;
  if constexpr (d == 3) {
    const T w = enter<T>(p.orientation[0]), x = enter<T>(p.orientation[1]), y = enter<T>(p.orientation[2]),
            z = enter<T>(p.orientation[3]);
    const T ww = w * w, xx = x * x, yy = y * y, zz = z * z, two = T(2);
    wr[0] = {ww + xx - yy - zz, two * (x * y - w * z), two * (x * z + w * y)};
    wr[1] = {two * (x * y + w * z), ww - xx + yy - zz, two * (y * z - w * x)};
    wr[2] = {two * (x * z - w * y), two * (y * z + w * x), ww - xx - yy + zz};
    W = ww + xx + yy + zz;
  } else {
    const T w = enter<T>(p.orientation[0]), z = enter<T>(p.orientation[1]), two = T(2);
    wr[0] = {w * w - z * z, zero - two * w * z};
    wr[1] = {two * w * z, w * w - z * z};
    W = w * w + z * z;
  }
  Matrix<T, H> m;
  for (int i = 0; i < d; ++i) {
    for (int j = 0; j < d; ++j) {
      if (!p.deformation) {
        m[i][j] = wr[i][j];
        continue;
      }
      T s = zero;
      for (int k = 0; k < d; ++k) s = s + wr[i][k] * enter<T>((*p.deformation)[k][j]);
      m[i][j] = s;
    }
    m[i][d] = W * enter<T>(p.position[i]);
    m[d][i] = zero;
  }
  m[d][d] = W;
  return m;
}

// x·diag(q)·yᵀ (q diagonal) or x·q·yᵀ: the symmetric product both quadrics need.
template <class T, int H>
Matrix<T, H> sandwich(const Matrix<T, H>& x, const Matrix<T, H>& q, bool diagonal) {
  const T zero = T(0);
  Matrix<T, H> r;
  if (diagonal) {
    for (int i = 0; i < H; ++i)
      for (int j = i; j < H; ++j) {
        T s = zero;
        for (int k = 0; k < H; ++k) s = s + x[i][k] * q[k][k] * x[j][k];
        r[i][j] = s;
        r[j][i] = s;
      }
    return r;
  }
  Matrix<T, H> xq;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      T s = zero;
      for (int k = 0; k < H; ++k) s = s + x[i][k] * q[k][j];
      xq[i][j] = s;
    }
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      T s = zero;
      for (int k = 0; k < H; ++k) s = s + xq[i][k] * x[j][k];
      r[i][j] = s;
    }
  return r;
}

// adj(M')ᵀ, with adj(M') = [[W adj(L), -adj(L) t], [0, det L]] for M' = [[L, t], [0, W]].
template <class T, int H>
Matrix<T, H> adjugate_transposed(const Matrix<T, H>& m) {
  constexpr int d = H - 1;
  const T zero = T(0);
  const T& W = m[d][d];
  std::array<std::array<T, d>, d> adjL;
  T detL;
  if constexpr (d == 3) {
    auto c = [&](int r0, int r1, int c0, int c1) -> T { return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]; };
    adjL[0] = {c(1, 2, 1, 2), zero - c(0, 2, 1, 2), c(0, 1, 1, 2)};
    adjL[1] = {zero - c(1, 2, 0, 2), c(0, 2, 0, 2), zero - c(0, 1, 0, 2)};
    adjL[2] = {c(1, 2, 0, 1), zero - c(0, 2, 0, 1), c(0, 1, 0, 1)};
    detL = m[0][0] * adjL[0][0] + m[0][1] * adjL[1][0] + m[0][2] * adjL[2][0];
  } else {
    adjL[0] = {m[1][1], zero - m[0][1]};
    adjL[1] = {zero - m[1][0], m[0][0]};
    detL = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  }
  Matrix<T, H> nt;  // adj(M')ᵀ
  for (int i = 0; i < d; ++i) {
    T s = zero;
    for (int j = 0; j < d; ++j) {
      nt[j][i] = W * adjL[i][j];
      s = s - adjL[i][j] * m[j][d];
    }
    nt[d][i] = s;
    nt[i][d] = zero;
  }
  nt[d][d] = detL;
  return nt;
}

// The world quadric A = adj(M')ᵀ Q adj(M').
template <class T, int H>
Matrix<T, H> world_at_pose(const Matrix<T, H>& m, const Matrix<T, H>& Q, bool diagonal) {
  return sandwich<T, H>(adjugate_transposed<T, H>(m), Q, diagonal);
}

// b's quadric in a's body frame: Rᵀ Q_b R with R = adj(M'_b) M'_a. With A, B the world quadrics,
// M'_aᵀ (λA - B) M'_a = c λ Q_a - Rᵀ Q_b R, c = det(M'_a)² > 0 (adj(M'_a) M'_a = det(M'_a) I), so
// det(μ Q_a - Rᵀ Q_b R) has the roots c λ: the same signs and multiplicities, hence the same status. In this
// frame a is its own quadric Q_a and nothing depends on where the bodies are in the world, so intervals stay
// narrow where the world quadrics' expansion cancels (bodies away from the origin).
template <class T, int H>
Matrix<T, H> relative_quadric(const Matrix<T, H>& ma, const Matrix<T, H>& mb, const Matrix<T, H>& Qb, bool diag_b) {
  const Matrix<T, H> nt = adjugate_transposed<T, H>(mb);  // adj(M'_b)ᵀ
  const T zero = T(0);
  Matrix<T, H> x;  // Rᵀ = M'_aᵀ adj(M'_b)ᵀ
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      T s = zero;
      for (int k = 0; k < H; ++k) s = s + ma[k][i] * nt[k][j];
      x[i][j] = s;
    }
  return sandwich<T, H>(x, Qb, diag_b);
}

// Does p separate a (negative side) and b (positive side)? Statement, stage 2,
// without forming the dual C = M' adj(Q) M'ᵀ: with q = M'ᵀp, pᵀCp = qᵀ adj(Q) q,
// and (Cp)_d = W (adj(Q) q)_d since M''s last row is (0, .., 0, W). A body
// costs H² + H products instead of C's H³ (the check is per pair and pose).
template <class T, int H>
bool plane_separates(const std::array<double, H>& p, const Matrix<T, H>& ma, const Matrix<T, H>& adjQa, bool diag_a,
                     const Matrix<T, H>& mb, const Matrix<T, H>& adjQb, bool diag_b) {
  constexpr int d = H - 1;
  const T zero = T(0);
  std::array<T, H> pt;
  for (int i = 0; i < H; ++i) {  // a double is exact in both
    if constexpr (std::is_same_v<T, Interval>)
      pt[i] = Interval(p[i], p[i]);
    else
      pt[i] = Rational(p[i]);
  }
  auto test = [&](const Matrix<T, H>& m, const Matrix<T, H>& adjQ, bool diagonal, Sign side) {
    std::array<T, H> q;  // q = M'ᵀp; M'[d][j] = 0 for j < d
    for (int j = 0; j < H; ++j) {
      T s = zero;
      for (int i = 0; i < (j < d ? d : H); ++i) s = s + m[i][j] * pt[i];
      q[j] = s;
    }
    std::array<T, H> aq;  // adj(Q) q
    for (int i = 0; i < H; ++i) {
      if (diagonal) {
        aq[i] = adjQ[i][i] * q[i];
        continue;
      }
      T s = zero;
      for (int j = 0; j < H; ++j) s = s + adjQ[i][j] * q[j];
      aq[i] = s;
    }
    if (sign(T(m[d][d] * aq[d])) != side) return false;
    T f = zero;
    for (int i = 0; i < H; ++i) f = f + q[i] * aq[i];
    return sign(f) == Sign::positive;
  };
  return test(ma, adjQa, diag_a, Sign::negative) && test(mb, adjQb, diag_b, Sign::positive);
}

template <class T, int H>
Status generic_status(const Matrix<T, H>& a, const Matrix<T, H>& b) {
  const T zero = T(0);
  std::vector<T> g = characteristic_coefficients_in<T, H>(a, b, zero);
  if constexpr (H == 3)
    return cubic_contact_status(g[3], g[2], g[1], g[0]);
  else
    return quartic_contact_status(g);
}

// The status of a = Q_a (a's own quadric, diagonal when diag_a) against b given in a's body frame: for a diagonal
// ellipsoid diag(q0, q1, q2, q3), q3 < 0, by 001 Appendix A's closed form (kernel/fast_quartic.hpp) on
// diag(q0, q1, q2, q3) / (-q3) = diag(ea, eb, ec, -1), a positive multiple (the roots scale by -q3 > 0: the same
// status), in 40 products instead of the generic expansion; otherwise the generic expansion.
template <class T, int H>
Status status_in_a_frame(const Matrix<T, H>& qa, bool diag_a, const Matrix<T, H>& b) {
  if constexpr (H == 4) {
    if (diag_a && sign(qa[3][3]) == Sign::negative) {
      const T s = T(0) - qa[3][3];
      const std::array<T, 5> g = appendix_a_coefficients<T>(T(qa[0][0] / s), T(qa[1][1] / s), T(qa[2][2] / s), b);
      return quartic_contact_status(std::span<const T>(g.data(), g.size()));
    }
  }
  return generic_status<T, H>(qa, b);
}

template <int H>
Matrix<double, H> midpoints(const Matrix<Interval, H>& m) {
  Matrix<double, H> r;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) r[i][j] = m[i][j].mid();
  return r;
}
template <int H>
Matrix<double, H> midpoints(const Matrix<Rational, H>& m) {
  Matrix<double, H> r;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) r[i][j] = m[i][j].get_d();
  return r;
}

// 000 section 3 in double; the plane as the array (n, o), or nothing.
template <int H>
std::optional<std::array<double, H>> build_plane(const Matrix<double, H>& a, const Matrix<double, H>& b) {
  PlaneConstruction<double, H> pc = separating_plane<double, H>(a, b);
  if (!pc.ok) return std::nullopt;
  std::array<double, H> p;
  for (int i = 0; i < H; ++i) {
    p[i] = pc.p(i);
    if (!std::isfinite(p[i])) return std::nullopt;
  }
  return p;
}

// Runs f(i) for i in [0, n) on up to `threads` threads (inline for one thread or little work: below 2 grains,
// where starting the threads would cost more than the work; the grains below are set for that, measured on the
// 1,000-body crowd of scripts/measure-scale.py).
template <class F>
void parallel_for(std::size_t n, int threads, std::size_t grain, F&& f) {
  if (threads <= 1 || n < 2 * grain) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  std::mutex m;
  auto work = [&] {
    for (std::size_t start = next.fetch_add(grain); start < n && !failed; start = next.fetch_add(grain)) {
      try {
        for (std::size_t i = start; i < std::min(n, start + grain); ++i) f(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

// Semi-axes of a shape XᵀQX <= 0 that is diagonal (axis-aligned, centred): Q = s·diag(1/a², .., -1), s > 0.
template <int H>
std::optional<std::array<double, H - 1>> diagonal_axes(const std::vector<std::vector<Rational>>& Q) {
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j)
      if (i != j && sgn(Q[i][j]) != 0) return std::nullopt;
  if (sgn(Q[H - 1][H - 1]) >= 0) return std::nullopt;
  std::array<double, H - 1> ax;
  for (int i = 0; i < H - 1; ++i) {
    if (sgn(Q[i][i]) <= 0) return std::nullopt;
    ax[i] = std::sqrt(Rational(-Q[H - 1][H - 1] / Q[i][i]).get_d());
  }
  return ax;
}

// What one body has at the current pose (have: 1 M', 4 A, 8 the rounded pose), valid while stamp matches.
template <int H>
struct BodyCache {
  std::size_t stamp = 0;
  int have = 0;
  bool queued = false;
  Matrix<Interval, H> mi, ai;
  Matrix<Rational, H> mr, ar;
  std::array<std::array<double, H>, H> pose{};
};

struct PairOutcome {
  Status status = Status::uncertain;
  bool by_plane = false, checked_plane = false, built = false, build_failed = false;
  std::optional<std::array<double, 4>> plane;  // the plane kept for the next pose (H entries used)
};

// Per body: Q and adj(Q) (exact and in intervals), the semi-axes when diagonal, the shape radius, and whether Q is
// diagonal (then adj(Q) is diagonal too).
template <int H>
struct BodyShapes {
  std::vector<Matrix<Rational, H>> Qr, adjQr;
  std::vector<Matrix<Interval, H>> Qi, adjQi;
  std::vector<std::optional<std::array<double, H - 1>>> axes;
  std::vector<Rational> radius;
  std::vector<char> diag;
};

template <int H>
BodyShapes<H> body_shapes(const Animation& anim) {
  const std::size_t n = anim.bodies.size();
  BodyShapes<H> s;
  s.Qr.resize(n);
  s.adjQr.resize(n);
  s.Qi.resize(n);
  s.adjQi.resize(n);
  s.axes.resize(n);
  s.radius.resize(n);
  s.diag.resize(n);
  for (std::size_t b = 0; b < n; ++b) {
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) s.Qr[b][i][j] = anim.bodies[b].Q[i][j];
    s.adjQr[b] = adjugate_of<Rational, H>(s.Qr[b], Rational(0));
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        s.Qi[b][i][j] = interval_of(s.Qr[b][i][j]);
        s.adjQi[b][i][j] = interval_of(s.adjQr[b][i][j]);
      }
    s.axes[b] = diagonal_axes<H>(anim.bodies[b].Q);
    s.radius[b] = body_shape_radius(anim, b);
  }
  for (std::size_t b = 0; b < n; ++b) {
    bool dg = true;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) dg = dg && (i == j || sgn(s.Qr[b][i][j]) == 0);
    s.diag[b] = dg;
  }
  return s;
}

// A pair left for stages 2 and 3 at one pose: its bodies and its position in anim.pairs.
struct PairTask {
  std::size_t a, b, pair;
};

// Stage 1 at pose k: bounding spheres in intervals enclosing the exact centre and radius, sweep on x, the sphere
// test. Returns the pairs it could not prove apart, sorted by pair position; fills ps's stage 1 counts.
template <int H>
std::vector<PairTask> bounding_stage(const Animation& anim, const BodyShapes<H>& shapes, std::size_t k,
                                     PoseSummary& ps) {
  constexpr int d = H - 1;
  const std::size_t n = anim.bodies.size();
  const bool all_pairs = anim.pairs.size() == n * (n - 1) / 2;  // then anim.pairs lists every pair in order
  std::vector<std::array<Interval, 3>> centre(n);
  std::vector<Interval> rad(n);
  std::vector<SweepInterval> box(n);
  for (std::size_t b = 0; b < n; ++b) {
    const KeyPose& p = anim.bodies[b].poses[k];
    const Rational& r = shapes.radius[b];
    for (int i = 0; i < d; ++i) centre[b][i] = interval_of(p.position[i]);
    rad[b] = interval_of(keyframe_is_identity(p, d) ? r : Rational(r * key_deformation_bound(p, d)));
    box[b] = {(centre[b][0] - rad[b]).lo, (centre[b][0] + rad[b]).hi};
  }
  std::size_t examined = 0;
  std::vector<std::pair<std::size_t, std::size_t>> swept = sweep_and_prune(box, examined);
  ps.sweep_examined = examined;
  std::vector<PairTask> tasks;
  for (const auto& [a, b] : swept) {
    Interval d2(0), r = rad[a] + rad[b];
    for (int i = 0; i < d; ++i) {
      Interval x = centre[a][i] - centre[b][i];
      d2 = d2 + x * x;
    }
    if (d2 > r * r) continue;  // proved apart at this pose
    std::size_t pos;
    if (all_pairs) {
      pos = a * (2 * n - a - 1) / 2 + (b - a - 1);  // "all": the pairs in the order of bodies
    } else {
      auto it = std::lower_bound(anim.pairs.begin(), anim.pairs.end(), std::make_pair(a, b));
      if (it == anim.pairs.end() || *it != std::make_pair(a, b)) continue;  // not a checked pair
      pos = std::size_t(it - anim.pairs.begin());
    }
    tasks.push_back({a, b, pos});
  }
  std::sort(tasks.begin(), tasks.end(), [](const PairTask& x, const PairTask& y) { return x.pair < y.pair; });
  ps.bounding_volumes = anim.pairs.size() - tasks.size();
  return tasks;
}

// Stages 2 and 3, one pose after the other (each pose's kept planes come from the pose before). Each pass computes
// first (in the run's arithmetic, once per body and pose) only what its pairs need: M' and C for the kept planes'
// checks, then A or the rounded pose for the static tests, then A for the new planes. The scratch is reused from
// pose to pose (no allocation per pose once warm).
template <int H>
class PoseStages {
 public:
  PoseStages(const Animation& anim, const AnimateOptions& opt, const BodyShapes<H>& shapes)
      : anim_(anim),
        opt_(opt),
        shapes_(shapes),
        kind_(opt.solve.arith.kind),
        exact_(kind_ == Arithmetic::Exact),
        fast_double_(kind_ == Arithmetic::Double),
        cache_(anim.bodies.size()) {}

  // Decides the pairs `tasks` at pose k; counts into ps and res, appends the events and undecided pairs to res.
  void run(std::size_t k, const std::vector<PairTask>& tasks, PoseSummary& ps, PosesResult& res) {
    k_ = k;
    tasks_ = &tasks;
    outcome_.assign(tasks.size(), PairOutcome{});
    match_kept_planes();
    stamp_ += 1;
    check_kept_planes();
    static_tests();
    if (opt_.planes) build_planes();
    record(ps, res);
  }

 private:
  using KeptPlane = std::pair<std::size_t, std::array<double, 4>>;  // pair position, plane (sorted by position)

  // plane_of_[t]: the plane kept for task t from the pose before, if any.
  void match_kept_planes() {
    const std::vector<PairTask>& tasks = *tasks_;
    plane_of_.assign(tasks.size(), nullptr);
    if (!opt_.planes || kept_.empty()) return;
    auto it = kept_.begin();  // both sorted by pair position: one merge
    for (std::size_t t = 0; t < tasks.size(); ++t) {
      while (it != kept_.end() && it->first < tasks[t].pair) ++it;
      if (it != kept_.end() && it->first == tasks[t].pair) plane_of_[t] = &it->second;
    }
  }

  // Computes for the bodies of the tasks `which` what they lack of `what` (1 M', 4 A, 8 rounded pose).
  void prepare(const std::vector<std::size_t>& which, int what) {
    const std::vector<PairTask>& tasks = *tasks_;
    todo_.clear();
    for (std::size_t t : which)
      for (std::size_t b : {tasks[t].a, tasks[t].b}) {
        if (cache_[b].stamp != stamp_) {
          cache_[b].stamp = stamp_;
          cache_[b].have = 0;
        }
        if ((cache_[b].have & what) != what && !(cache_[b].queued)) {
          cache_[b].queued = true;
          todo_.push_back(b);
        }
      }
    parallel_for(todo_.size(), opt_.threads, 64, [&](std::size_t u) { complete_body(todo_[u], what); });
    for (std::size_t b : todo_) cache_[b].queued = false;
  }

  void complete_body(std::size_t b, int what) {
    constexpr int d = H - 1;
    BodyCache<H>& c = cache_[b];
    const KeyPose& p = anim_.bodies[b].poses[k_];
    if (!(c.have & 1)) {
      if (exact_)
        c.mr = pose_matrix<Rational, H>(p);
      else
        c.mi = pose_matrix<Interval, H>(p);
      c.have |= 1;
    }
    if ((what & 4) && !(c.have & 4)) {
      if (exact_)
        c.ar = world_at_pose<Rational, H>(c.mr, shapes_.Qr[b], shapes_.diag[b]);
      else
        c.ai = world_at_pose<Interval, H>(c.mi, shapes_.Qi[b], shapes_.diag[b]);
      c.have |= 4;
    }
    if ((what & 8) && !(c.have & 8)) {  // M = M'/W rounded to doubles, for api/static_status.hpp
      c.pose = {};
      for (int i = 0; i < d; ++i)
        for (int j = 0; j <= d; ++j) c.pose[i][j] = (c.mi[i][j] / c.mi[d][d]).mid();
      c.pose[d][d] = 1;
      c.have |= 8;
    }
  }

  // Pass 1: the kept planes (000 section 4: checked first). Leaves in rest_ the tasks they do not settle.
  void check_kept_planes() {
    const std::vector<PairTask>& tasks = *tasks_;
    with_plane_.clear();
    rest_.clear();
    for (std::size_t t = 0; t < tasks.size(); ++t) (plane_of_[t] ? with_plane_ : rest_).push_back(t);
    prepare(with_plane_, 1);
    parallel_for(with_plane_.size(), opt_.threads, 256, [&](std::size_t u) {
      const std::size_t t = with_plane_[u];
      std::array<double, H> p;
      for (int i = 0; i < H; ++i) p[i] = (*plane_of_[t])[i];
      const BodyCache<H>& ca = cache_[tasks[t].a];
      const BodyCache<H>& cb = cache_[tasks[t].b];
      PairOutcome& o = outcome_[t];
      o.checked_plane = true;
      const std::size_t a = tasks[t].a, b = tasks[t].b;
      const bool da = shapes_.diag[a], db = shapes_.diag[b];
      if (exact_ ? plane_separates<Rational, H>(p, ca.mr, shapes_.adjQr[a], da, cb.mr, shapes_.adjQr[b], db)
                 : plane_separates<Interval, H>(p, ca.mi, shapes_.adjQi[a], da, cb.mi, shapes_.adjQi[b], db)) {
        o.status = Status::separate;
        o.by_plane = true;
        o.plane = *plane_of_[t];
      }
    });
    for (std::size_t t : with_plane_)
      if (!outcome_[t].by_plane) rest_.push_back(t);
  }

  // Uses api/static_status.hpp's double test when both shapes are diagonal and the run is in double.
  bool fast_pair(const PairTask& task) const { return fast_double_ && shapes_.axes[task.a] && shapes_.axes[task.b]; }

  // Pass 2: the static test for the tasks in rest_.
  void static_tests() {
    const std::vector<PairTask>& tasks = *tasks_;
    fast_.clear();
    general_.clear();
    for (std::size_t t : rest_) (fast_pair(tasks[t]) ? fast_ : general_).push_back(t);
    prepare(fast_, 1 | 8);
    prepare(general_, 1);
    parallel_for(rest_.size(), opt_.threads, 128,
                 [&](std::size_t u) { outcome_[rest_[u]].status = static_status_of(tasks[rest_[u]]); });
  }

  Status static_status_of(const PairTask& task) const {
    constexpr int d = H - 1;
    const BodyCache<H>& ca = cache_[task.a];
    const BodyCache<H>& cb = cache_[task.b];
    if (exact_)
      return status_in_a_frame<Rational, H>(
          shapes_.Qr[task.a], shapes_.diag[task.a],
          relative_quadric<Rational, H>(ca.mr, cb.mr, shapes_.Qr[task.b], shapes_.diag[task.b]));
    if (fast_pair(task)) {
      const auto& axa = *shapes_.axes[task.a];
      const auto& axb = *shapes_.axes[task.b];
      if constexpr (d == 3)
        return static_status(Ellipsoid{axa, ca.pose}, Ellipsoid{axb, cb.pose}, opt_.solve.arith);
      else
        return static_status(Ellipse{axa, ca.pose}, Ellipse{axb, cb.pose}, opt_.solve.arith);
    }
    const Status status = status_in_a_frame<Interval, H>(
        shapes_.Qi[task.a], shapes_.diag[task.a],
        relative_quadric<Interval, H>(ca.mi, cb.mi, shapes_.Qi[task.b], shapes_.diag[task.b]));
    if (status != Status::uncertain || kind_ != Arithmetic::Certified) return status;
    // Certified: the exact status.
    const auto& pa = anim_.bodies[task.a].poses[k_];
    const auto& pb = anim_.bodies[task.b].poses[k_];
    return generic_status<Rational, H>(
        shapes_.Qr[task.a], relative_quadric<Rational, H>(pose_matrix<Rational, H>(pa), pose_matrix<Rational, H>(pb),
                                                          shapes_.Qr[task.b], shapes_.diag[task.b]));
  }

  // Pass 3: a new plane for each pair found separate (000 section 3), kept for the next pose.
  void build_planes() {
    const std::vector<PairTask>& tasks = *tasks_;
    separate_.clear();
    for (std::size_t t : rest_)
      if (outcome_[t].status == Status::separate) separate_.push_back(t);
    prepare(separate_, 1 | 4);
    parallel_for(separate_.size(), opt_.threads, 16, [&](std::size_t u) {
      const std::size_t t = separate_[u];
      PairOutcome& o = outcome_[t];
      const BodyCache<H>& ca = cache_[tasks[t].a];
      const BodyCache<H>& cb = cache_[tasks[t].b];
      const auto plane = exact_ ? build_plane<H>(midpoints<H>(ca.ar), midpoints<H>(cb.ar))
                                : build_plane<H>(midpoints<H>(ca.ai), midpoints<H>(cb.ai));
      if (plane) {
        std::array<double, 4> p{};
        for (int i = 0; i < H; ++i) p[i] = (*plane)[i];
        o.plane = p;
        o.built = true;
      } else {
        o.build_failed = true;
      }
    });
  }

  // The results in the order of pairs; the planes kept for the next pose.
  void record(PoseSummary& ps, PosesResult& res) {
    const std::vector<PairTask>& tasks = *tasks_;
    next_kept_.clear();
    for (std::size_t t = 0; t < tasks.size(); ++t) {
      const PairTask& task = tasks[t];
      const PairOutcome& o = outcome_[t];
      if (o.plane) next_kept_.emplace_back(task.pair, *o.plane);
      res.plane_checks += o.checked_plane;
      res.planes_built += o.built;
      ps.planes_built += o.built;
      res.plane_build_failed += o.build_failed;
      if (o.by_plane)
        ++ps.separating_plane;
      else
        ++ps.static_test;
      PairPoseStatus st{k_, task.a, task.b, o.status, o.by_plane};
      if (opt_.keep_tested) res.tested.push_back(st);
      if (o.status == Status::uncertain) {
        res.undecided.push_back({k_, task.a, task.b,
                                 "the static test's error bound cannot decide the status at this pose (arithmetic " +
                                     res.arithmetic + ")"});
        ++ps.undecided;
      } else if (in_collision(o.status)) {
        res.events.push_back(st);
        ++ps.events;
      }
    }
    std::swap(kept_, next_kept_);
  }

  const Animation& anim_;
  const AnimateOptions& opt_;
  const BodyShapes<H>& shapes_;
  const Arithmetic::Kind kind_;
  const bool exact_, fast_double_;
  std::vector<BodyCache<H>> cache_;
  std::size_t stamp_ = 0;
  std::size_t k_ = 0;                             // the current pose
  const std::vector<PairTask>* tasks_ = nullptr;  // its pairs past stage 1
  std::vector<KeptPlane> kept_, next_kept_;       // the planes kept from the pose before, and for the next
  std::vector<PairOutcome> outcome_;
  std::vector<const std::array<double, 4>*> plane_of_;
  std::vector<std::size_t> todo_, with_plane_, rest_, separate_, fast_, general_;
};

template <int H>
PosesResult run_poses(const Animation& anim, const AnimateOptions& opt) {
  using SteadyClock = std::chrono::steady_clock;
  const auto t_start = SteadyClock::now();
  PosesResult res;
  res.animation = anim.name;
  res.file = anim.path;
  res.arithmetic = opt.solve.arith.name();
  res.dim = anim.dim;
  res.frames = anim.frames();
  res.poses = anim.times.size();
  res.pairs_per_pose = anim.pairs.size();
  res.times = anim.times;
  res.planes_disabled = !opt.planes;
  for (const auto& b : anim.bodies) res.body_names.push_back(b.name);

  const BodyShapes<H> shapes = body_shapes<H>(anim);
  // Stage 1 for every pose first (poses are independent here: the poses on the threads, each pose on one).
  const std::size_t P = anim.times.size();
  std::vector<std::vector<PairTask>> pose_tasks(P);
  std::vector<PoseSummary> summaries(P);
  parallel_for(P, opt.threads, 1, [&](std::size_t k) {
    const auto t1 = SteadyClock::now();
    PoseSummary& ps = summaries[k];
    ps.pose = k;
    ps.pairs = anim.pairs.size();
    pose_tasks[k] = bounding_stage<H>(anim, shapes, k, ps);
    ps.seconds = std::chrono::duration<double>(SteadyClock::now() - t1).count();
  });
  PoseStages<H> stages(anim, opt, shapes);
  for (std::size_t k = 0; k < P; ++k) {
    const auto t_pose = SteadyClock::now();
    PoseSummary& ps = summaries[k];
    stages.run(k, pose_tasks[k], ps, res);
    ps.seconds += std::chrono::duration<double>(SteadyClock::now() - t_pose).count();
    res.bounding_volumes += ps.bounding_volumes;
    res.separating_plane += ps.separating_plane;
    res.static_test += ps.static_test;
    res.sweep_examined += ps.sweep_examined;
    res.per_pose.push_back(ps);
  }
  res.seconds = std::chrono::duration<double>(SteadyClock::now() - t_start).count();
  return res;
}

}  // namespace

PosesResult animate_poses(const Animation& anim, const AnimateOptions& opt) {
  if (opt.threads < 1) throw std::invalid_argument("--jobs " + std::to_string(opt.threads) + ": expected at least 1");
  const Arithmetic::Kind kind = opt.solve.arith.kind;
  if (kind != Arithmetic::Double && kind != Arithmetic::Exact && kind != Arithmetic::Certified)
    throw std::invalid_argument("--poses: arithmetic " + opt.solve.arith.name() +
                                " is not supported (double, exact or certified)");
  if (opt.shard_count != 1)
    throw std::invalid_argument("--poses: --frame-block is not supported (poses run in one block)");
  if (opt.all_intervals)
    throw std::invalid_argument("--poses: --all-intervals has no meaning at a pose (a status, not intervals)");
  if (anim.dim == 2) return run_poses<3>(anim, opt);
  if (anim.dim == 3) return run_poses<4>(anim, opt);
  throw std::invalid_argument("--poses: dim must be 2 or 3");
}

nlohmann::ordered_json poses_result_to_json(const PosesResult& r) {
  nlohmann::ordered_json j;
  j["format"] = kAnimationAnswerFormat;
  j["animation"] = r.animation;
  j["arith"] = r.arithmetic;
  j["arithmetic"] = r.arithmetic;
  j["frames"] = r.frames;
  j["poses"] = r.poses;
  j["pairs_per_frame"] = r.pairs_per_pose;
  j["mode"] = "poses";
  auto pair = [&](std::size_t a, std::size_t b) {
    return nlohmann::ordered_json::array({r.body_names[a], r.body_names[b]});
  };
  j["events"] = nlohmann::ordered_json::array();
  for (const auto& e : r.events)
    j["events"].push_back({{"pose", e.pose},
                           {"t", r.times[e.pose].get_str()},
                           {"pair", pair(e.body_a, e.body_b)},
                           {"status", to_string(e.status)}});
  j["undecided"] = nlohmann::ordered_json::array();
  for (const auto& u : r.undecided)
    j["undecided"].push_back(
        {{"pose", u.pose}, {"t", r.times[u.pose].get_str()}, {"pair", pair(u.body_a, u.body_b)}, {"why", u.why}});
  j["stages"] = {{"bounding_volumes", r.bounding_volumes},
                 {"separating_plane", r.separating_plane},
                 {"static_test", r.static_test}};
  j["separating_plane_stage"] = r.planes_disabled ? "off" : "built";
  j["planes"] = {{"checked", r.plane_checks},
                 {"kept", r.separating_plane},
                 {"built", r.planes_built},
                 {"build_failed", r.plane_build_failed}};
  j["sweep_examined"] = r.sweep_examined;
  nlohmann::ordered_json pp = nlohmann::ordered_json::array();
  for (const auto& p : r.per_pose)
    pp.push_back({{"pose", p.pose},
                  {"bounding_volumes", p.bounding_volumes},
                  {"separating_plane", p.separating_plane},
                  {"static_test", p.static_test},
                  {"planes_built", p.planes_built},
                  {"events", p.events},
                  {"undecided", p.undecided},
                  {"ms", p.seconds * 1e3}});
  j["per_pose"] = pp;
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace eccd

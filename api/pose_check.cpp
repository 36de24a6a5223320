// The per-pose mode (see api/pose_check.hpp for the statement).
#include "api/pose_check.hpp"

#include "api/static_status.hpp"
#include "api/sweep_and_prune.hpp"
#include "kernel/characteristic_polynomial.hpp"
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

// The dual C = M' adj(Q) M'ᵀ.
template <class T, int H>
Matrix<T, H> dual_at_pose(const Matrix<T, H>& m, const Matrix<T, H>& adjQ, bool diagonal) {
  return sandwich<T, H>(m, adjQ, diagonal);
}

// The world quadric A = adj(M')ᵀ Q adj(M'), adj(M') = [[W adj(L), -adj(L) t], [0, det L]] for M' = [[L, t], [0, W]].
template <class T, int H>
Matrix<T, H> world_at_pose(const Matrix<T, H>& m, const Matrix<T, H>& Q, bool diagonal) {
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
  return sandwich<T, H>(nt, Q, diagonal);
}

// Does p separate a (negative side) and b (positive side)? Statement, stage 2.
template <class T, int H>
bool plane_separates(const std::array<double, H>& p, const Matrix<T, H>& ca, const Matrix<T, H>& cb) {
  const T zero = T(0);
  std::array<T, H> pt;
  for (int i = 0; i < H; ++i) {  // a double is exact in both
    if constexpr (std::is_same_v<T, Interval>)
      pt[i] = Interval(p[i], p[i]);
    else
      pt[i] = Rational(p[i]);
  }
  auto test = [&](const Matrix<T, H>& c, Sign side) {
    std::array<T, H> v;
    for (int i = 0; i < H; ++i) {
      T s = zero;
      for (int j = 0; j < H; ++j) s = s + c[i][j] * pt[j];
      v[i] = s;
    }
    if (sign(v[H - 1]) != side) return false;
    T q = zero;
    for (int i = 0; i < H; ++i) q = q + pt[i] * v[i];
    return sign(q) == Sign::positive;
  };
  return test(ca, Sign::negative) && test(cb, Sign::positive);
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

// What one body has at the current pose (have: 1 M', 2 C, 4 A, 8 the rounded pose), valid while stamp matches.
template <int H>
struct BodyCache {
  std::size_t stamp = 0;
  int have = 0;
  bool queued = false;
  Matrix<Interval, H> mi, ci, ai;
  Matrix<Rational, H> mr, cr, ar;
  std::array<std::array<double, H>, H> pose{};
};

struct PairOutcome {
  Status status = Status::uncertain;
  bool by_plane = false, checked_plane = false, built = false, build_failed = false;
  std::optional<std::array<double, 4>> plane;  // the plane kept for the next pose (H entries used)
};

template <int H>
PosesResult run_poses(const Animation& anim, const AnimateOptions& opt) {
  constexpr int d = H - 1;
  using SteadyClock = std::chrono::steady_clock;
  const auto t_start = SteadyClock::now();
  const Arithmetic::Kind kind = opt.solve.arith.kind;
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

  const std::size_t n = anim.bodies.size();
  // Per body: Q, adj(Q) (exact and in intervals), the shape radius, the semi-axes when diagonal.
  std::vector<Matrix<Rational, H>> Qr(n), adjQr(n);
  std::vector<Matrix<Interval, H>> Qi(n), adjQi(n);
  std::vector<std::optional<std::array<double, H - 1>>> axes(n);
  std::vector<Rational> radius(n);
  for (std::size_t b = 0; b < n; ++b) {
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) Qr[b][i][j] = anim.bodies[b].Q[i][j];
    adjQr[b] = adjugate_of<Rational, H>(Qr[b], Rational(0));
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        Qi[b][i][j] = interval_of(Qr[b][i][j]);
        adjQi[b][i][j] = interval_of(adjQr[b][i][j]);
      }
    axes[b] = diagonal_axes<H>(anim.bodies[b].Q);
    radius[b] = body_shape_radius(anim, b);
  }

  std::vector<char> diag(n);
  for (std::size_t b = 0; b < n; ++b) {
    bool dg = true;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) dg = dg && (i == j || sgn(Qr[b][i][j]) == 0);
    diag[b] = dg;  // then adj(Q) is diagonal too
  }
  std::vector<BodyCache<H>> cache(n);
  std::size_t stamp = 0;
  const bool all_pairs = anim.pairs.size() == n * (n - 1) / 2;      // then anim.pairs lists every pair in order
  using KeptPlane = std::pair<std::size_t, std::array<double, 4>>;  // pair position, plane (sorted by position)
  std::vector<KeptPlane> kept, next_kept;  // the planes kept from the pose before, and for the next
  // Scratch reused from pose to pose (no allocation per pose once warm).
  std::vector<PairOutcome> outcome;
  std::vector<const std::array<double, 4>*> plane_of;
  std::vector<std::size_t> todo, with_plane, rest, separate, fast, general;
  // Stage 1 for every pose first (poses are independent here: the poses on the threads, each pose on one):
  // bounding spheres in intervals enclosing the exact centre and radius, sweep on x, the sphere test.
  struct Task {
    std::size_t a, b, pair;
  };
  const std::size_t P = anim.times.size();
  std::vector<std::vector<Task>> pose_tasks(P);
  std::vector<PoseSummary> summaries(P);
  parallel_for(P, opt.threads, 1, [&](std::size_t k) {
    const auto t1 = SteadyClock::now();
    PoseSummary& ps = summaries[k];
    ps.pose = k;
    ps.pairs = anim.pairs.size();
    std::vector<std::array<Interval, 3>> centre(n);
    std::vector<Interval> rad(n);
    std::vector<SweepInterval> box(n);
    for (std::size_t b = 0; b < n; ++b) {
      const KeyPose& p = anim.bodies[b].poses[k];
      for (int i = 0; i < d; ++i) centre[b][i] = interval_of(p.position[i]);
      rad[b] = interval_of(keyframe_is_identity(p, d) ? radius[b] : Rational(radius[b] * key_deformation_bound(p, d)));
      box[b] = {(centre[b][0] - rad[b]).lo, (centre[b][0] + rad[b]).hi};
    }
    std::size_t examined = 0;
    std::vector<std::pair<std::size_t, std::size_t>> swept = sweep_and_prune(box, examined);
    ps.sweep_examined = examined;
    std::vector<Task>& tasks = pose_tasks[k];
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
    std::sort(tasks.begin(), tasks.end(), [](const Task& x, const Task& y) { return x.pair < y.pair; });
    ps.bounding_volumes = anim.pairs.size() - tasks.size();
    ps.seconds = std::chrono::duration<double>(SteadyClock::now() - t1).count();
  });
  for (std::size_t k = 0; k < P; ++k) {
    const auto t_pose = SteadyClock::now();
    PoseSummary& ps = summaries[k];
    const std::vector<Task>& tasks = pose_tasks[k];
    // Stages 2 and 3 in three passes, each computing first (in the run's arithmetic, once per body and pose) only
    // what its pairs need: M' and C for the kept planes' checks, then A or the rounded pose for the static tests,
    // then A for the new planes.
    const bool exact = kind == Arithmetic::Exact;
    outcome.assign(tasks.size(), PairOutcome{});
    plane_of.assign(tasks.size(), nullptr);
    if (opt.planes && !kept.empty()) {  // both sorted by pair position: one merge
      auto it = kept.begin();
      for (std::size_t t = 0; t < tasks.size(); ++t) {
        while (it != kept.end() && it->first < tasks[t].pair) ++it;
        if (it != kept.end() && it->first == tasks[t].pair) plane_of[t] = &it->second;
      }
    }
    stamp += 1;
    auto prepare = [&](const std::vector<std::size_t>& which, int what) {  // what: 1 M', 2 C, 4 A, 8 rounded pose
      todo.clear();
      for (std::size_t t : which)
        for (std::size_t b : {tasks[t].a, tasks[t].b}) {
          if (cache[b].stamp != stamp) {
            cache[b].stamp = stamp;
            cache[b].have = 0;
          }
          if ((cache[b].have & what) != what && !(cache[b].queued)) {
            cache[b].queued = true;
            todo.push_back(b);
          }
        }
      parallel_for(todo.size(), opt.threads, 64, [&](std::size_t u) {
        BodyCache<H>& c = cache[todo[u]];
        const KeyPose& p = anim.bodies[todo[u]].poses[k];
        const std::size_t b = todo[u];
        if (!(c.have & 1)) {
          if (exact)
            c.mr = pose_matrix<Rational, H>(p);
          else
            c.mi = pose_matrix<Interval, H>(p);
          c.have |= 1;
        }
        if ((what & 2) && !(c.have & 2)) {
          if (exact)
            c.cr = dual_at_pose<Rational, H>(c.mr, adjQr[b], diag[b]);
          else
            c.ci = dual_at_pose<Interval, H>(c.mi, adjQi[b], diag[b]);
          c.have |= 2;
        }
        if ((what & 4) && !(c.have & 4)) {
          if (exact)
            c.ar = world_at_pose<Rational, H>(c.mr, Qr[b], diag[b]);
          else
            c.ai = world_at_pose<Interval, H>(c.mi, Qi[b], diag[b]);
          c.have |= 4;
        }
        if ((what & 8) && !(c.have & 8)) {  // M = M'/W rounded to doubles, for api/static_status.hpp
          c.pose = {};
          for (int i = 0; i < d; ++i)
            for (int j = 0; j <= d; ++j) c.pose[i][j] = (c.mi[i][j] / c.mi[d][d]).mid();
          c.pose[d][d] = 1;
          c.have |= 8;
        }
      });
      for (std::size_t b : todo) cache[b].queued = false;
    };
    // Pass 1: the kept planes (000 section 4: checked first).
    with_plane.clear();
    rest.clear();
    separate.clear();
    for (std::size_t t = 0; t < tasks.size(); ++t) (plane_of[t] ? with_plane : rest).push_back(t);
    prepare(with_plane, 1 | 2);
    parallel_for(with_plane.size(), opt.threads, 256, [&](std::size_t u) {
      const std::size_t t = with_plane[u];
      std::array<double, H> p;
      for (int i = 0; i < H; ++i) p[i] = (*plane_of[t])[i];
      const BodyCache<H>& ca = cache[tasks[t].a];
      const BodyCache<H>& cb = cache[tasks[t].b];
      PairOutcome& o = outcome[t];
      o.checked_plane = true;
      if (exact ? plane_separates<Rational, H>(p, ca.cr, cb.cr) : plane_separates<Interval, H>(p, ca.ci, cb.ci)) {
        o.status = Status::separate;
        o.by_plane = true;
        o.plane = *plane_of[t];
      }
    });
    for (std::size_t t : with_plane)
      if (!outcome[t].by_plane) rest.push_back(t);
    // Pass 2: the static test.
    const bool fast_double = kind == Arithmetic::Double;
    {
      fast.clear();
      general.clear();
      for (std::size_t t : rest) (fast_double && axes[tasks[t].a] && axes[tasks[t].b] ? fast : general).push_back(t);
      prepare(fast, 1 | 8);
      prepare(general, 1 | 4);
    }
    parallel_for(rest.size(), opt.threads, 128, [&](std::size_t u) {
      const std::size_t t = rest[u];
      const Task& task = tasks[t];
      PairOutcome& o = outcome[t];
      const BodyCache<H>& ca = cache[task.a];
      const BodyCache<H>& cb = cache[task.b];
      if (exact) {
        o.status = generic_status<Rational, H>(ca.ar, cb.ar);
      } else if (fast_double && axes[task.a] && axes[task.b]) {
        if constexpr (d == 3)
          o.status =
              static_status(Ellipsoid{*axes[task.a], ca.pose}, Ellipsoid{*axes[task.b], cb.pose}, opt.solve.arith);
        else
          o.status = static_status(Ellipse{*axes[task.a], ca.pose}, Ellipse{*axes[task.b], cb.pose}, opt.solve.arith);
      } else {
        o.status = generic_status<Interval, H>(ca.ai, cb.ai);
        if (o.status == Status::uncertain && kind == Arithmetic::Certified) {  // the exact status
          const auto& pa = anim.bodies[task.a].poses[k];
          const auto& pb = anim.bodies[task.b].poses[k];
          o.status = generic_status<Rational, H>(
              world_at_pose<Rational, H>(pose_matrix<Rational, H>(pa), Qr[task.a], diag[task.a]),
              world_at_pose<Rational, H>(pose_matrix<Rational, H>(pb), Qr[task.b], diag[task.b]));
        }
      }
    });
    // Pass 3: a new plane for each pair found separate (000 section 3), kept for the next pose.
    if (opt.planes) {
      for (std::size_t t : rest)
        if (outcome[t].status == Status::separate) separate.push_back(t);
      prepare(separate, 1 | 4);
      parallel_for(separate.size(), opt.threads, 16, [&](std::size_t u) {
        const std::size_t t = separate[u];
        PairOutcome& o = outcome[t];
        const BodyCache<H>& ca = cache[tasks[t].a];
        const BodyCache<H>& cb = cache[tasks[t].b];
        const auto plane = exact ? build_plane<H>(midpoints<H>(ca.ar), midpoints<H>(cb.ar))
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
    // Results in the order of pairs; the planes kept for the next pose.
    next_kept.clear();
    for (std::size_t t = 0; t < tasks.size(); ++t) {
      const Task& task = tasks[t];
      const PairOutcome& o = outcome[t];
      if (o.plane) next_kept.emplace_back(task.pair, *o.plane);
      res.plane_checks += o.checked_plane;
      res.planes_built += o.built;
      ps.planes_built += o.built;
      res.plane_build_failed += o.build_failed;
      if (o.by_plane)
        ++ps.separating_plane;
      else
        ++ps.static_test;
      PairPoseStatus st{k, task.a, task.b, o.status, o.by_plane};
      if (opt.keep_tested) res.tested.push_back(st);
      if (o.status == Status::uncertain) {
        res.undecided.push_back({k, task.a, task.b,
                                 "the static test's error bound cannot decide the status at this pose (arithmetic " +
                                     res.arithmetic + ")"});
        ++ps.undecided;
      } else if (in_collision(o.status)) {
        res.events.push_back(st);
        ++ps.events;
      }
    }
    std::swap(kept, next_kept);
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

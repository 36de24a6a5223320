// Animations (see api/animate.hpp for the statement).
#include "api/animate.hpp"

#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"
#include "kernel/keyframe_motion.hpp"

#if __has_include("api/separate.hpp")
#include "api/separate.hpp"
#define ECCD_ANIMATE_PLANES 1
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <thread>

namespace eccd {

namespace {

using Vec = std::vector<Rational>;

// A rational >= sqrt(x) (x >= 0): exact when x is the square of a rational,
// otherwise ceil(sqrt(x)·2^40)/2^40 rounded up.
Rational sqrt_upper(const Rational& x) {
  if (sgn(x) <= 0) return Rational(0);
  mpz_class n = x.get_num(), d = x.get_den();
  if (mpz_perfect_square_p(n.get_mpz_t()) && mpz_perfect_square_p(d.get_mpz_t())) {
    mpz_class rn, rd;
    mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
    mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
    return Rational(rn, rd);
  }
  // s = floor(sqrt(floor(x·2^80))) satisfies s² <= x·2^80 < (s + 1)², so (s + 1)/2^40 > sqrt(x).
  mpz_class scaled = (n << 80) / d;  // floor
  mpz_class s;
  mpz_sqrt(s.get_mpz_t(), scaled.get_mpz_t());
  Rational r(s + 1, mpz_class(1) << 40);
  r.canonicalize();
  return r;
}

// A rational bound on |x| over the solid X^T Q X <= 0 (x in the body's frame):
// Q = [[A, b], [b^T, c]], centre x0 = −A⁻¹b, solid (x − x0)^T A (x − x0) <= κ
// with κ = −b·x0 − c; |x − x0|² <= κ/λ_min(A) <= κ·max_i (A⁻¹)_ii for a
// diagonal A, κ·tr(A⁻¹) otherwise.
Rational shape_radius(const std::vector<std::vector<Rational>>& Q, int dim) {
  // A⁻¹ by Gauss-Jordan (A is positive definite: pivots on the diagonal are positive).
  std::vector<Vec> a(dim, Vec(2 * dim, Rational(0)));
  for (int i = 0; i < dim; ++i) {
    for (int j = 0; j < dim; ++j) a[i][j] = Q[i][j];
    a[i][dim + i] = 1;
  }
  for (int c = 0; c < dim; ++c) {
    int p = c;
    while (p < dim && sgn(a[p][c]) == 0) ++p;
    if (p == dim) throw std::logic_error("animate: a shape matrix with a singular quadratic part");
    std::swap(a[p], a[c]);
    Rational inv = 1 / a[c][c];
    for (auto& x : a[c]) x *= inv;
    for (int r = 0; r < dim; ++r)
      if (r != c && sgn(a[r][c]) != 0) {
        Rational f = a[r][c];
        for (int j = 0; j < 2 * dim; ++j) a[r][j] -= f * a[c][j];
      }
  }
  bool diagonal = true;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) diagonal = diagonal && (i == j || sgn(Q[i][j]) == 0);
  Vec x0(dim, Rational(0));
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) x0[i] -= a[i][dim + j] * Q[j][dim];
  Rational kappa = -Q[dim][dim];
  for (int i = 0; i < dim; ++i) kappa -= Q[i][dim] * x0[i];
  Rational s = 0;
  for (int i = 0; i < dim; ++i) s = diagonal ? std::max(s, a[i][dim + i]) : s + a[i][dim + i];
  Rational c2 = 0;
  for (const auto& x : x0) c2 += x * x;
  return sqrt_upper(c2) + sqrt_upper(kappa * s);
}

// A bound on ‖D‖₂ at a key: 1 for the identity, else ‖D‖_F rounded up.
Rational deformation_bound(const KeyPose& p, int dim) {
  if (keyframe_is_identity(p, dim)) return Rational(1);
  Rational f = 0;
  for (const auto& row : *p.deformation)
    for (const auto& x : row) f += x * x;
  return sqrt_upper(f);
}

// The answer's instants in global time t = t0 + τ·dt (dt > 0), exactly.
Instant to_global(const Instant& in, const Rational& t0, const Rational& dt, int float_digits) {
  if (in.certified()) {
    Rational lo = t0 + *in.lo * dt, hi = t0 + *in.hi * dt;
    return bracketed_instant((lo + hi) / 2, lo, hi);
  }
  Instant out = in;
  try {
    Rational tau = parse_rational(in.approx);
    Rational t = t0 + tau * dt;
    out.approx = decimal_string(t, float_digits);
    out.value = nearest_double(t);
  } catch (const std::invalid_argument&) {  // "nan", "inf": kept as the pipeline wrote it
    out.value = t0.get_d() + in.value * dt.get_d();
  }
  return out;
}
Answer to_global(const Answer& a, const Rational& t0, const Rational& dt, int digits) {
  Answer g = a;
  auto map = [&](const Instant& i) { return to_global(i, t0, dt, digits); };
  for (auto& [s, e] : g.intervals) {
    s = map(s);
    e = map(e);
  }
  if (g.first_contact) g.first_contact = map(*g.first_contact);
  for (auto& c : g.contacts) c = map(c);
  for (auto& [s, e] : g.contact_intervals) {
    s = map(s);
    e = map(e);
  }
  for (auto& u : g.undecided) u = map(u);
  return g;
}

// First-contact mode: the first collision interval, as the 3D pipeline's
// first_contact gives it (kernel/ccd_projection.hpp); the contacts and
// undecided instants stay (each is true of the frame).
void first_interval_only(Answer& a) {
  if (a.intervals.size() > 1) a.intervals.resize(1);
}

struct PairTask {
  std::size_t a = 0, b = 0, pair = 0;  // bodies and the position in Animation::pairs
};
struct TaskResult {
  bool plane_settled = false;
  Solution solution;
  bool solved = false;
  std::string budget_why;  // exact: a budget ran out
  std::exception_ptr error;
};

}  // namespace

Scene pair_frame_scene(const Animation& anim, std::size_t i, std::size_t j, std::size_t k) {
  if (i >= anim.bodies.size() || j >= anim.bodies.size() || i == j)
    throw std::invalid_argument("pair_frame_scene: bodies " + std::to_string(i) + " and " + std::to_string(j) + " of " +
                                std::to_string(anim.bodies.size()));
  if (k >= anim.frames())
    throw std::invalid_argument("pair_frame_scene: frame " + std::to_string(k) + " of " +
                                std::to_string(anim.frames()));
  const AnimationBody& A = anim.bodies[i];
  const AnimationBody& B = anim.bodies[j];
  Scene s;
  s.path = anim.path;
  s.name = anim.name + "/frame-" + std::to_string(k) + "/" + A.name + "--" + B.name;
  s.note = "frame " + std::to_string(k) + " of animation " + anim.name + ": local time tau = (t - " +
           anim.times[k].get_str() + ") / (" + anim.times[k + 1].get_str() + " - " + anim.times[k].get_str() + ")";
  s.dim = anim.dim;
  s.a = SceneObject{A.Q, keyframe_motion(A.poses[k], A.poses[k + 1], anim.dim)};
  s.b = SceneObject{B.Q, keyframe_motion(B.poses[k], B.poses[k + 1], anim.dim)};
  return s;
}

BoundingSphere swept_bounding_sphere(const Animation& anim, std::size_t body, std::size_t k) {
  const AnimationBody& b = anim.bodies.at(body);
  const KeyPose& p0 = b.poses.at(k);
  const KeyPose& p1 = b.poses.at(k + 1);
  BoundingSphere s;
  Rational half2 = 0;
  for (int i = 0; i < anim.dim; ++i) {
    s.centre.push_back((p0.position[i] + p1.position[i]) / 2);
    Rational h = (p1.position[i] - p0.position[i]) / 2;
    half2 += h * h;
  }
  s.radius = sqrt_upper(half2) +
             shape_radius(b.Q, anim.dim) * std::max(deformation_bound(p0, anim.dim), deformation_bound(p1, anim.dim));
  return s;
}

KeptPlaneCheck::KeptPlaneCheck(const Animation& anim) {
  if (anim.dim != 3) return;
  const B like(1.0, 0);
  auto conv = [&](const Rational& q) { return scalar_traits<B>::from_rational(q, like); };
  for (const AnimationBody& body : anim.bodies) {
    Matrix<Rational, 4> q;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) q[i][j] = body.Q.at(i).at(j);
    const Matrix<Rational, 4> adj = adjugate_of<Rational, 4>(q, Rational(0));  // exact, then rounded once
    std::array<std::array<B, 4>, 4> a;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) a[i][j] = conv(adj[i][j]);
    adj_.push_back(a);
    bool rigid = true;
    std::vector<Key> keys;
    for (std::size_t n = 0; n < body.poses.size(); ++n) {
      const KeyPose& p = body.poses[n];
      rigid = rigid && keyframe_is_identity(p, 3);
      Key k;
      for (int i = 0; i < 4; ++i) k.q[i] = conv(p.orientation[i]);
      for (int i = 0; i < 3; ++i) k.c[i] = conv(p.position[i]);
      if (n + 1 < body.poses.size()) {  // keyframe_motion's q1 for the frame from this key
        const std::vector<Rational> o = shorter_way(p.orientation, body.poses[n + 1].orientation);
        for (int i = 0; i < 4; ++i) k.q_next[i] = conv(o[i]);
      }
      keys.push_back(k);
    }
    keys_.push_back(std::move(keys));
    rigid_.push_back(rigid);
  }
  ok_ = true;
}

KeptPlaneCheck::Plane KeptPlaneCheck::prepare(const std::vector<Rational>& normal, const Rational& offset) const {
  const B like(1.0, 0);
  Plane p;
  for (int i = 0; i < 3; ++i) p[i] = i < int(normal.size()) ? scalar_traits<B>::from_rational(normal[i], like) : B(0);
  p[3] = scalar_traits<B>::from_rational(offset, like);
  return p;
}

FrameSides KeptPlaneCheck::check(const Plane& plane, std::size_t i, std::size_t j, std::size_t k) const {
  if (!ok_ || !rigid_.at(i) || !rigid_.at(j)) return FrameSides::unknown;
  auto body = [&](std::size_t b) {
    KeyframeBody3<B> kb;
    kb.adj = &adj_[b];
    const Key &k0 = keys_[b].at(k), &k1 = keys_[b].at(k + 1);
    kb.q0 = k0.q;
    kb.q1 = k0.q_next;
    kb.c0 = k0.c;
    kb.c1 = k1.c;
    return kb;
  };
  return keyframe_plane_check(plane, body(i), body(j));
}

Rational body_shape_radius(const Animation& anim, std::size_t body) {
  return shape_radius(anim.bodies.at(body).Q, anim.dim);
}
Rational key_deformation_bound(const KeyPose& pose, int dim) { return deformation_bound(pose, dim); }

namespace {

// The result's header: what was run, on what.
AnimationResult result_header(const Animation& anim, const AnimateOptions& opt) {
  AnimationResult res;
  res.animation = anim.name;
  res.file = anim.path;
  res.arithmetic = opt.solve.arith.name();
  res.dim = anim.dim;
  res.frames = anim.frames();
  res.pairs_per_frame = anim.pairs.size();
  for (const auto& b : anim.bodies) res.body_names.push_back(b.name);
  res.shard_index = opt.shard_index;
  res.shard_count = opt.shard_count;
  res.all_intervals = opt.all_intervals;
#ifdef ECCD_ANIMATE_PLANES
  res.plane_stage_built = opt.planes;
#endif
  res.planes_disabled = !opt.planes;
  return res;
}

// The options of stage 3's solve of one pair-frame.
SolveOptions frame_solve_options(const Animation& anim, const AnimateOptions& opt) {
  SolveOptions so = opt.solve;
  if (opt.all_intervals) {
    so.first_contact = false;
    so.variant = Variant::answer;
  } else {
    so.first_contact = anim.dim == 3;  // 2D: cut to the first interval below (first_interval_only)
    so.variant = Variant::answer;
  }
  return so;
}

// Stage 1 on frame k: bounding spheres, sweep-and-prune on x, then the exact sphere test. Returns the pairs it
// could not prove apart, in the order of pairs (pair_index[a][b]: the position of pair (a, b), or -1).
std::vector<PairTask> frame_bounding_stage(const Animation& anim, const std::vector<std::vector<long>>& pair_index,
                                           std::size_t k) {
  const std::size_t n = anim.bodies.size();
  std::vector<BoundingSphere> sph;
  for (std::size_t b = 0; b < n; ++b) sph.push_back(swept_bounding_sphere(anim, b, k));
  std::vector<std::size_t> order(n);
  for (std::size_t b = 0; b < n; ++b) order[b] = b;
  std::vector<Rational> lo(n), hi(n);
  for (std::size_t b = 0; b < n; ++b) {
    lo[b] = sph[b].centre[0] - sph[b].radius;
    hi[b] = sph[b].centre[0] + sph[b].radius;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return lo[x] < lo[y] || (lo[x] == lo[y] && x < y); });
  std::vector<PairTask> tasks;
  for (std::size_t u = 0; u < n; ++u) {
    const std::size_t x = order[u];
    for (std::size_t v = u + 1; v < n && lo[order[v]] <= hi[x]; ++v) {
      const std::size_t y = order[v];
      const std::size_t a = std::min(x, y), b = std::max(x, y);
      if (pair_index[a][b] < 0) continue;
      Rational d2 = 0;
      for (int i = 0; i < anim.dim; ++i) {
        Rational d = sph[a].centre[i] - sph[b].centre[i];
        d2 += d * d;
      }
      Rational r = sph[a].radius + sph[b].radius;
      if (d2 > r * r) continue;  // proved apart over the whole frame
      tasks.push_back({a, b, std::size_t(pair_index[a][b])});
    }
  }
  std::sort(tasks.begin(), tasks.end(), [](const PairTask& x, const PairTask& y) { return x.pair < y.pair; });
  return tasks;
}

// Where a pair-frame's task is: frame_tasks[frame_pos][task_pos].
struct Slot {
  std::size_t frame_pos = 0, task_pos = 0;
};

// Stage 2's state along one pair's frames: the plane kept from the last frame that found it.
struct KeptPlaneState {
#ifdef ECCD_ANIMATE_PLANES
  std::optional<SeparatingPlane> plane;
  KeptPlaneCheck::Plane prepared{};
  std::size_t frame = 0;  // the frame position after which `plane` may be checked
#endif
};

// Stages 2 and 3, pair by pair (a pair's frames in order, so that the plane kept from frame k - 1 is at hand in
// frame k), pairs on a pool of threads; results stored by (frame, position), so nothing depends on the schedule.
class PairFrameStages {
 public:
  PairFrameStages(const Animation& anim, const AnimateOptions& opt, const SolveOptions& so, std::size_t first,
                  const std::vector<std::vector<PairTask>>& frame_tasks)
      : anim_(anim), opt_(opt), so_(so), first_(first), frame_tasks_(frame_tasks) {
    out_.resize(frame_tasks.size());
    task_seconds_.resize(frame_tasks.size());
    for (std::size_t f = 0; f < frame_tasks.size(); ++f) {
      out_[f].resize(frame_tasks[f].size());
      task_seconds_[f].resize(frame_tasks[f].size());
    }
#ifdef ECCD_ANIMATE_PLANES
    // Stage 2's interval check from prepared numbers: double and certified runs (a proof in intervals is one
    // there); exact and MPFR runs check in their own arithmetic only.
    if (opt.planes && anim.dim == 3 && (so.arith.kind == Arithmetic::Double || so.arith.kind == Arithmetic::Certified))
      fast_planes_.emplace(anim);
#endif
  }

  // Runs every pair-frame on opt.threads threads, the longest pairs first; reports to opt.progress.
  void run() {
    std::vector<std::vector<Slot>> by_pair(anim_.pairs.size());
    std::size_t total = 0;
    for (std::size_t f = 0; f < frame_tasks_.size(); ++f)
      for (std::size_t t = 0; t < frame_tasks_[f].size(); ++t) {
        by_pair[frame_tasks_[f][t].pair].push_back({f, t});
        ++total;
      }
    std::vector<std::size_t> work_pairs;
    for (std::size_t p = 0; p < by_pair.size(); ++p)
      if (!by_pair[p].empty()) work_pairs.push_back(p);
    std::stable_sort(work_pairs.begin(), work_pairs.end(), [&](std::size_t x, std::size_t y) {
      return by_pair[x].size() > by_pair[y].size();
    });  // longest first
    std::atomic<std::size_t> next{0};
    auto work = [&]() {
      for (std::size_t w = next++; w < work_pairs.size() && !failed_; w = next++) run_pair(by_pair[work_pairs[w]]);
    };
    const std::size_t nthreads = std::min<std::size_t>(std::size_t(opt_.threads), work_pairs.size());
    std::vector<std::thread> pool;
    for (std::size_t w = 0; w < nthreads; ++w) pool.emplace_back(work);
    if (opt_.progress) {  // the calling thread reports while the pool works
      while (done_ < total && !failed_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        opt_.progress(done_, total);
      }
    }
    for (auto& th : pool) th.join();
    if (opt_.progress) opt_.progress(done_, total);
  }

  TaskResult& result(std::size_t f, std::size_t t) { return out_[f][t]; }
  double seconds(std::size_t f, std::size_t t) const { return task_seconds_[f][t]; }

 private:
  // One pair's frames in order; stops at the first error anywhere.
  void run_pair(const std::vector<Slot>& slots) {
    using SteadyClock = std::chrono::steady_clock;
    KeptPlaneState kept;
    for (const Slot& slot : slots) {
      const PairTask& task = frame_tasks_[slot.frame_pos][slot.task_pos];
      TaskResult& r = out_[slot.frame_pos][slot.task_pos];
      const auto t0 = SteadyClock::now();
      try {
        run_pair_frame(task, slot.frame_pos, r, kept);
      } catch (...) {
        r.error = std::current_exception();
        failed_ = true;
      }
      task_seconds_[slot.frame_pos][slot.task_pos] = std::chrono::duration<double>(SteadyClock::now() - t0).count();
      ++done_;
      if (failed_) break;
    }
  }

  // The pair-frame's scene, built when a stage needs it.
  const Scene& scene_of(std::optional<Scene>& built, const PairTask& task, std::size_t k) const {
    if (!built) built = pair_frame_scene(anim_, task.a, task.b, k);
    return *built;
  }

  void run_pair_frame(const PairTask& task, std::size_t frame_pos, TaskResult& r, KeptPlaneState& kept) {
    const std::size_t k = first_ + frame_pos;
    std::optional<Scene> built;
#ifdef ECCD_ANIMATE_PLANES
    // Only a plane from the frame just before (a frame dropped by stage 1 in between forgets it).
    if (opt_.planes && kept.plane && kept.frame + 1 == frame_pos && kept_separates(kept, task, k, built)) {
      r.plane_settled = true;
      kept.frame = frame_pos;  // checked on this frame; the next frame checks it again
      return;
    }
    kept.plane.reset();
#else
    (void)kept;
#endif
    const Scene& scene = scene_of(built, task, k);
    try {
      r.solution = solve(scene, so_);
      if (!opt_.all_intervals) first_interval_only(r.solution.answer);
      r.solved = true;
    } catch (const BudgetExhausted& e) {
      r.budget_why = std::string("resource budget exhausted: ") + e.what();
    }
#ifdef ECCD_ANIMATE_PLANES
    if (opt_.planes && r.solved && !r.solution.answer.collides && r.solution.decided())
      keep_plane(scene, frame_pos, kept);
#endif
  }

#ifdef ECCD_ANIMATE_PLANES
  bool kept_separates(const KeptPlaneState& kept, const PairTask& task, std::size_t k,
                      std::optional<Scene>& built) const {
    const FrameSides f = fast_planes_ ? fast_planes_->check(kept.prepared, task.a, task.b, k) : FrameSides::unknown;
    if (f != FrameSides::unknown) return f == FrameSides::separates;
    return plane_separates_on_frame(scene_of(built, task, k), *kept.plane, so_) == PlaneCheck::separates;
  }

  // A plane separating the pair at the frame's end, kept for the next frame.
  void keep_plane(const Scene& scene, std::size_t frame_pos, KeptPlaneState& kept) const {
    Separation sep = separate_at(scene, Rational(1), so_);
    if (sep.status == "separate" && sep.plane) {
      kept.plane = sep.plane;
      if (fast_planes_) kept.prepared = fast_planes_->prepare(kept.plane->normal, kept.plane->offset);
      kept.frame = frame_pos;
    }
  }
#endif

  const Animation& anim_;
  const AnimateOptions& opt_;
  const SolveOptions& so_;
  const std::size_t first_;
  const std::vector<std::vector<PairTask>>& frame_tasks_;
  std::vector<std::vector<TaskResult>> out_;
  std::vector<std::vector<double>> task_seconds_;
#ifdef ECCD_ANIMATE_PLANES
  std::optional<KeptPlaneCheck> fast_planes_;
#endif
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> failed_{false};
};

// Why a solved pair-frame's answer is undecided: the solver's reasons and the undecided instants.
std::string undecided_why(const TaskResult& r, const PairFrameAnswer& pa) {
  std::string why;
  for (const auto& w : r.solution.undecided_reasons) why += (why.empty() ? "" : "; ") + w;
  if (why.empty()) why = "undecided instants in the answer";
  std::string at;
  for (const auto& u : pa.answer.undecided) at += (at.empty() ? "" : ", ") + u.approx;
  if (!at.empty()) why += " (at t ~ " + at + ")";
  return why;
}

// The answers of frame k (position f), in the order of pairs, into fs and res.
void record_frame(const Animation& anim, const AnimateOptions& opt, int float_digits, std::size_t k, std::size_t f,
                  const std::vector<PairTask>& tasks, PairFrameStages& stages, FrameSummary& fs, AnimationResult& res) {
  const Rational dt = anim.times[k + 1] - anim.times[k];
  for (std::size_t t = 0; t < tasks.size(); ++t) {
    const PairTask& task = tasks[t];
    TaskResult& r = stages.result(f, t);
    if (r.error) std::rethrow_exception(r.error);
    fs.seconds += stages.seconds(f, t);
    if (r.plane_settled) {
      ++fs.separating_plane;
      continue;
    }
    ++fs.continuous_test;
    if (!r.solved) {
      res.undecided.push_back({k, task.a, task.b, r.budget_why});
      ++fs.undecided;
      continue;
    }
    PairFrameAnswer pa{k, task.a, task.b, to_global(r.solution.answer, anim.times[k], dt, float_digits),
                       r.solution.answer};
    if (opt.keep_tested) res.tested.push_back(pa);
    if (!r.solution.decided()) {
      res.undecided.push_back({k, task.a, task.b, undecided_why(r, pa)});
      ++fs.undecided;
    } else if (r.solution.answer.collides) {
      res.events.push_back(std::move(pa));
      ++fs.events;
    }
  }
}

}  // namespace

AnimationResult animate(const Animation& anim, const AnimateOptions& opt) {
  if (opt.threads < 1)
    throw std::invalid_argument("--threads " + std::to_string(opt.threads) + ": expected at least 1");
  if (opt.shard_count < 1 || opt.shard_index >= opt.shard_count)
    throw std::invalid_argument("--shard " + std::to_string(opt.shard_index) + "/" + std::to_string(opt.shard_count) +
                                ": expected i/n with 0 <= i < n");
  using SteadyClock = std::chrono::steady_clock;
  const auto t_start = SteadyClock::now();
  AnimationResult res = result_header(anim, opt);
  const SolveOptions so = frame_solve_options(anim, opt);
  const int float_digits = opt.solve.arith.kind == Arithmetic::Mpfr ? precision_digits(opt.solve.arith.mpfr_bits) : 17;

  const std::size_t n = anim.bodies.size();
  std::vector<std::vector<long>> pair_index(n, std::vector<long>(n, -1));
  for (std::size_t p = 0; p < anim.pairs.size(); ++p) pair_index[anim.pairs[p].first][anim.pairs[p].second] = long(p);

  const std::size_t F = anim.frames();
  const std::size_t first = F * opt.shard_index / opt.shard_count, last = F * (opt.shard_index + 1) / opt.shard_count;

  // Stage 1, frame by frame.
  std::vector<FrameSummary> summary;
  std::vector<std::vector<PairTask>> frame_tasks;  // per frame, in the order of pairs
  for (std::size_t k = first; k < last; ++k) {
    const auto t_frame = SteadyClock::now();
    FrameSummary fs;
    fs.frame = k;
    fs.pairs = anim.pairs.size();
    std::vector<PairTask> tasks = frame_bounding_stage(anim, pair_index, k);
    fs.bounding_volumes = anim.pairs.size() - tasks.size();
    fs.seconds = std::chrono::duration<double>(SteadyClock::now() - t_frame).count();
    summary.push_back(fs);
    frame_tasks.push_back(std::move(tasks));
  }

  // Stages 2 and 3.
  PairFrameStages stages(anim, opt, so, first, frame_tasks);
  stages.run();

  // The answers, frame by frame in the order of pairs.
  for (std::size_t f = 0; f < frame_tasks.size(); ++f) {
    FrameSummary& fs = summary[f];
    record_frame(anim, opt, float_digits, first + f, f, frame_tasks[f], stages, fs, res);
    res.bounding_volumes += fs.bounding_volumes;
    res.separating_plane += fs.separating_plane;
    res.continuous_test += fs.continuous_test;
    res.per_frame.push_back(fs);
  }
  res.seconds = std::chrono::duration<double>(SteadyClock::now() - t_start).count();
  return res;
}

namespace {
// animation-format.md: "With a floating arithmetic the instants carry no lo/hi" (the scene answer writes null).
void drop_null_brackets(nlohmann::ordered_json& j) {
  if (j.is_object()) {
    if (j.contains("approx"))
      for (const char* k : {"lo", "hi"})
        if (j.contains(k) && j[k].is_null()) j.erase(k);
    for (auto& [key, v] : j.items()) drop_null_brackets(v);
  } else if (j.is_array()) {
    for (auto& v : j) drop_null_brackets(v);
  }
}
}  // namespace

nlohmann::ordered_json animation_result_to_json(const AnimationResult& r) {
  nlohmann::ordered_json j;
  j["format"] = kAnimationAnswerFormat;
  j["animation"] = r.animation;
  j["arith"] = r.arithmetic;       // the key every other eccd JSON object uses (eccd solve --json)
  j["arithmetic"] = r.arithmetic;  // the same: the key the animation answer format names (docs/animation-format.md)
  j["frames"] = r.frames;
  j["pairs_per_frame"] = r.pairs_per_frame;
  j["mode"] = r.all_intervals ? "all-intervals" : "first-contact";
  auto pair = [&](std::size_t a, std::size_t b) {
    return nlohmann::ordered_json::array({r.body_names[a], r.body_names[b]});
  };
  j["events"] = nlohmann::ordered_json::array();
  for (const auto& e : r.events) {
    nlohmann::ordered_json ev;
    ev["frame"] = e.frame;
    ev["pair"] = pair(e.body_a, e.body_b);
    ev["answer"] = nlohmann::ordered_json::parse(answer_to_json(e.answer).dump());
    drop_null_brackets(ev["answer"]);
    ev["local_answer"] =
        nlohmann::ordered_json::parse(answer_to_json(e.local).dump());  // in τ (the pair-frame's scene)
    drop_null_brackets(ev["local_answer"]);
    j["events"].push_back(ev);
  }
  j["undecided"] = nlohmann::ordered_json::array();
  for (const auto& u : r.undecided)
    j["undecided"].push_back({{"frame", u.frame}, {"pair", pair(u.body_a, u.body_b)}, {"why", u.why}});
  j["stages"] = {{"bounding_volumes", r.bounding_volumes},
                 {"separating_plane", r.separating_plane},
                 {"continuous_test", r.continuous_test}};
  j["separating_plane_stage"] = r.planes_disabled ? "off" : r.plane_stage_built ? "built" : "not built";
  if (r.shard_count > 1) j["shard"] = std::to_string(r.shard_index) + "/" + std::to_string(r.shard_count);
  nlohmann::ordered_json pf = nlohmann::ordered_json::array();
  for (const auto& f : r.per_frame)
    pf.push_back({{"frame", f.frame},
                  {"bounding_volumes", f.bounding_volumes},
                  {"separating_plane", f.separating_plane},
                  {"continuous_test", f.continuous_test},
                  {"events", f.events},
                  {"undecided", f.undecided},
                  {"ms", f.seconds * 1e3}});
  j["per_frame"] = pf;
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace eccd

// Static tests from a scene at an instant or from two poses (api/static_status.hpp).
#include "api/static_status.hpp"

#include "api/static_filter_simd.hpp"

#include "floating/rounded_input.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "kernel/fast_quartic.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/quartic_sign_status.hpp"
#include "kernel/quartic_status.hpp"
#include "kernel/static_filter3d.hpp"
#include "number/forward_bound.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "number/mpfr_real.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace eccd {

// Here, not in api/static_filter_simd.cpp: this check must run on any CPU.
bool simd::has_avx512() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool ok = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return ok;
#else
  return false;
#endif
}

bool simd::has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool ok = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return ok;
#else
  return false;
#endif
}

namespace {
simd::Isa g_isa_limit = simd::Isa::avx512;
}  // namespace

const char* simd::to_string(Isa isa) {
  return isa == Isa::avx512 ? "avx512" : isa == Isa::avx2 ? "avx2" : "none (pair by pair)";
}
simd::Isa simd::cpu_isa() { return has_avx512() ? Isa::avx512 : has_avx2() ? Isa::avx2 : Isa::none; }
simd::Isa simd::static_batch_isa() { return std::min(cpu_isa(), g_isa_limit); }
void simd::set_static_batch_isa_limit(Isa limit) { g_isa_limit = limit; }

namespace {

template <class T, int N>
using Mat = std::array<std::array<T, N>, N>;

// The status from f's coefficients g_0..g_{N-1} (increasing powers of λ).
template <class T, std::size_t K>
Status status_of(const std::array<T, K>& g) {
  if constexpr (K == 4)
    return cubic_contact_status(g[3], g[2], g[1], g[0]);
  else
    return quartic_contact_status(g);
}

// ---- the scene at an instant ------------------------------------------------

template <class T, int N>
Status scene_status(const MovingPair<T, N>& m, const T& t) {
  std::vector<Poly<T>> g = characteristic_of(m);
  std::array<T, N + 1> v;
  for (int i = 0; i <= N; ++i) v[i] = g[i].is_zero() ? t - t : g[i](t);
  return status_of(v);
}

template <int N>
Status scene_status_in(const Scene& scene, const mpq_class& t, const Arithmetic& arith) {
  if (arith.kind == Arithmetic::Exact || arith.kind == Arithmetic::Certified) {
    PreparedPair<N> p = prepare_pair<N>(scene);
    if (arith.kind == Arithmetic::Certified) {  // intervals of doubles enclosing the exact motions first
      Status s = scene_status<Interval, N>(to_arithmetic<Interval, N>(p, Interval(0)), interval_of(Rational(t)));
      if (s != Status::uncertain) return s;
    }
    return scene_status<Rational, N>(to_arithmetic<Rational, N>(p, Rational(1)), Rational(t));
  }
  auto rounded = [&](const auto& like) {
    using T = std::decay_t<decltype(like)>;
    std::string trouble;
    MovingPair<T, N> m = round_pair<T, N>(scene, like, trouble);
    if (!trouble.empty()) return Status::uncertain;  // a value that is not finite decides nothing
    return scene_status<T, N>(m, scalar_traits<T>::from_rational(t, like));
  };
  if (arith.kind == Arithmetic::Double) return rounded(Bounded<double>(1.0, 0));
  return rounded(Bounded<Mpfr>(Mpfr(mpq_class(1), arith.mpfr_bits), 0));
}

// ---- two shapes at two poses ------------------------------------------------

template <int N>
[[gnu::noinline, gnu::cold]] void check_shape_failed(const std::array<double, N - 1>& axes, const Mat<double, N>& pose,
                                                     const char* which) {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument(std::string("static test: object ") + which + ": " + what);
  };
  for (double a : axes)
    if (!(a > 0) || !std::isfinite(a)) fail("semi-axis " + std::to_string(a) + " is not a positive finite number");
  for (const auto& row : pose)
    for (double x : row)
      if (!std::isfinite(x)) fail("the pose has an entry that is not finite");
  for (int j = 0; j < N; ++j)
    if (pose[N - 1][j] != (j == N - 1 ? 1.0 : 0.0)) fail("the pose is not affine (its last row must be 0 ... 0 1)");
  fail("the pose is singular (its linear part has determinant 0)");
}

// Validation in one pass without a branch per entry (a branch per entry costs 10 % of the double test): x * 0 is 0 for
// every finite x and NaN otherwise, so one sum says whether all are finite; the message is built only on failure.
template <int N>
void check_shape(const std::array<double, N - 1>& axes, const Mat<double, N>& pose, const char* which) {
  double z = 0;
  bool ok = true;
#pragma GCC unroll 16
  for (double a : axes) {
    z += a * 0.0;
    ok &= a > 0;
  }
#pragma GCC unroll 16
  for (const auto& row : pose)
#pragma GCC unroll 16
    for (double x : row) z += x * 0.0;
#pragma GCC unroll 16
  for (int j = 0; j < N; ++j) ok &= pose[N - 1][j] == (j == N - 1 ? 1.0 : 0.0);
  if (!(ok & (z == 0))) check_shape_failed<N>(axes, pose, which);
  // Singular linear part: a cheap double determinant first, the exact one only when that is 0.
  auto det = [](const auto& m) -> std::decay_t<decltype(m[0][0])> {
    if constexpr (N == 3)
      return m[0][0] * m[1][1] - m[0][1] * m[1][0];
    else
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  if (det(pose) == 0) {
    Mat<Rational, N> q;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) q[i][j] = Rational(pose[i][j]);
    if (Rational(det(q)) == 0) check_shape_failed<N>(axes, pose, which);
  }
}

template <class T>
T from_double(double x) {
  if constexpr (std::is_same_v<T, Rational>)
    return Rational(x);
  else if constexpr (std::is_same_v<T, ForwardBound>)
    return ForwardBound::exact(x);
  else
    return T(x, 0);  // Bounded<double>: the given double is exact
}

// adj of the affine pose M = [R t; 0 1] in block form: N = [adj(R), -adj(R) t; 0, det R],
// so that N M = det(R) I (a positive multiple of M^-1 up to the sign of det R,
// which the quadric Nᵀ Q N squares away). R is not singular (check_shape).
template <class T, int N>
[[gnu::always_inline]] inline Mat<T, N> affine_adjugate(const Mat<double, N>& pose) {
  Mat<T, N> m;
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i)
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j) m[i][j] = from_double<T>(pose[i][j]);
  Mat<T, N> n;
  T det;
  if constexpr (N == 3) {
    n[0][0] = m[1][1];
    n[0][1] = -m[0][1];
    n[1][0] = -m[1][0];
    n[1][1] = m[0][0];
    det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  } else {
    auto c = [&](int r0, int r1, int c0, int c1) -> T { return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]; };
    n[0][0] = c(1, 2, 1, 2);
    n[0][1] = -c(0, 2, 1, 2);
    n[0][2] = c(0, 1, 1, 2);
    n[1][0] = -c(1, 2, 0, 2);
    n[1][1] = c(0, 2, 0, 2);
    n[1][2] = -c(0, 1, 0, 2);
    n[2][0] = c(1, 2, 0, 1);
    n[2][1] = -c(0, 2, 0, 1);
    n[2][2] = c(0, 1, 0, 1);
    det = m[0][0] * n[0][0] + m[0][1] * n[1][0] + m[0][2] * n[2][0];
  }
  constexpr int d = N - 1;
#pragma GCC unroll 16
  for (int i = 0; i < d; ++i) {
    T s = m[0][0] - m[0][0];
#pragma GCC unroll 16
    for (int k = 0; k < d; ++k) s = s - n[i][k] * m[k][d];
    n[i][d] = s;
    n[d][i] = m[0][0] - m[0][0];
  }
  n[d][d] = det;
  return n;
}

template <class T, int N>
[[gnu::always_inline]] inline Mat<T, N> shape_matrix(const std::array<double, N - 1>& axes) {
  Mat<T, N> q;
  const T zero = from_double<T>(0), one = from_double<T>(1);
#pragma GCC unroll 16
  for (auto& row : q) row.fill(zero);
#pragma GCC unroll 16
  for (int i = 0; i < N - 1; ++i) {
    if constexpr (std::is_same_v<T, ForwardBound>)
      q[i][i] = ForwardBound::inverse_square_leaf(axes[i]);
    else {
      T a = from_double<T>(axes[i]);
      q[i][i] = one / (a * a);
    }
  }
  q[N - 1][N - 1] = zero - one;
  return q;
}

// Exact: world quadrics and the generic expansion of det(λA - B).
template <int N>
Status exact_pose_status(const std::array<double, N - 1>& axes_a, const Mat<double, N>& pose_a,
                         const std::array<double, N - 1>& axes_b, const Mat<double, N>& pose_b) {
  const Rational zero(0);
  auto world = [&](const std::array<double, N - 1>& axes, const Mat<double, N>& pose) {
    return moving_quadric_in<Rational, Rational, N>(shape_matrix<Rational, N>(axes), affine_adjugate<Rational, N>(pose),
                                                    zero);
  };
  std::vector<Rational> g =
      characteristic_coefficients_in<Rational, N>(world(axes_a, pose_a), world(axes_b, pose_b), zero);
  std::array<Rational, N + 1> v;
  for (int i = 0; i <= N; ++i) v[i] = g[i];
  return status_of(v);
}

// Double: a in standard position, b relative to it; 001 Appendix A in 3D.
// T = ForwardBound (the fast path: a-priori bound, signs of Δ and Descartes,
// kernel/quartic_sign_status.hpp) or Bounded<double> (running bound, Sturm).
// pose_coefficients: f's coefficients g_0..g_{N-1}; straight-line code for
// ForwardBound (the batch loop below vectorises it across pairs).
template <int N, class T>
[[gnu::always_inline]] inline std::array<T, N + 1> pose_coefficients(const std::array<double, N - 1>& axes_a,
                                                                     const Mat<double, N>& pose_a,
                                                                     const std::array<double, N - 1>& axes_b,
                                                                     const Mat<double, N>& pose_b) {
  const T zero = from_double<T>(0.0);
  Mat<T, N> nb = affine_adjugate<T, N>(pose_b);
  Mat<T, N> r;  // adj(M_b) M_a: b's frame relative to a's; affine, so its last row is (0 ... 0 det R_b)
#pragma GCC unroll 16
  for (int i = 0; i < N - 1; ++i)
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j) {
      T s = zero;
#pragma GCC unroll 16
      for (int k = 0; k < N; ++k)
        if (std::is_same_v<T, ForwardBound> || pose_a[k][j] != 0) s = s + nb[i][k] * from_double<T>(pose_a[k][j]);
      r[i][j] = s;
    }
#pragma GCC unroll 16
  for (int j = 0; j < N; ++j) r[N - 1][j] = j == N - 1 ? nb[N - 1][N - 1] : zero;
  // b = Rᵀ Q_b R with Q_b diagonal: b_ij = sum_k q_k r_ki r_kj (40 products in 3D, not 128).
  Mat<T, N> qb = shape_matrix<T, N>(axes_b), b;
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i)
#pragma GCC unroll 16
    for (int j = i; j < N; ++j) {
      T s = zero;
#pragma GCC unroll 16
      for (int k = 0; k < N - 1; ++k) s = s + qb[k][k] * r[k][i] * r[k][j];
      if (i == N - 1 && j == N - 1)
        s = s + qb[N - 1][N - 1] * r[N - 1][N - 1] * r[N - 1][N - 1];  // the last row's one entry
      b[i][j] = s;
      b[j][i] = s;
    }
  Mat<T, N> qa = shape_matrix<T, N>(axes_a);
  if constexpr (N == 4) {
    return appendix_a_coefficients(qa[0][0], qa[1][1], qa[2][2], b);
  } else {
    // det(λ diag(d1, d2, d3) - b), the 3x3 analogue of Appendix A.
    const T &d1 = qa[0][0], &d2 = qa[1][1], &d3 = qa[2][2];
    const T &b11 = b[0][0], &b12 = b[0][1], &b13 = b[0][2], &b22 = b[1][1], &b23 = b[1][2], &b33 = b[2][2];
    T m1 = b22 * b33 - b23 * b23, m2 = b11 * b33 - b13 * b13, m3 = b11 * b22 - b12 * b12;
    T det = b11 * m1 - b12 * (b12 * b33 - b13 * b23) + b13 * (b12 * b23 - b13 * b22);
    return std::array<T, 4>{zero - det, d1 * m1 + d2 * m2 + d3 * m3,
                            zero - (d1 * d2 * b33 + d1 * d3 * b22 + d2 * d3 * b11), d1 * d2 * d3};
  }
}

// The status from the coefficients: the sign rules (ForwardBound: Δ and
// Descartes; Bounded<double>: the Sturm count in 3D, 003 Theorem 6 in 2D).
template <class T, std::size_t K>
Status coefficient_status(const std::array<T, K>& g) {
  if constexpr (K == 5 && std::is_same_v<T, ForwardBound>)
    return quartic_sign_status(g);
  else
    return status_of(g);
}

template <class T, std::size_t K>
[[gnu::flatten]] Status fast_coefficient_status(const std::array<T, K>& g) {
  return coefficient_status(g);
}

template <int N, class T>
Status double_pose_status(const std::array<double, N - 1>& axes_a, const Mat<double, N>& pose_a,
                          const std::array<double, N - 1>& axes_b, const Mat<double, N>& pose_b) {
  return coefficient_status(pose_coefficients<N, T>(axes_a, pose_a, axes_b, pose_b));
}

// The double test: the fast ForwardBound path, and where it cannot decide
// (Δ within its bound of 0, e.g. the positive double root of symmetric
// shapes) the running-bound Sturm test, which decides some of those.
// The fast path as one function: flatten inlines the whole straight-line
// program (the ForwardBound operations, Appendix A, Δ), which the compiler
// otherwise leaves as calls passing 24-byte values through memory.
// In 3D the plain-double program with static bounds (kernel/static_filter3d.hpp), flattened into one
// function (value and magnitude side by side in SSE2 registers: number/static_bound.hpp's ValueMagnitude). The
// same compiled for AVX-512 + FMA measured slower for one pair (84 against 62 ns/pair, /tmp micro-benchmark,
// loaded machine), so only the batch's lanes use api/static_filter_simd.hpp.
[[gnu::flatten]] Status fast_status3(const std::array<double, 3>& axes_a, const Mat<double, 4>& pose_a,
                                     const std::array<double, 3>& axes_b, const Mat<double, 4>& pose_b) {
  return static_filter3d(axes_a, pose_a, axes_b, pose_b);
}

template <int N>
[[gnu::flatten]] Status fast_pose_status(const std::array<double, N - 1>& axes_a, const Mat<double, N>& pose_a,
                                         const std::array<double, N - 1>& axes_b, const Mat<double, N>& pose_b) {
  if constexpr (N == 4)
    return fast_status3(axes_a, pose_a, axes_b, pose_b);
  else
    return double_pose_status<N, ForwardBound>(axes_a, pose_a, axes_b, pose_b);
}

template <int N>
Status double_pose_status_filtered(const std::array<double, N - 1>& axes_a, const Mat<double, N>& pose_a,
                                   const std::array<double, N - 1>& axes_b, const Mat<double, N>& pose_b) {
  Status s = fast_pose_status<N>(axes_a, pose_a, axes_b, pose_b);
  return s != Status::uncertain ? s : double_pose_status<N, Bounded<double>>(axes_a, pose_a, axes_b, pose_b);
}

// Where the fast path is uncertain: the running-bound test, then (certified) the exact one.
template <int N>
Status after_fast(const std::array<double, N - 1>& axes_a, const Mat<double, N>& pose_a,
                  const std::array<double, N - 1>& axes_b, const Mat<double, N>& pose_b, const Arithmetic& arith) {
  Status s = double_pose_status<N, Bounded<double>>(axes_a, pose_a, axes_b, pose_b);
  return s != Status::uncertain || arith.kind != Arithmetic::Certified
             ? s
             : exact_pose_status<N>(axes_a, pose_a, axes_b, pose_b);
}

template <int N>
Status pose_status(const std::array<double, N - 1>& axes_a, const Mat<double, N>& pose_a,
                   const std::array<double, N - 1>& axes_b, const Mat<double, N>& pose_b, const Arithmetic& arith) {
  if constexpr (N == 4) {
    // The 3D filter first: a status from it implies valid input (finite, semi-axes >= 2^-12, both linear parts
    // non-singular: kernel/static_filter3d.hpp), so the full validation runs only when it is uncertain; the
    // filter does not read the last rows, which are checked here.
    auto affine = [](const Mat<double, 4>& m) {
      return (m[3][0] == 0) & (m[3][1] == 0) & (m[3][2] == 0) & (m[3][3] == 1);
    };
    if ((arith.kind == Arithmetic::Double || arith.kind == Arithmetic::Certified) && affine(pose_a) && affine(pose_b)) {
      Status s = fast_status3(axes_a, pose_a, axes_b, pose_b);
      if (s != Status::uncertain) return s;
      check_shape<N>(axes_a, pose_a, "a");
      check_shape<N>(axes_b, pose_b, "b");
      return after_fast<N>(axes_a, pose_a, axes_b, pose_b, arith);
    }
  }
  check_shape<N>(axes_a, pose_a, "a");
  check_shape<N>(axes_b, pose_b, "b");
  switch (arith.kind) {
    case Arithmetic::Double:
      return double_pose_status_filtered<N>(axes_a, pose_a, axes_b, pose_b);
    case Arithmetic::Exact:
      return exact_pose_status<N>(axes_a, pose_a, axes_b, pose_b);
    case Arithmetic::Certified: {  // the filtered predicate: double with its error bound, exact only when it cannot
                                   // decide
      Status s = double_pose_status_filtered<N>(axes_a, pose_a, axes_b, pose_b);
      return s != Status::uncertain ? s : exact_pose_status<N>(axes_a, pose_a, axes_b, pose_b);
    }
    default:
      throw std::invalid_argument("static test from two poses: arithmetic " + arith.name() +
                                  " is not offered (double or exact)");
  }
}

// One block of the batch: the lanes' inputs in structure of arrays (a short
// last block repeats its first pair), then f's coefficients with their
// a-priori bounds for every lane in one straight-line loop (vectorised).
template <int N, class Shape>
[[gnu::flatten]] void coefficient_block(const Shape* a, const Shape* b, int lanes,
                                        double (&gv)[N + 1][kStaticBatchLanes], double (&gm)[N + 1][kStaticBatchLanes],
                                        double (&gd)[N + 1][kStaticBatchLanes]) {
  constexpr int L = kStaticBatchLanes;
  // Structure of arrays: the block's inputs lane by lane (a short last block repeats its first pair).
  double axa[N - 1][L], axb[N - 1][L], ma[N][N][L], mb[N][N][L];
  for (int l = 0; l < L; ++l) {
    const Shape& sa = a[l < lanes ? l : 0];
    const Shape& sb = b[l < lanes ? l : 0];
    for (int k = 0; k < N - 1; ++k) {
      axa[k][l] = sa.semi_axes[k];
      axb[k][l] = sb.semi_axes[k];
    }
    for (int r = 0; r < N; ++r)
      for (int c = 0; c < N; ++c) {
        ma[r][c][l] = sa.pose[r][c];
        mb[r][c][l] = sb.pose[r][c];
      }
  }
  // The vectorised loop: straight-line code over the lanes.
  for (int l = 0; l < L; ++l) {
    std::array<double, N - 1> xa, xb;
    Mat<double, N> pa, pb;
#pragma GCC unroll 16
    for (int k = 0; k < N - 1; ++k) {
      xa[k] = axa[k][l];
      xb[k] = axb[k][l];
    }
#pragma GCC unroll 16
    for (int r = 0; r < N; ++r)
#pragma GCC unroll 16
      for (int c = 0; c < N; ++c) {
        pa[r][c] = ma[r][c][l];
        pb[r][c] = mb[r][c][l];
      }
    std::array<ForwardBound, N + 1> g = pose_coefficients<N, ForwardBound>(xa, pa, xb, pb);
#pragma GCC unroll 16
    for (int k = 0; k <= N; ++k) {
      gv[k][l] = g[k].value();
      gm[k][l] = g[k].magnitude();
      gd[k][l] = g[k].depth();
    }
  }
}

// The batch: validation first (nothing written on a bad pair), then blocks of
// kStaticBatchLanes pairs: the coefficients of every lane in one loop (SoA
// lanes g[k][lane]: value, magnitude, depth), then the sign rule per lane.
template <int N, class Shape>
void pose_status_batch(std::span<const Shape> a, std::span<const Shape> b, std::span<Status> out,
                       const Arithmetic& arith) {
  if (a.size() != b.size() || a.size() != out.size())
    throw std::invalid_argument("static_status_batch: the spans have different sizes (" + std::to_string(a.size()) +
                                ", " + std::to_string(b.size()) + ", " + std::to_string(out.size()) + ")");
  auto validate = [&](std::size_t i) {
    try {
      check_shape<N>(a[i].semi_axes, a[i].pose, "a");
      check_shape<N>(b[i].semi_axes, b[i].pose, "b");
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("static_status_batch: pair " + std::to_string(i) + ": " + e.what());
    }
  };
  const std::size_t n = a.size();
  if constexpr (N == 4) {
    const simd::Isa isa = simd::static_batch_isa();
    if ((arith.kind == Arithmetic::Double || arith.kind == Arithmetic::Certified) && isa != simd::Isa::none) {
      // Blocks of lanes in structure of arrays, vectorised (AVX-512, or AVX2). A status from the filter
      // implies valid input (kernel/static_filter3d.hpp; the last rows are checked here), so only the pairs it leaves
      // uncertain are validated in full; the codes wait in `codes` until every pair is known valid (nothing written
      // before).
      constexpr int SL = simd::kSimdLanes;
      std::vector<double> codes(n);
      for (std::size_t base = 0; base < n; base += SL) {
        const int lanes = int(std::min<std::size_t>(SL, n - base));
        double in[kStaticInputs][SL], code[SL];
        bool affine[SL];
        for (int l = 0; l < SL; ++l) {  // a short last block repeats its first pair
          const Shape& sa = a[base + (l < lanes ? l : 0)];
          const Shape& sb = b[base + (l < lanes ? l : 0)];
          for (int j = 0; j < 3; ++j) {
            in[static_axis_a(j)][l] = sa.semi_axes[j];
            in[static_axis_b(j)][l] = sb.semi_axes[j];
            for (int c = 0; c < 4; ++c) {
              in[static_pose_a(j, c)][l] = sa.pose[j][c];
              in[static_pose_b(j, c)][l] = sb.pose[j][c];
            }
          }
          affine[l] = (sa.pose[3][0] == 0) & (sa.pose[3][1] == 0) & (sa.pose[3][2] == 0) & (sa.pose[3][3] == 1) &
                      (sb.pose[3][0] == 0) & (sb.pose[3][1] == 0) & (sb.pose[3][2] == 0) & (sb.pose[3][3] == 1);
        }
        if (isa == simd::Isa::avx512)
          simd::static_filter3d_lanes_avx512(in, code);
        else
          simd::static_filter3d_lanes_avx2(in, code);
        for (int l = 0; l < lanes; ++l) {
          codes[base + l] = affine[l] ? code[l] : 0.0;
          if (codes[base + l] == 0.0) validate(base + l);
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        Status s = static_filter_status(codes[i]);
        out[i] =
            s != Status::uncertain ? s : after_fast<N>(a[i].semi_axes, a[i].pose, b[i].semi_axes, b[i].pose, arith);
      }
      return;
    }
  }
  for (std::size_t i = 0; i < n; ++i) validate(i);
  if (arith.kind != Arithmetic::Double && arith.kind != Arithmetic::Certified) {
    for (std::size_t i = 0; i < n; ++i)
      out[i] = pose_status<N>(a[i].semi_axes, a[i].pose, b[i].semi_axes, b[i].pose, arith);
    return;
  }
  constexpr int L = kStaticBatchLanes;
  if constexpr (N == 4) {
    for (std::size_t i = 0; i < n; ++i) {  // pair by pair: without AVX2 the lanes do not vectorise
      Status s = fast_status3(a[i].semi_axes, a[i].pose, b[i].semi_axes, b[i].pose);
      out[i] = s != Status::uncertain ? s : after_fast<N>(a[i].semi_axes, a[i].pose, b[i].semi_axes, b[i].pose, arith);
    }
    return;
  }
  for (std::size_t base = 0; base < n; base += L) {
    const int lanes = int(std::min<std::size_t>(L, n - base));
    double gv[N + 1][L], gm[N + 1][L], gd[N + 1][L];
    coefficient_block<N, Shape>(a.data() + base, b.data() + base, lanes, gv, gm, gd);
    for (int l = 0; l < lanes; ++l) {
      std::array<ForwardBound, N + 1> g;
      for (int k = 0; k <= N; ++k) g[k] = ForwardBound(gv[k][l], gm[k][l], gd[k][l]);
      Status s = fast_coefficient_status(g);
      const std::size_t i = base + l;
      if (s == Status::uncertain) s = after_fast<N>(a[i].semi_axes, a[i].pose, b[i].semi_axes, b[i].pose, arith);
      out[i] = s;
    }
  }
}

}  // namespace

void static_status_batch(std::span<const Ellipsoid> a, std::span<const Ellipsoid> b, std::span<Status> out,
                         const Arithmetic& arith) {
  pose_status_batch<4>(a, b, out, arith);
}
void static_status_batch(std::span<const Ellipse> a, std::span<const Ellipse> b, std::span<Status> out,
                         const Arithmetic& arith) {
  pose_status_batch<3>(a, b, out, arith);
}

Status status_at(const Scene& scene, const mpq_class& t, const Arithmetic& arith) {
  if (t < 0 || t > 1) throw std::invalid_argument("status_at: t = " + t.get_str() + " is outside [0, 1]");
  // A cycloidal scene (2D): the static test of f(λ;t) at t, with g_i(t) enclosed (kernel/cycloidal_motion.hpp):
  // Bounded double / MPFR (uncertain where the error bound covers a sign), or MPFI for certified. Exact refuses.
  if (scene.dim == 2 && has_cycloidal_motion(scene) && arith.kind != Arithmetic::Exact) {
    auto in = [&](const auto& like) {
      using T = std::decay_t<decltype(like)>;
      auto g = cycloidal_g<T>(cycloidal_pair<T>(scene, like), scalar_traits<T>::from_rational(t, like));
      return cubic_contact_status(g[3], g[2], g[1], g[0]);
    };
    if (arith.kind == Arithmetic::Double) return in(Bounded<double>(1.0, 0));
    if (arith.kind == Arithmetic::Mpfr) return in(Bounded<Mpfr>(Mpfr(mpq_class(1), arith.mpfr_bits), 0));
    return in(MpfiInterval(mpq_class(0), arith.mpfi_rungs.empty() ? 128 : arith.mpfi_rungs.back()));
  }
  return scene.dim == 3 ? scene_status_in<4>(scene, t, arith) : scene_status_in<3>(scene, t, arith);
}

Status static_status(const Ellipse& a, const Ellipse& b, const Arithmetic& arith) {
  return pose_status<3>(a.semi_axes, a.pose, b.semi_axes, b.pose, arith);
}

Status static_status(const Ellipsoid& a, const Ellipsoid& b, const Arithmetic& arith) {
  return pose_status<4>(a.semi_axes, a.pose, b.semi_axes, b.pose, arith);
}

}  // namespace eccd

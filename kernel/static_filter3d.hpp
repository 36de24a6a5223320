#pragma once
// The static test of two ellipsoids from two poses in plain double with
// a-priori error bounds: a straight-line program with no bound
// object inside it, its magnitude run and a depth fixed at compile time
// (number/static_bound.hpp), then the sign rule. It says `uncertain` where a
// bound cannot decide (touching, near-touching, symmetric shapes, inputs
// outside the ranges below); the caller then takes the running-bound path.
//
// Statement. 001 section 3 / 002 Theorem 1 as in kernel/quartic_sign_status.hpp:
// with f(λ) = det(λA - B) the ellipsoids are separate iff f has two distinct
// negative roots, touch iff a negative double root, overlap otherwise.
// Formulation (no division, no inverse): an ellipsoid with semi-axes s and
// affine pose M = [L t; 0 1] is the image of the unit ball x^T J x <= 0,
// J = diag(1, 1, 1, -1), under M' = M S, S = diag(s1, s2, s3, 1) (the columns
// of L scaled by the semi-axes). In a's unit frame (X = M'_a Y) a is J and
// b is R^T J R with R = adj(M'_b) M'_a = [N L'_a, N (t_a - t_b); 0, det L'_b],
// N = adj(L'_b): a positive multiple of the true relative quadric, and a
// positive multiple of B or a congruence changes neither the signs nor the
// multiplicities of f's roots. So f(λ) = det(λ J - b) (001 Appendix A with
// ea = eb = ec = 1, kernel/fast_quartic.hpp), b_ij = Σ_{k<3} R_ki R_kj, and
// b_44 = Σ_k R_k4² - det².
// Bounds. The program runs three times (number/static_bound.hpp): values,
// magnitudes M_k of g_k and the depths d_k (compile time), so
//   |ĝ_k - g_k| <= e_k = 2 d_k u M_k + τ
// where g_k is f's exact coefficient for the given doubles. τ covers
// underflow. Ranges (else `uncertain`): every pose entry |x| <= 2^12 and every
// semi-axis in [2^-12, 2^12]. Then an entry of L' = L S is a product of two
// leaves <= 2^12, every monomial of every g_k is a product of leaves bounded
// by 2^576 (g_1..g_3: at most 3 entries of b, each R·R, each R at most 3
// factors of L' or t, so <= 2^432; g_0 = -(det L'_a det³)²: 24 entries of L'),
// the program's expansion has fewer than 2^42 monomials (R: <= 12, b: <= 468,
// g_1: fewer than 2^5 · 468^3, g_0: 6^8) and fewer than 2^9 products. A product that underflows
// errs by at most 2^-1075 absolutely and that error reaches g_k multiplied by
// at most the rest of a monomial (<= 2^576) for each monomial through it, so
// all of them together stay below 2^(9 + 42 + 576 - 1075 + 1) = 2^-447:
// τ = 2^-430. (Nothing overflows in range: M_k <= 2^618.)
// Sign rule: every |ĝ_k| > e_k (else uncertain). Descartes on f(-λ):
// g4, -g3, g2, -g1, g0 with 0 sign changes -> no negative root -> overlapping.
// Otherwise the discriminant Δ on the ĝ_k as fresh leaves, exactly as in
// kernel/quartic_sign_status.hpp: ρ = max e_k / |ĝ_k| <= 2^-20, then
// |computed Δ - Δ(g)| <= m (2 d_Δ u + 7 ρ) with m Δ's magnitude run on |ĝ|;
// Δ < 0 -> overlapping; Δ > 0 with 2 changes -> separate; anything else
// uncertain. Underflow in Δ: every |ĝ_k| in [2^-150, 2^150] (else uncertain),
// so every product's magnitude is >= 2^-900 and an underflow's 2^-1075 is
// below 2^-175 of it (inside the factor 2); no overflow below 2^900 · 2^10.
// A status implies valid input: the ranges exclude infinities, semi-axes
// below 2^-12 and non-positive ones; a NaN input (which passes one pair's
// max/min range test) is a factor of some monomial of g_1..g_3, so some ĝ_k
// is NaN and no sign is certain; and |ĝ_0| > e_0 makes the exact g_0 =
// -(det L'_a det³)² non-zero, so both linear parts are non-singular. The last
// rows of the poses (0 0 0 1) are not read: the caller checks them.
// The lane form (static_filter3d_lanes) is the same program over arrays of
// doubles, one lane per pair, no branch and no call in the loop, so the
// compiler vectorises it; its status per lane is computed with selects.
// Requirements: plain double inputs (the semi-axes, the top three rows of
// the poses; the last row (0 0 0 1) is checked by the caller).
#include "kernel/contact_status.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/fast_quartic.hpp"
#include "number/lane_vector.hpp"
#include "number/static_bound.hpp"

#include <array>
#include <cmath>
#include <cstdint>

namespace eccd {

// The inputs of one pair: index of a's semi-axis j, a's pose entry (i, j) (rows 0..2), and b's likewise.
inline constexpr int kStaticInputs = 30;
constexpr int static_axis_a(int j) { return j; }
constexpr int static_pose_a(int i, int j) { return 3 + 4 * i + j; }
constexpr int static_axis_b(int j) { return 15 + j; }
constexpr int static_pose_b(int i, int j) { return 18 + 4 * i + j; }

// f's coefficients g_0..g_4 (increasing powers of λ) in the unit-ball formulation; leaf(k) gives input k as T.
template <class T, class Leaf>
[[gnu::always_inline]] constexpr std::array<T, 5> unit_ball_coefficients(Leaf leaf) {
  T la[3][3], lb[3][3], dt[3];
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i) {
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      la[i][j] = leaf(static_pose_a(i, j)) * leaf(static_axis_a(j));
      lb[i][j] = leaf(static_pose_b(i, j)) * leaf(static_axis_b(j));
    }
    dt[i] = leaf(static_pose_a(i, 3)) - leaf(static_pose_b(i, 3));
  }
  T n[3][3];  // adj(L'_b)
  n[0][0] = lb[1][1] * lb[2][2] - lb[1][2] * lb[2][1];
  n[0][1] = lb[0][2] * lb[2][1] - lb[0][1] * lb[2][2];
  n[0][2] = lb[0][1] * lb[1][2] - lb[0][2] * lb[1][1];
  n[1][0] = lb[1][2] * lb[2][0] - lb[1][0] * lb[2][2];
  n[1][1] = lb[0][0] * lb[2][2] - lb[0][2] * lb[2][0];
  n[1][2] = lb[0][2] * lb[1][0] - lb[0][0] * lb[1][2];
  n[2][0] = lb[1][0] * lb[2][1] - lb[1][1] * lb[2][0];
  n[2][1] = lb[0][1] * lb[2][0] - lb[0][0] * lb[2][1];
  n[2][2] = lb[0][0] * lb[1][1] - lb[0][1] * lb[1][0];
  T det = lb[0][0] * n[0][0] + lb[0][1] * n[1][0] + lb[0][2] * n[2][0];
  T r[3][4];
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i) {
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) r[i][j] = n[i][0] * la[0][j] + n[i][1] * la[1][j] + n[i][2] * la[2][j];
    r[i][3] = n[i][0] * dt[0] + n[i][1] * dt[1] + n[i][2] * dt[2];
  }
  std::array<std::array<T, 4>, 4> b;
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i)
#pragma GCC unroll 4
    for (int j = i; j < 4; ++j) {
      T s = r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
      if (i == 3 && j == 3) s = s - det * det;
      b[i][j] = s;
      b[j][i] = s;
    }
  const T one(1);
  std::array<T, 5> g = appendix_a_coefficients(one, one, one, b);
  // g_0 = det(-b) = det(J) det(R)^2 = -(det L'_a · det³)^2, since det R = det(N L'_a) det = det³ det L'_a: a
  // short product instead of Appendix A's 4x4 cofactor expansion, whose cancellation is large when the poses
  // scale unevenly (the filter then could not certify g_0's sign); the same number for exact inputs.
  T det_a = la[0][0] * (la[1][1] * la[2][2] - la[1][2] * la[2][1]) -
            la[0][1] * (la[1][0] * la[2][2] - la[1][2] * la[2][0]) +
            la[0][2] * (la[1][0] * la[2][1] - la[1][1] * la[2][0]);
  T p = det_a * (det * (det * det));
  g[0] = -(p * p);
  return g;
}

namespace static_filter_detail {

inline constexpr std::array<int, 5> kDepth = [] {
  std::array<StaticDepth, 5> g = unit_ball_coefficients<StaticDepth>([](int) { return StaticDepth(); });
  return std::array<int, 5>{g[0].value(), g[1].value(), g[2].value(), g[3].value(), g[4].value()};
}();
static_assert(kDepth[0] > 0 && kDepth[0] * 0x1p-53 <= 0x1p-10, "the bound needs d u <= 2^-10");
// Δ's depth: quartic_discriminant (kernel/discriminant.hpp) is not constexpr, so the StaticDepth run of it is
// checked against this constant by tests/api/test_static_filter3d.cpp. (A constant, not a start-up
// initialisation: this header is also compiled for AVX2 in api/static_filter_simd.cpp, whose code must not run
// before the CPU is checked.)
inline constexpr int kDeltaDepth = 13;

inline constexpr double kU = 0x1p-53, kTau = 0x1p-430, kMaxEntry = 0x1p12, kMinAxis = 0x1p-12;

// The magnitude run's type for a lane type: Magnitude for double (one lane, or the compiler's vectoriser),
// LaneMagnitude<W> for W lanes in one vector register (number/lane_vector.hpp).
template <class D>
struct LaneOf {
  using Magnitude = eccd::Magnitude;
};
template <int W>
struct LaneOf<LaneDouble<W>> {
  using Magnitude = LaneMagnitude<W>;
};

// Flags are doubles 1 / 0 and "and" is a product: a lane of the vectorised loop holds doubles only (bools there
// are masks that GCC 12 cannot convert or mix with doubles).
[[gnu::always_inline]] inline double flag(bool c) { return c ? 1.0 : 0.0; }

// The status from ĝ and e (and Δ with its bound), as a code 0 uncertain, 1 separate, 2 overlapping; branch-free
// so that it vectorises in the lane loop (kLanes); one pair returns early and skips Δ where it can.
// ok: 1 when the inputs' ranges held, else 0.
template <bool kLanes, class D = double>
[[gnu::always_inline]] inline D decide(D ok, const std::array<D, 5>& g, const std::array<D, 5>& e) {
  D certain = ok, in_range = D(1);
#pragma GCC unroll 5
  for (int k = 0; k < 5; ++k) {
    const D a = lane_abs(g[k]);
    certain = certain * lane_gt(a, e[k]);
    in_range = in_range * (lane_ge(a, D(0x1p-150)) * lane_le(a, D(0x1p150)));
  }
  // Sign changes of g4, -g3, g2, -g1, g0 (all non-zero when certain).
  const D zero(0);
  const D s4 = lane_gt(g[4], zero), s3 = lane_not_gt(g[3], zero), s2 = lane_gt(g[2], zero),
          s1 = lane_not_gt(g[1], zero), s0 = lane_gt(g[0], zero);
  const D changes = (s4 - s3) * (s4 - s3) + (s3 - s2) * (s3 - s2) + (s2 - s1) * (s2 - s1) + (s1 - s0) * (s1 - s0);
  if constexpr (!kLanes) {
    if (certain == 0) return 0.0;
    if (changes == 0) return 2.0;
  }
  // ρ: the sum of the e_k / |ĝ_k| (>= their maximum; a sum needs no select). Δ on fresh leaves ĝ.
  D rho(0);
#pragma GCC unroll 5
  for (int k = 0; k < 5; ++k) rho = rho + e[k] / lane_abs(g[k]);
  D dv, dm;
  if constexpr (kLanes) {
    using Mag = typename LaneOf<D>::Magnitude;
    dv = quartic_discriminant(g[4], g[3], g[2], g[1], g[0]);
    dm = quartic_discriminant(Mag::leaf(g[4]), Mag::leaf(g[3]), Mag::leaf(g[2]), Mag::leaf(g[1]), Mag::leaf(g[0]))
             .value();
  } else {
    const ValueMagnitude d =
        quartic_discriminant(ValueMagnitude::leaf(g[4]), ValueMagnitude::leaf(g[3]), ValueMagnitude::leaf(g[2]),
                             ValueMagnitude::leaf(g[1]), ValueMagnitude::leaf(g[0]));
    dv = d.value();
    dm = d.magnitude();
  }
  const D derr = dm * (D(2 * kDeltaDepth * kU) + D(7) * rho);
  const D delta_ok = in_range * lane_le(rho, D(0x1p-20)) * lane_le(dm, D(0x1p1000));
  const D delta_pos = delta_ok * lane_gt(dv, derr), delta_neg = delta_ok * lane_gt(-dv, derr);
  const D zero_changes = lane_eq(changes, zero);
  // exclusive: 2 overlapping, 1 separate, 0 uncertain
  const D overlapping = certain * (zero_changes + (D(1) - zero_changes) * delta_neg);
  const D separate = certain * lane_eq(changes, D(2)) * delta_pos;
  return D(2) * overlapping + separate;
}

// f's coefficients ĝ_k with their bounds e_k (|ĝ_k - g_k| <= e_k when ok = 1: the ranges held); D is double or
// a lane vector (number/lane_vector.hpp).
template <class D = double>
struct Bounds {
  std::array<D, 5> g, e;
  D ok;
};
template <bool kLanes, class D = double, class Leaf>
[[gnu::always_inline]] inline Bounds<D> bounds(Leaf leaf) {
  D ok(1);                 // the ranges
  if constexpr (kLanes) {  // compares and products only (0 for NaN too)
    const D min_axis(kMinAxis), max_entry(kMaxEntry);
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      ok = ok * (lane_ge(leaf(static_axis_a(j)), min_axis) * lane_le(leaf(static_axis_a(j)), max_entry));
      ok = ok * (lane_ge(leaf(static_axis_b(j)), min_axis) * lane_le(leaf(static_axis_b(j)), max_entry));
#pragma GCC unroll 4
      for (int c = 0; c < 4; ++c)
        ok = ok * (lane_le(lane_abs(leaf(static_pose_a(j, c))), max_entry) *
                   lane_le(lane_abs(leaf(static_pose_b(j, c))), max_entry));
    }
  } else {  // max / min instructions (x > m ? x : m); a NaN input is passed over here, but it makes some
            // coefficient NaN (every input is a factor of some monomial), and then no sign is certain
    double big = 0, small = kMaxEntry;
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      const double xa = leaf(static_axis_a(j)), xb = leaf(static_axis_b(j));
      big = xa > big ? xa : big;
      big = xb > big ? xb : big;
      small = xa < small ? xa : small;
      small = xb < small ? xb : small;
#pragma GCC unroll 4
      for (int c = 0; c < 4; ++c) {
        const double pa = std::fabs(leaf(static_pose_a(j, c))), pb = std::fabs(leaf(static_pose_b(j, c)));
        big = pa > big ? pa : big;
        big = pb > big ? pb : big;
      }
    }
    ok = flag(big <= kMaxEntry) * flag(small >= kMinAxis);
  }
  Bounds<D> r;
  r.ok = ok;
  std::array<D, 5>&g = r.g, &e = r.e;
  if constexpr (kLanes) {  // separate runs: each lane of the vectorised loop holds one double
    using Mag = typename LaneOf<D>::Magnitude;
    g = unit_ball_coefficients<D>(leaf);
    const std::array<Mag, 5> m = unit_ball_coefficients<Mag>([&](int k) { return Mag::leaf(leaf(k)); });
#pragma GCC unroll 5
    for (int k = 0; k < 5; ++k) e[k] = D(2 * kDepth[k] * kU) * m[k].value() + D(kTau);
  } else {  // one pair: value and magnitude side by side (ValueMagnitude)
    const std::array<ValueMagnitude, 5> vm =
        unit_ball_coefficients<ValueMagnitude>([&](int k) { return ValueMagnitude::leaf(leaf(k)); });
#pragma GCC unroll 5
    for (int k = 0; k < 5; ++k) {
      g[k] = vm[k].value();
      e[k] = 2 * kDepth[k] * kU * vm[k].magnitude() + kTau;
    }
  }
  return r;
}

template <bool kLanes, class D = double, class Leaf>
[[gnu::always_inline]] inline D pair_code(Leaf leaf) {
  const Bounds<D> r = bounds<kLanes, D>(leaf);
  return decide<kLanes, D>(r.ok, r.g, r.e);
}

}  // namespace static_filter_detail

// The status a filter code stands for (1 separate, 2 overlapping, anything else
// uncertain: the filter did not decide); api/static_status.cpp reads the batch's codes with it.
inline Status static_filter_status(double c) {
  return c == 1.0 ? Status::separate : c == 2.0 ? Status::overlapping : Status::uncertain;
}

// The inputs of one pair as leaves: the semi-axes and the top three rows of the affine poses.
template <class Axes, class Pose>
[[gnu::always_inline]] inline auto static_leaves(const Axes& axes_a, const Pose& pose_a, const Axes& axes_b,
                                                 const Pose& pose_b) {
  return [xa = &axes_a, pa = &pose_a, xb = &axes_b, pb = &pose_b](int k) -> double {
    if (k < 3) return (*xa)[k];
    if (k < 15) return (*pa)[(k - 3) / 4][(k - 3) % 4];
    if (k < 18) return (*xb)[k - 15];
    return (*pb)[(k - 18) / 4][(k - 18) % 4];
  };
}

// One pair: separate, overlapping, or uncertain (never touching: a touch is a double root that no error bound
// proves).
template <class Axes, class Pose>
Status static_filter3d(const Axes& axes_a, const Pose& pose_a, const Axes& axes_b, const Pose& pose_b) {
  return static_filter_status(static_filter_detail::pair_code<false>(static_leaves(axes_a, pose_a, axes_b, pose_b)));
}

// Lanes: in[k][l] is input k (static_axis_a, ...) of lane l; code[l] = 0 uncertain, 1 separate, 2 overlapping.
// Straight-line over the lanes: GCC 12 vectorises the loop for AVX-512 (api/static_filter_simd.hpp), not for AVX2.
template <int L>
[[gnu::always_inline]] inline void static_filter3d_lanes(const double (&in)[kStaticInputs][L], double (&code)[L]) {
#pragma GCC ivdep
  for (int l = 0; l < L; ++l) code[l] = static_filter_detail::pair_code<true>([&](int k) { return in[k][l]; });
}

// W lanes in one vector register (number/lane_vector.hpp: the same program lane by lane, no vectoriser needed):
// L pairs as L / W vectors; in and code as above.
template <int W, int L>
[[gnu::always_inline]] inline void static_filter3d_vector_lanes(const double (&in)[kStaticInputs][L],
                                                                double (&code)[L]) {
  static_assert(L % W == 0);
  using D = LaneDouble<W>;
  for (int base = 0; base < L; base += W) {
    const D c = static_filter_detail::pair_code<true, D>([&](int k) { return D::load(&in[k][base]); });
    c.store(&code[base]);
  }
}

}  // namespace eccd

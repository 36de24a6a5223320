#pragma once
// Lane vectors for the batched static test: W doubles side by side
// in one register of GCC's portable vector extension (4 lanes: AVX2's ymm,
// 8: AVX-512's zmm, 2: SSE2's xmm), with the operations the static filter's
// straight-line program uses (kernel/static_filter3d.hpp) lane by lane.
// LaneDouble<W> is W independent doubles: +, -, * and / round each lane as the
// scalar operation does (IEEE 754, round to nearest; the translation unit
// that uses it turns FMA contraction off, so each lane rounds exactly as the
// one-pair program does). LaneMagnitude<W> is number/static_bound.hpp's
// Magnitude lane by lane (+ and - add the magnitudes, * multiplies them, a
// leaf is |x|). The comparisons return flags as doubles 1 / 0, as the scalar
// program's flag(bool) does, so that the status rule stays products and sums
// (a NaN compares false, as in scalar code).
// Why not the compiler's vectoriser: GCC 12 vectorises the lane loop with
// AVX-512's mask registers only ("control flow in loop" under -mavx2), so the
// batch would have no AVX2 path (measured: slower than single pairs without
// AVX-512). No paper: an implementation device (docs/references.md lists the
// static test's sources).
// Requirements: GCC or Clang (vector_size extension); W a power of two.
#include <cmath>
#include <cstring>

// The wide vectors pass by value only between inlined functions of one translation unit (a unit compiled
// without AVX, as the tests' W = 4 check, gets GCC's note that such a return would change the ABI).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace eccd {

// The vector types by width (GCC ignores a vector_size that depends on a template parameter in an alias).
template <int W>
struct LaneTypes;
template <>
struct LaneTypes<2> {
  typedef double V __attribute__((vector_size(16)));
  typedef long long Mask __attribute__((vector_size(16)));
};
template <>
struct LaneTypes<4> {
  typedef double V __attribute__((vector_size(32)));
  typedef long long Mask __attribute__((vector_size(32)));
};
template <>
struct LaneTypes<8> {
  typedef double V __attribute__((vector_size(64)));
  typedef long long Mask __attribute__((vector_size(64)));
};

template <int W>
class LaneDouble {
 public:
  using V = typename LaneTypes<W>::V;
  using Mask = typename LaneTypes<W>::Mask;

  LaneDouble() : v_{} {}
  LaneDouble(int k) : LaneDouble(double(k)) {}  // NOLINT: broadcast a small exact constant
  LaneDouble(double x) {                        // NOLINT: broadcast
    for (int l = 0; l < W; ++l) v_[l] = x;
  }
  static LaneDouble load(const double* p) {
    LaneDouble r;
    std::memcpy(&r.v_, p, sizeof(V));
    return r;
  }
  void store(double* p) const { std::memcpy(p, &v_, sizeof(V)); }
  double operator[](int l) const { return v_[l]; }
  const V& raw() const { return v_; }

  friend LaneDouble operator+(LaneDouble a, LaneDouble b) { return of(a.v_ + b.v_); }
  friend LaneDouble operator-(LaneDouble a, LaneDouble b) { return of(a.v_ - b.v_); }
  friend LaneDouble operator*(LaneDouble a, LaneDouble b) { return of(a.v_ * b.v_); }
  friend LaneDouble operator/(LaneDouble a, LaneDouble b) { return of(a.v_ / b.v_); }
  friend LaneDouble operator*(int k, LaneDouble b) { return LaneDouble(k) * b; }
  LaneDouble operator-() const { return of((V)((Mask)v_ ^ sign_bits())); }

  friend LaneDouble lane_abs(LaneDouble a) { return of((V)((Mask)a.v_ & ~sign_bits())); }
  // Flags 1.0 / 0.0 per lane (false for a NaN operand).
  friend LaneDouble lane_gt(LaneDouble a, LaneDouble b) { return flags(a.v_ > b.v_); }
  friend LaneDouble lane_ge(LaneDouble a, LaneDouble b) { return flags(a.v_ >= b.v_); }
  friend LaneDouble lane_le(LaneDouble a, LaneDouble b) { return flags(a.v_ <= b.v_); }
  friend LaneDouble lane_eq(LaneDouble a, LaneDouble b) { return flags(a.v_ == b.v_); }
  friend LaneDouble lane_not_gt(LaneDouble a, LaneDouble b) { return flags(~(a.v_ > b.v_)); }

 private:
  static LaneDouble of(V v) {
    LaneDouble r;
    r.v_ = v;
    return r;
  }
  static Mask sign_bits() { return (Mask)LaneDouble(-0.0).v_; }  // -0.0 in every lane: the sign bit alone
  static LaneDouble flags(Mask m) { return of((V)(m & (Mask)LaneDouble(1.0).v_)); }
  V v_;
};

// Scalar forms of the same flags (the one-pair and auto-vectorised lane programs).
inline double lane_abs(double a) { return std::fabs(a); }
inline double lane_gt(double a, double b) { return a > b ? 1.0 : 0.0; }
inline double lane_ge(double a, double b) { return a >= b ? 1.0 : 0.0; }
inline double lane_le(double a, double b) { return a <= b ? 1.0 : 0.0; }
inline double lane_eq(double a, double b) { return a == b ? 1.0 : 0.0; }
inline double lane_not_gt(double a, double b) { return !(a > b) ? 1.0 : 0.0; }

template <int W>
class LaneMagnitude {
 public:
  using D = LaneDouble<W>;
  LaneMagnitude() = default;
  LaneMagnitude(int k) : m_(double(k < 0 ? -k : k)) {}  // NOLINT: small exact constants
  static LaneMagnitude leaf(D x) { return of(lane_abs(x)); }
  D value() const { return m_; }
  friend LaneMagnitude operator+(LaneMagnitude a, LaneMagnitude b) { return of(a.m_ + b.m_); }
  friend LaneMagnitude operator-(LaneMagnitude a, LaneMagnitude b) { return of(a.m_ + b.m_); }
  friend LaneMagnitude operator*(LaneMagnitude a, LaneMagnitude b) { return of(a.m_ * b.m_); }
  friend LaneMagnitude operator*(int k, LaneMagnitude b) { return LaneMagnitude(k) * b; }
  LaneMagnitude operator-() const { return *this; }

 private:
  static LaneMagnitude of(D m) {
    LaneMagnitude r;
    r.m_ = m;
    return r;
  }
  D m_;
};

}  // namespace eccd

#pragma GCC diagnostic pop

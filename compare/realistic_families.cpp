// The realistic-input families and the linear ones (see compare/scene_generator.hpp
// for the constructions): decimal (a generic scene with every number rounded
// to a number of significant digits), keyframe (rigid bodies under keyframed
// joints, animation-format.md) and overlap / graze (linear translations
// pushed a given depth into each other, or touching at t0).
#include "compare/scene_building.hpp"

#include "kernel/keyframe_motion.hpp"

#include <algorithm>
#include <cmath>

namespace eccd::scene_building {

Rational pow10(int e) {
  mpz_class t = 1;
  for (int i = 0; i < std::abs(e); ++i) t *= 10;
  return e >= 0 ? Rational(t) : Rational(mpz_class(1), t);
}

// A "real-valued" number picked by the seed, written with `digits` significant digits.
Rational decimal_in(Rng& r, double lo, double hi, int digits) {
  double u = double(r.next() >> 11) / double(1ULL << 53);
  return round_significant(Rational(lo + (hi - lo) * u), digits);
}

// sqrt(a) for a > 0, to ~digits + 3 decimals (a choice of number, checked by nobody).
Rational sqrt_approx(const Rational& a, int digits) {
  int m = digits + 6;
  mpz_class num = a.get_num() * mpz_class(pow10(2 * m).get_num()), root;
  num /= a.get_den();
  mpz_sqrt(root.get_mpz_t(), num.get_mpz_t());
  return Rational(root) / pow10(m);
}

// Each non-zero coefficient times (1 + j), |j| <= 10^-3 picked by the seed (the
// generator's numbers have short denominators; a measured value has all its
// digits), then rounded to `digits` significant digits. Zeros stay zero.
RPoly round_poly(Rng& r, const RPoly& p, int digits) {
  std::vector<Rational> c;
  for (const auto& x : p.c) {
    Rational j = r.frac(-1000000, 1000000, 1000000000);
    c.push_back(round_significant(Rational(x) * (1 + j), digits));
  }
  return RPoly(c);
}
Motion round_motion(Rng& rng, const Motion& m, int digits) {
  auto rp = [&](const RPoly& p) { return round_poly(rng, p, digits); };
  if (auto* k = std::get_if<KinematicMotion>(&m)) {
    KinematicMotion r;
    for (int i = 0; i < 4; ++i) r.d[i] = rp(k->d[i]);
    return r;
  }
  if (auto* e = std::get_if<EulerMotion>(&m)) {
    EulerMotion r;
    for (int i = 0; i < 4; ++i) r.e[i] = rp(e->e[i]);
    for (int i = 0; i < 3; ++i) r.v[i] = rp(e->v[i]);
    r.v3 = e->v3;  // the translation denominator stays 1
    return r;
  }
  if (auto* mm = std::get_if<MatrixMotion>(&m)) {
    MatrixMotion r = *mm;
    for (auto& row : r.m)
      for (auto& x : row) x = rp(x);
    return r;
  }
  return m;
}

// decimal: a generic scene, every number rounded to `digits` significant digits.
Built build_decimal(Rng& r, const GeneratorSpec& s) {
  GeneratorSpec base = s;
  static const char* bases[] = {"colliding", "free", "touch"};
  base.family = bases[r.uniform(0, s.degree >= 2 ? 2 : 1)];
  Built b = base.family == "touch" ? build_touch(r, base) : build_random(r, base);
  b.base = base.family;
  b.t0.reset();
  b.ma = round_motion(r, b.ma, s.digits);
  b.mb = round_motion(r, b.mb, s.digits);
  auto axis = [&](const Rational& a) {
    return round_significant(sqrt_approx(a, s.digits) * (1 + r.frac(-1000000, 1000000, 1000000000)), s.digits);
  };
  for (auto& a : b.alpha_a) b.axes_a.push_back(axis(a));
  for (auto& a : b.alpha_b) b.axes_b.push_back(axis(a));
  return b;
}

// keyframe: one body under a chain of keyframed joints (see the header).
struct Keyframed {
  Motion motion;
  nlohmann::ordered_json json;
};
// A unit quaternion (2D: a unit pair [w, z]) picked in double, written with `digits` digits.
Vec random_orientation(Rng& r, int dim, int digits) {
  int n = dim == 3 ? 4 : 2;
  while (true) {
    std::vector<double> q(n);
    double len = 0;
    for (auto& x : q) {
      x = double(r.next() >> 11) / double(1ULL << 52) - 1.0;
      len += x * x;
    }
    len = std::sqrt(len);
    if (len < 0.2 || len > 1.0) continue;
    Vec out;
    for (double x : q) out.push_back(round_significant(Rational(x / len), digits));
    return out;
  }
}
Keyframed keyframed_body(Rng& r, int dim, int degree, int digits, const Vec& box_lo, const Vec& box_hi) {
  const int joints = degree / 2;  // 2 -> 1, 3 -> 1, 4 -> 2, 5 -> 2, 6 -> 3
  const bool moving_root = degree % 2 == 1;
  Vec c0, c1;
  for (int i = 0; i < dim; ++i) {
    c0.push_back(decimal_in(r, box_lo[i].get_d(), box_hi[i].get_d(), digits));
    c1.push_back(moving_root ? decimal_in(r, box_lo[i].get_d(), box_hi[i].get_d(), digits) : c0[i]);
  }
  std::vector<std::pair<Vec, Vec>> keys;
  for (int k = 0; k < joints; ++k) {
    Vec q0 = random_orientation(r, dim, digits), q1 = random_orientation(r, dim, digits);
    // animation-format.md: q'_1 = -q_1 when q_0 . q_1 < 0 (the shorter way round; kernel/keyframe_motion.hpp)
    keys.push_back({q0, shorter_way(q0, q1)});
  }
  Keyframed out;
  if (joints == 1) {
    const Vec& q0 = keys[0].first;
    const Vec& q1 = keys[0].second;
    // The motion by the animation rule (kernel/keyframe_motion.hpp); the JSON writes the key values.
    out.motion = keyframe_motion(KeyPose{c0, q0, std::nullopt}, KeyPose{c1, q1, std::nullopt}, dim);
    nlohmann::ordered_json j;
    if (dim == 3) {
      j["type"] = "euler";
      for (int i = 0; i < 4; ++i) j["e"].push_back(bern_json(q0[i], q1[i]));
      for (int i = 0; i < 3; ++i)
        j["translation"].push_back(moving_root ? bern_json(c0[i], c1[i]) : nlohmann::ordered_json(number_text(c0[i])));
      j["translation_denominator"] = "1";
    } else {
      const KinematicMotion& km = std::get<KinematicMotion>(out.motion);
      j["type"] = "kinematic";
      j["d"].push_back(poly_json(km.d[0]));
      j["d"].push_back(poly_json(km.d[1]));
      j["d"].push_back(bern_json(q0[0], q1[0]));
      j["d"].push_back(bern_json(-q0[1], -q1[1]));
    }
    out.json = j;
    return out;
  }
  // A chain: root translation c(τ), then joint k's rotation, then bone offset o_k.
  HMat M(dim + 1, std::vector<RPoly>(dim + 1));
  for (int i = 0; i <= dim; ++i) M[i][i] = constant(1);
  for (int i = 0; i < dim; ++i) M[i][dim] = RPoly(std::vector<Rational>{c0[i], c1[i] - c0[i]});
  for (int k = 0; k < joints; ++k) {
    M = hmul(M, keyframe_rotation(keys[k].first, keys[k].second, dim));
    Vec o;
    for (int i = 0; i < dim; ++i) o.push_back(decimal_in(r, -0.8, 0.8, digits));
    M = hmul(M, hconst(identity(dim), o));
  }
  MatrixMotion mm;
  mm.m = M;
  out.motion = mm;
  out.json = motion_json(mm);
  return out;
}

Built build_keyframe(Rng& r, const GeneratorSpec& s) {
  Built b;
  const int dim = s.dim;
  for (int i = 0; i < dim; ++i) b.axes_a.push_back(decimal_in(r, 0.4, 1.6, s.digits));
  for (int i = 0; i < dim; ++i) b.axes_b.push_back(decimal_in(r, 0.4, 1.6, s.digits));
  Vec lo(dim, Rational(-2)), hi(dim, Rational(2));
  int other = int(r.uniform(2, s.degree));
  bool swap = r.uniform(0, 1) == 1;
  Keyframed ka = keyframed_body(r, dim, swap ? other : s.degree, s.digits, lo, hi);
  Keyframed kb = keyframed_body(r, dim, swap ? s.degree : other, s.digits, lo, hi);
  b.ma = ka.motion;
  b.mb = kb.motion;
  b.json_a = ka.json;
  b.json_b = kb.json;
  return b;
}

// overlap / graze: see the header. Both motions are matrix motions of degree 1.
Built build_linear_overlap(Rng& r, const GeneratorSpec& s) {
  Built b;
  const int dim = s.dim;
  Rational t0 = r.frac(4, 16, 20);
  b.t0 = t0;
  Rational delta = s.family == "overlap" ? pow10(-s.d_exponent) : Rational(0);
  Vec n = random_unit(r, dim), m;
  do m = random_unit(r, dim);
  while (dot(m, n) == -1);
  Tangency ta = shape_with_normal(r, n), tb = shape_with_normal(r, m);
  b.alpha_a = ta.alpha;
  b.alpha_b = tb.alpha;
  Mat RB = rotation_taking(r, m, n);
  Vec cB = mat_vec(RB, tb.point);
  for (int i = 0; i < dim; ++i) cB[i] = ta.point[i] - cB[i];
  // B's translation s(t) = -δ n + (t - t0) v τ, τ ⊥ n: along the tangent plane.
  Vec tau = dim == 2 ? Vec{-n[1], n[0]} : orthogonal_to(r, n);
  Rational v = r.frac(1, 8, 2);
  // The common motion G: a constant rational rotation and a linear translation.
  Vec ga = random_unit(r, dim), gb = random_unit(r, dim);
  Mat RG = dot(ga, gb) == -1 ? identity(dim) : rotation_taking(r, ga, gb);
  Vec g0, g1;
  for (int i = 0; i < dim; ++i) {
    g0.push_back(r.frac(-24, 24, 8));
    g1.push_back(r.frac(-24, 24, 8));
  }
  auto affine = [&](const Mat& L, const std::vector<RPoly>& tr) {
    MatrixMotion mm;
    mm.m.assign(dim + 1, std::vector<RPoly>(dim + 1));
    for (int i = 0; i < dim; ++i) {
      for (int j = 0; j < dim; ++j) mm.m[i][j] = constant(L[i][j]);
      mm.m[i][dim] = tr[i];
    }
    mm.m[dim][dim] = constant(1);
    return mm;
  };
  // A: x -> RG x + g(t);  B: x -> RG (RB x + cB + s(t)) + g(t).
  std::vector<RPoly> ta_tr, tb_tr;
  Mat LB = mat_mul(RG, RB);
  Vec rc = mat_vec(RG, cB), rn = mat_vec(RG, n), rt = mat_vec(RG, tau);
  for (int i = 0; i < dim; ++i) {
    RPoly g(std::vector<Rational>{g0[i], g1[i]});
    ta_tr.push_back(g);
    RPoly sB(std::vector<Rational>{rc[i] - delta * rn[i] - t0 * v * rt[i], v * rt[i]});
    tb_tr.push_back(g + sB);
  }
  b.ma = affine(RG, ta_tr);
  b.mb = affine(LB, tb_tr);
  return b;
}

}  // namespace eccd::scene_building

// kernel/cycloidal_motion.hpp: A(t), g_i(t) and Δ(t) of cycloidal motions
// (003 section V) evaluated pointwise in an enclosing scalar. Checked against:
//   - exact rational values at the instants where the angle π(θ0 + θ1 t) is a
//     multiple of π/2 (sin and cos are 0, ±1): A(t) = N(t)ᵀ Q N(t) written in
//     the test from the statement's X_body = Rᵀ X + c - Rᵀ(c + V), its
//     determinant-free pencil coefficients by the Leibniz expansion of
//     det(λA - B) at λ = 0..3, and the cubic discriminant; the MPFI values at
//     128 bits must contain them and Bounded<double> must bound them;
//   - the turn is about the object's centre (a shape written with an offset
//     centre): at a half turn with no translation the solid is the same set;
//   - g3 = det A and g0 = -det B do not depend on t (the shapes do not change);
//   - the mean value theorem for the Dual derivative: (Δ(b) - Δ(a)) / (b - a)
//     is a value of Δ' on [a, b], so the enclosure of Δ'([a, b]) meets it;
//   - cycloidal_pair refuses a rational motion beside a cycloidal one.
#include "io/scene_reader.hpp"
#include "kernel/cycloidal_motion.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using M3 = std::array<std::array<mpq_class, 3>, 3>;

Scene scene_of(const std::string& a, const std::string& b) {
  return parse_scene(
      "{\"format\": \"ellipse-ccd-scene/1\", \"name\": \"t\", \"dim\": 2, \"a\": " + a + ", \"b\": " + b + "}", "test");
}
std::string cyc(const std::string& shape, const std::string& th0, const std::string& th1, const std::string& x0,
                const std::string& x1, const std::string& y0, const std::string& y1) {
  return "{\"shape\": " + shape + ", \"motion\": {\"type\": \"cycloidal\", \"angle_over_pi\": [\"" + th0 + "\", \"" +
         th1 + "\"], \"translation\": [[\"" + x0 + "\", \"" + x1 + "\"], [\"" + y0 + "\", \"" + y1 + "\"]]}}";
}
// An ellipse x²/9 + y²/4 <= 1 centred at (1, -2) in its own frame, as a matrix shape.
const std::string kOffset =
    "{\"matrix\": [[\"4\", \"0\", \"-4\"], [\"0\", \"9\", \"18\"], [\"-4\", \"18\", \"4\"]]}";  // 4(x-1)² + 9(y+2)² -
                                                                                                // 36
const std::string kCircle = "{\"semi_axes\": [\"2\", \"2\"]}";

// A(t) exactly when the angle is k π / 2: X_body = Rᵀ X + c - Rᵀ(c + V), A = Nᵀ Q N.
M3 exact_quadric(const SceneObject& o, const mpq_class& t) {
  const auto& Q = o.Q;
  const auto& m = std::get<CycloidalMotion>(o.motion);
  const mpq_class det = Q[0][0] * Q[1][1] - Q[0][1] * Q[1][0];
  const mpq_class cx = (-Q[0][2] * Q[1][1] + Q[1][2] * Q[0][1]) / det,
                  cy = (-Q[1][2] * Q[0][0] + Q[0][2] * Q[1][0]) / det;
  const mpq_class ang = m.theta0 + m.theta1 * t;  // a multiple of 1/2
  const mpz_class k = mpz_class(ang * 2) % 4;
  const long kk = ((k.get_si() % 4) + 4) % 4;
  const int cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
  const mpq_class c(cs[kk]), s(sn[kk]);
  const mpq_class vx = m.x[0] + m.x[1] * t, vy = m.y[0] + m.y[1] * t;
  // R = [[c, -s], [s, c]], Rᵀ = [[c, s], [-s, c]]; N's affine part Rᵀ and translation c - Rᵀ(c + V)
  const mpq_class wx = cx + vx, wy = cy + vy;
  M3 n{};
  n[0][0] = c;
  n[0][1] = s;
  n[1][0] = -s;
  n[1][1] = c;
  n[0][2] = cx - (c * wx + s * wy);
  n[1][2] = cy - (-s * wx + c * wy);
  n[2][2] = 1;
  M3 a{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) a[i][j] += n[p][i] * Q[p][q] * n[q][j];
  return a;
}
mpq_class det3(const M3& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
// g_0..g_3 of det(λA - B) from its values at λ = 0..3.
std::array<mpq_class, 4> exact_g(const M3& a, const M3& b) {
  mpq_class v[4];
  for (int l = 0; l < 4; ++l) {
    M3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = l * a[i][j] - b[i][j];
    v[l] = det3(m);
  }
  const mpq_class d1 = v[1] - v[0], d2 = v[2] - 2 * v[1] + v[0], d3 = v[3] - 3 * v[2] + 3 * v[1] - v[0];
  return {v[0], d1 - d2 / 2 + d3 / 3, d2 / 2 - d3 / 2, d3 / 6};
}
bool contains(const MpfiInterval& x, const mpq_class& q) { return mpfi_cmp_q(x.get(), q.get_mpq_t()) == 0; }
bool bounds(const Bounded<double>& x, const mpq_class& q) {
  return abs(mpq_class(x.value()) - q) <= mpq_class(double(x.bound()));
}

}  // namespace

TEST_CASE("cycloidal A(t), g and Δ contain the exact values at quarter turns", "[kernel][cycloidal_motion]") {
  // A turns by π(1/2 + 3t) about its centre (1, -2) + V; B by π(-1 + t); at t = k/6 A's angle is a multiple of
  // π/2, B's at t = 0, 1/2, 1.
  const Scene s =
      scene_of(cyc(kOffset, "1/2", "3", "-3", "6", "1", "-2"), cyc(kCircle, "-1", "1", "2", "-1", "0", "3"));
  const MpfiInterval like(mpq_class(0), 128);
  const CycloidalPair<MpfiInterval> pi = cycloidal_pair<MpfiInterval>(s, like);
  const Bounded<double> blike(0.0, 0);
  const CycloidalPair<Bounded<double>> pb = cycloidal_pair<Bounded<double>>(s, blike);
  for (const mpq_class& t : {mpq_class(0), mpq_class(1, 2), mpq_class(1)}) {
    const M3 a = exact_quadric(s.a, t), b = exact_quadric(s.b, t);
    const auto g = exact_g(a, b);
    const mpq_class delta = cubic_discriminant(g[3], g[2], g[1], g[0]);
    const MpfiInterval ti(t, 128);
    const auto ai = cycloidal_quadric_at<MpfiInterval>(pi.a, ti);
    const auto gi = cycloidal_g<MpfiInterval>(pi, ti);
    const auto gb = cycloidal_g<Bounded<double>>(pb, Bounded<double>(t.get_d(), 0));
    INFO("t = " << t);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(contains(ai[i][j], a[i][j]));
    for (int k = 0; k < 4; ++k) {
      CHECK(contains(gi[k], g[k]));
      CHECK(bounds(gb[k], g[k]));
    }
    CHECK(contains(cycloidal_delta<MpfiInterval>(pi, ti), delta));
    CHECK(bounds(cycloidal_delta<Bounded<double>>(pb, Bounded<double>(t.get_d(), 0)), delta));
    // The shapes do not change: g3 = det A, g0 = -det B (the constants of Q).
    CHECK(g[3] == det3(exact_quadric(s.a, mpq_class(0))));
  }
}

TEST_CASE("cycloidal motion turns about the centre, keeps g3 and g0, and its Δ' meets every difference quotient",
          "[kernel][cycloidal_motion]") {
  // A half turn of the offset ellipse with no translation: the same set, so A(1) = A(0) exactly.
  const Scene s = scene_of(cyc(kOffset, "0", "1", "0", "0", "0", "0"), cyc(kCircle, "0", "0", "5", "0", "0", "0"));
  const M3 a0 = exact_quadric(s.a, mpq_class(0)), a1 = exact_quadric(s.a, mpq_class(1));
  CHECK(a0 == a1);
  const MpfiInterval like(mpq_class(0), 128);
  const auto p = cycloidal_pair<MpfiInterval>(s, like);
  const auto at1 = cycloidal_quadric_at<MpfiInterval>(p.a, MpfiInterval(mpq_class(1), 128));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) CHECK(contains(at1[i][j], a0[i][j]));

  const Scene m =
      scene_of(cyc(kOffset, "1/3", "7/5", "-4", "8", "1", "-1"), cyc(kCircle, "0", "-2", "1", "0", "2", "-3"));
  const auto pm = cycloidal_pair<MpfiInterval>(m, like);
  M3 qa, qb;  // the shapes as the reader wrote them
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      qa[i][j] = m.a.Q[i][j];
      qb[i][j] = m.b.Q[i][j];
    }
  std::mt19937_64 rng(4337);
  for (int k = 0; k < 30; ++k) {
    mpq_class lo(long(rng() % 1000), 1000), w(long(rng() % 50) + 1, 10000);
    lo.canonicalize();
    w.canonicalize();
    const mpq_class hi = lo + w;
    const auto g = cycloidal_g<MpfiInterval>(pm, MpfiInterval(lo, 128));
    // g3 = det A = det Q_A, g0 = -det B = -det Q_B at every t.
    CHECK(contains(g[3], det3(qa)));
    CHECK(contains(g[0], -det3(qb)));
    // mean value theorem: the quotient of the enclosures meets Δ'([lo, hi]).
    const MpfiInterval da = cycloidal_delta<MpfiInterval>(pm, MpfiInterval(lo, 128));
    const MpfiInterval db = cycloidal_delta<MpfiInterval>(pm, MpfiInterval(hi, 128));
    MpfiInterval quot(mpq_class(0), 128);
    mpfi_sub(quot.get(), db.get(), da.get());
    mpfi_div_q(quot.get(), quot.get(), w.get_mpq_t());
    Dual<MpfiInterval> tt(range_of(lo, hi, like), MpfiInterval(mpq_class(1), 128));
    const MpfiInterval dd = cycloidal_delta<Dual<MpfiInterval>>(pm, tt).d;
    MpfiInterval both(mpq_class(0), 128);
    INFO("[" << lo << ", " << hi << "]");
    CHECK_FALSE(mpfi_intersect(both.get(), quot.get(), dd.get()) < 0);
    CHECK_FALSE(mpfi_is_empty(both.get()));
  }
}

TEST_CASE("cycloidal_pair refuses a rational motion beside a cycloidal one", "[kernel][cycloidal_motion]") {
  const Scene s = scene_of(cyc(kCircle, "0", "1", "0", "0", "0", "0"),
                           "{\"shape\": " + kCircle +
                               ", \"motion\": {\"type\": \"matrix\", \"m\": [[\"1\", \"0\", [\"0\", \"1\"]], [\"0\", "
                               "\"1\", \"0\"], [\"0\", \"0\", \"1\"]]}}");
  CHECK(has_cycloidal_motion(s));
  try {
    cycloidal_pair<MpfiInterval>(s, MpfiInterval(mpq_class(0), 64));
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("object b has a matrix motion beside a cycloidal one") != std::string::npos);
  }
}

}  // namespace ECCD_UNITY_ID

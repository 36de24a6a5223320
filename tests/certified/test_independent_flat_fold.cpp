// An end of independent motions at a fold that is flat in the other
// parameter (certified/independent_proof.hpp, narrowed_run): pair 4 of the
// benchmark group independent-rotating (`eccd generate --dims 3 --degrees 2
// --motions euler --families colliding --count 4 --seed 7`, scene
// 3d-deg2-colliding-euler-1659179808692259, made independent: A moves with s,
// B with t). Its t-end near 0.36164 is a fold F = F_u = F_s = 0 at u ~ 0.3254,
// s ~ 0.3603 where G = max_u F has G_ss ~ 1.5e-4 against G_st ~ -2.4e-3, so
// across one localisation strip of t the points with G_s = 0 sweep about 16
// strip widths of s: the exclusion needs X's s-range to cover that sweep,
// and Krawczyk's test fails on an X that wide. The end is proved on the
// run narrowed by finer strip proofs. Checked: exact and certified prove
// every end; the t-end's bracket holds the fold's t located independently,
// by Newton's method on (F, F_u, F_s) in (u, t, s) in 400-bit MPFI mid-points
// and rationals from the double fold; the certificate checks (eccd-check's
// checker, which replays the finer strips and the end). Bounded by work
// counts (box tests, Krawczyk tests), not by time.
#include "api/certify.hpp"
#include "api/solve.hpp"
#include "certified/krawczyk.hpp"
#include "compare/scene_generator.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "number/mpfi_interval.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Scene rotating_pair_4() {
  GeneratorSpec c;
  c.dim = 3;
  c.degree = 2;
  c.family = "colliding";
  c.motion = "euler";
  c.seed = scene_seed(7, c, 3);
  GeneratedScene g = generate_scene(c);
  REQUIRE(g.name == "3d-deg2-colliding-euler-1659179808692259");
  g.doc["parameters"] = "independent";
  g.doc.erase("answer");
  return scene_from_text(g.doc.dump(), "rotating-4");
}

long work(const Solution& s, const std::string& key) {
  for (const auto& [k, v] : s.work)
    if (k == key) return v;
  return -1;
}

// The fold's t: Newton on (F, F_u, F_s) in (u, t, s) of the exact net with s and t exchanged, in 400-bit MPFI
// evaluations read as rationals (the mid-points), the step solved exactly by Cramer's rule.
mpq_class fold_t(const Scene& scene, std::array<double, 3> start, mpq_class& last_step) {
  using namespace krawczyk_method;
  Scene shared = scene;
  shared.independent = false;
  const TriBern<Rational> F = independent_ellipsoid_function<Rational, 4>(
      to_arithmetic_bernstein<Rational, 4>(prepare_pair<4>(shared), Rational(1)));
  const TriBern<Rational> Ft = F.swap_st();
  const int bits = 400;
  TriBern<MpfiInterval> net;
  net.n = Ft.n;
  for (const auto& q : Ft.c) net.c.emplace_back(q, bits);
  Nets nets(net, bits);
  const System sys{{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 1, 2}, std::nullopt, "fold"};
  const auto x0 = newton(nets, sys, start);
  REQUIRE(x0);
  std::array<mpq_class, 3> x{mpq_class((*x0)[0]), mpq_class((*x0)[1]), mpq_class((*x0)[2])};
  auto mid = [](const MpfiInterval& v) { return mpq_class((lower(v) + upper(v)) / 2); };
  for (int it = 0; it < 8; ++it) {
    const std::array<MpfiInterval, 3> p{MpfiInterval(x[0], bits), MpfiInterval(x[1], bits), MpfiInterval(x[2], bits)};
    std::array<mpq_class, 3> f;
    std::array<std::array<mpq_class, 3>, 3> J;
    for (int e = 0; e < 3; ++e) {
      f[e] = -mid(nets.eval(sys.eqs[e], p));
      for (int v = 0; v < 3; ++v) J[e][v] = mid(nets.eval(plus(sys.eqs[e], v), p));
    }
    auto det = [](const std::array<std::array<mpq_class, 3>, 3>& m) {
      return mpq_class(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
    };
    const mpq_class d = det(J);
    REQUIRE(sgn(d) != 0);
    last_step = 0;
    std::array<mpq_class, 3> nx = x;
    for (int v = 0; v < 3; ++v) {
      auto Jv = J;
      for (int e = 0; e < 3; ++e) Jv[e][v] = f[e];
      const mpq_class step = det(Jv) / d;
      nx[v] += step;
      last_step = std::max(last_step, mpq_class(abs(step)));
    }
    for (int v = 0; v < 3; ++v) x[v] = mid(MpfiInterval(nx[v], bits));  // a 400-bit point
  }
  return x[1];
}

}  // namespace

TEST_CASE("a flat fold's end (rotating pair 4, t near 0.36164) is proved on a narrowed run and holds the fold",
          "[independent][flat-fold]") {
  const Scene scene = rotating_pair_4();
  mpq_class step;
  const mpq_class t_star = fold_t(scene, {0.32537, 0.36164, 0.36025}, step);
  INFO("fold t = " << t_star.get_d() << ", last Newton step " << step.get_d());
  REQUIRE(step < mpq_class(1, mpz_class(1) << 200));  // converged (quadratically, from about 1e-15)
  CHECK(t_star > mpq_class(0.3616333));               // inside the run the localisation leaves
  CHECK(t_star < mpq_class(0.3616486));
  for (const char* a : {"exact", "certified"}) {
    SolveOptions o;
    o.arith = parse_arithmetic(a);
    const Solution s = solve(scene, o);
    INFO(a << ": " << (s.undecided_reasons.empty() ? std::string("-") : s.undecided_reasons[0]));
    CHECK(s.method == "bezier-independent-proved");
    CHECK(s.answer.undecided.empty());
    CHECK(s.certified);
    REQUIRE(s.answer.t_intervals.size() == 1);
    const Instant& end = s.answer.t_intervals[0].first;
    REQUIRE(end.certified());
    CHECK(*end.lo <= t_star);
    CHECK(t_star <= *end.hi);
    CHECK(*end.hi - *end.lo < Rational(1, 1000000000));
    // work: the localisation, the narrowed run's finer strips and the ends' Krawczyk tests
    CHECK(work(s, "box_tests") > 0);
    CHECK(work(s, "box_tests") < 150000);
    CHECK(work(s, "krawczyk_tests") < 40);
    CHECK(work(s, "proved_ends") == 2);
  }
  // the certificate records the finer strips and the end on the narrowed run; eccd-check's checker accepts it
  const Certificate c = certify(scene);
  const CertificateCheck ok = check_certificate(scene, c.text);
  INFO(ok.failed_claim << ": " << ok.reason);
  CHECK(ok.valid);
}

}  // namespace ECCD_UNITY_ID

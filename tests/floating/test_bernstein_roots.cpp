// The double root finder (floating/bernstein_roots.hpp: de Casteljau
// subdivision, refinement by Anderson-Björck steps on O(n) values,
// kernel/bernstein_horner.hpp, issue 21) against exact isolation (CGAL via
// exact/algebraic_roots, brackets of 2^-64) on the Δ(t) of the generated 2D
// cases of motion degree 2 to 6 (Δ of degree 48 to 144: cases/generated/2d).
#include "floating/bernstein_roots.hpp"
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;

namespace {

struct Compared {
  std::vector<FloatRoot<double>> dbl;
  std::vector<AlgebraicRoot> exact;
  int degree = 0;
};

Compared compare_case(const std::string& file) {
  Scene s = read_scene_file(file);
  const auto p = prepare_pair<H_2D>(s);
  FloatingPolicy<double> pol(Basis::bernstein, 53, 1.0);
  auto gd = characteristic_of(to_arithmetic<double, H_2D>(p, 1.0));
  REQUIRE(pol.normalise_g(gd));  // as cd_disc does
  const Bern<double> dd = discriminant_of(gd, pol);
  ExactPolicy ex;
  const auto gq = characteristic_of(to_arithmetic<Rational, H_2D>(p, Rational(1)));
  const Poly<Rational> dq = discriminant_of(gq, ex);
  Compared c;
  c.degree = dd.degree();
  BernsteinRootOptions<double> o;
  c.dbl = bernstein_roots(dd, o);
  REQUIRE(o.stopped.empty());
  c.exact = ex.roots(dq, false);
  return c;
}

double mid(const AlgebraicRoot& r) { return mpq_class((r.lo + r.hi) / 2).get_d(); }

std::vector<std::string> cases_2d() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(case_path("generated/2d"))) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("double roots of Δ agree with exact isolation on the generated 2D cases (degrees 48..144)",
          "[floating][bernstein_roots]") {
  int simple_checked = 0, files = 0;
  for (const auto& f : cases_2d()) {
    INFO(f);
    const Compared c = compare_case(f);
    ++files;
    // Every reported root or cluster lies near an exact root, and every simple exact root near a reported
    // one: 1e-6 covers a double root split or shifted by the rounding of Δ (~sqrt(1e-14 · condition)). A
    // double root (a touch) may vanish under rounding (the header's known failure mode: on 2 of the 10
    // touch cases here Δ in double keeps one strict sign near it), so it is not required.
    for (const auto& r : c.dbl) {
      INFO("double root " << r.value << (r.cluster ? " (cluster)" : ""));
      bool near = false;
      for (const auto& e : c.exact) near = near || (e.lo.get_d() - 1e-6 <= r.hi && r.lo <= e.hi.get_d() + 1e-6);
      CHECK(near);
    }
    for (const auto& e : c.exact) {
      INFO("exact root " << mid(e) << " multiplicity " << e.multiplicity);
      bool near = false;
      for (const auto& r : c.dbl) near = near || (e.lo.get_d() - 1e-6 <= r.hi && r.lo <= e.hi.get_d() + 1e-6);
      if (e.multiplicity == 1) CHECK(near);
      // A simple exact root at least 1e-3 from the others: one simple double root, to 1e-9 (the tests' double
      // tolerance).
      bool alone = e.multiplicity == 1;
      for (const auto& o : c.exact)
        if (&o != &e) alone = alone && std::fabs(mid(o) - mid(e)) > 1e-3;
      if (!alone) continue;
      int found = 0;
      for (const auto& r : c.dbl)
        if (std::fabs(r.value - mid(e)) <= 1e-9) {
          ++found;
          CHECK_FALSE(r.cluster);
          CHECK(r.lo <= r.hi);
          CHECK(r.hi - r.lo <= 1e-12);
        }
      CHECK(found == 1);
      ++simple_checked;
    }
  }
  CHECK(files >= 50);
  CHECK(simple_checked >= 31);  // the isolated simple roots of these 50 cases (31 when this test was written)
}

}  // namespace ECCD_UNITY_ID

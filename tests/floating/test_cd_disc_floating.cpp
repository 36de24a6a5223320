// The floating CD-DISC pipelines (double, MPFR) against the exact one.
// What double says on the near-touching scenes is not asserted: that
// difference is what the workbench measures (003 saw collisions reported for
// d < 1e-6; the report shows it). What is asserted: agreement on a
// well-conditioned scene, at MPFR precisions, and 003's claim that Δ's
// coefficients are more accurate built in Bernstein form than in power form.
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

namespace {
std::string brief(const Answer& a) {
  std::string s = a.collides ? "collides" : "free";
  for (const auto& [x, y] : a.intervals) s += " [" + x.approx.substr(0, 12) + ", " + y.approx.substr(0, 12) + "]";
  if (!a.undecided.empty()) s += " undecided:" + std::to_string(a.undecided.size());
  return s;
}
}  // namespace

TEST_CASE("double (every basis) reproduces the exact intervals on a well-conditioned scene", "[floating][cd_disc]") {
  Scene s = translation_scene(4, 2, rp({-10, 12}), rp({0, 1}), 3, 1, rp({0}), rp({1, -2}));
  auto ex = solve_exact(s);
  REQUIRE(ex.answer.collides);
  for (Basis b : {Basis::power, Basis::bernstein, Basis::scaled_bernstein}) {
    INFO("basis " << to_string(b));
    auto fl = solve_floating<double>(s, b, 53, 1.0);
    REQUIRE(fl.answer.intervals.size() == ex.answer.intervals.size());
    for (std::size_t i = 0; i < ex.answer.intervals.size(); ++i) {
      CHECK(std::abs(std::stod(fl.answer.intervals[i].first.approx) - std::stod(ex.answer.intervals[i].first.approx)) <
            1e-9);
      CHECK(std::abs(std::stod(fl.answer.intervals[i].second.approx) -
                     std::stod(ex.answer.intervals[i].second.approx)) < 1e-9);
    }
    CHECK(fl.answer.contacts.size() == ex.answer.contacts.size());
  }
}

TEST_CASE("variants 1-3 agree with the full answer (double)", "[floating][cd_disc][variants]") {
  Scene s = translation_scene(4, 2, rp({-10, 12}), rp({0, 1}), 3, 1, rp({0}), rp({1, -2}));
  auto full = solve_floating<double>(s, Basis::bernstein, 53, 1.0);
  auto v1 = solve_floating<double>(s, Basis::scaled_bernstein, 53, 1.0, Variant::collides);
  auto v2 = solve_floating<double>(s, Basis::bernstein, 53, 1.0, Variant::first_contact);
  auto v3 = solve_floating<double>(s, Basis::bernstein, 53, 1.0, Variant::all_contacts);
  CHECK(v1.answer.collides == full.answer.collides);
  REQUIRE(v2.answer.first_contact.has_value());
  CHECK(std::abs(std::stod(v2.answer.first_contact->approx) - std::stod(full.answer.first_contact->approx)) < 1e-12);
  CHECK(v3.answer.contacts.size() == full.answer.contacts.size());
}

TEST_CASE("MPFR at 1024 bits agrees with exact on 003 Example 2 and all its shifts", "[floating][mpfr][paper003]") {
  std::vector<std::string> names{"example2"};
  for (const char* e : {"3", "6", "9", "12", "15"}) {
    names.push_back(std::string("example2-away-1e-") + e);
    names.push_back(std::string("example2-towards-1e-") + e);
  }
  for (const auto& n : names) {
    INFO(n);
    Scene s = read_scene_file(case_path("paper003/" + n + ".json"));
    auto ex = solve_exact(s);
    auto mp = solve_floating<Mpfr>(s, Basis::bernstein, 1024, Mpfr(Q(1), 1024));
    CHECK(mp.answer.collides == ex.answer.collides);
    CHECK(mp.answer.undecided.empty());
    // Every endpoint of one answer lies within 1e-15 (compared as doubles) of an endpoint of the
    // other. (The interval count may differ: rounding noise can split the
    // double root of Δ at an isolated touch into two touches ~1e-100 apart.)
    auto ends = [](const Answer& a) {
      std::vector<double> e;
      for (const auto& [x, y] : a.intervals) {
        e.push_back(std::stod(x.approx));
        e.push_back(std::stod(y.approx));
      }
      return e;
    };
    auto covered = [](const std::vector<double>& xs, const std::vector<double>& ys) {
      for (double x : xs) {
        bool near = false;
        for (double y : ys) near = near || std::abs(x - y) < 1e-15;
        if (!near) return false;
      }
      return true;
    };
    auto em = ends(mp.answer), ee = ends(ex.answer);
    CHECK(covered(em, ee));
    CHECK(covered(ee, em));
  }
}

namespace {
std::vector<std::string> example2_family() {
  std::vector<std::string> names{"example2"};
  for (const char* e : {"3", "6", "9", "12", "15"}) {
    names.push_back(std::string("example2-away-1e-") + e);
    names.push_back(std::string("example2-towards-1e-") + e);
  }
  return names;
}
// max_i |b_i - e_i| / max_i |e_i| over the Bernstein coefficients (the exact ones e).
double relative_coefficient_error(const Bern<double>& b, const Bern<Q>& e) {
  REQUIRE(b.b.size() == e.b.size());
  Q scale = 0, worst = 0;
  for (std::size_t i = 0; i < e.b.size(); ++i) {
    Q d = abs(Q(Q(b.b[i]) - e.b[i]));  // the double converted exactly
    if (d > worst) worst = d;
    if (abs(e.b[i]) > scale) scale = abs(e.b[i]);
  }
  return Q(worst / scale).get_d();
}
}  // namespace

// 003 section VI-C: Δ computed in the power basis is unstable in double, the
// Bernstein form "numerically more stable" (and 002 IV). Measured here on the
// coefficients root isolation works on: Δ built in double from the same g_k
// (prepared input) in each basis, against the exact Δ in Bernstein form.
TEST_CASE(
    "003 Example 2 family: Δ built in double has a smaller coefficient error in Bernstein form than in power form",
    "[floating][paper003][coefficient_error]") {
  for (const auto& n : example2_family()) {
    INFO(n);
    Scene s = read_scene_file(case_path("paper003/" + n + ".json"));
    const PreparedPair2 p = prepare_pair<H_2D>(s);
    const auto gq = characteristic_of(to_arithmetic<Q, H_2D>(p, Q(1)));
    const auto gd = characteristic_of(to_arithmetic<double, H_2D>(p, 1.0));
    ExactPolicy ex;
    const Poly<Q> dq = discriminant_of(gq, ex);
    const Bern<Q> exact = to_bernstein(dq);
    const double power =
        relative_coefficient_error(discriminant_of(gd, FloatingPolicy<double>(Basis::power, 53, 1.0)), exact);
    const double bern =
        relative_coefficient_error(discriminant_of(gd, FloatingPolicy<double>(Basis::bernstein, 53, 1.0)), exact);
    INFO("relative coefficient error of Δ: power " << power << ", bernstein " << bern);
    CHECK(bern < power);
    CHECK(bern < 1e-6);
  }
}

// What double and MPFR say on the near-touch family may be wrong (that is what
// the workbench measures: 003 saw collisions reported for d < 1e-6); what must
// hold is that MPFR at 128 bits in Bernstein form, well above what these
// shifts need, agrees with the exact answer wherever it claims one.
TEST_CASE("003 Example 2 family: MPFR 128 (Bernstein) never contradicts the exact collides",
          "[floating][mpfr][paper003]") {
  for (const auto& n : example2_family()) {
    INFO(n);
    Scene s = read_scene_file(case_path("paper003/" + n + ".json"));
    auto ex = solve_exact(s);
    auto m128 = solve_floating<Mpfr>(s, Basis::bernstein, 128, Mpfr(Q(1), 128));
    INFO("exact " << brief(ex.answer) << "; mpfr:128 " << brief(m128.answer));
    // a collision found is a claim; "free" is one only when nothing is left undecided
    if (m128.answer.collides)
      CHECK(ex.answer.collides);
    else if (m128.answer.undecided.empty())
      CHECK_FALSE(ex.answer.collides);
  }
}

}  // namespace ECCD_UNITY_ID

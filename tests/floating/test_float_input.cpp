// Issue 14, points 1-4: floating pipelines that start from the scene's own
// numbers (input mode rounded), scale by powers of two, always terminate, and
// say "undecided" where their running error bound cannot decide.
// Every floating answer here is checked against the exact pipeline on the same
// scene: it may be undecided, never confidently wrong (same `collides`, same
// number of intervals, ends within 1e-6, when nothing is undecided).
// The scenes are in tests/data/float/ (made by tests/data/float/round_scene.py
// and the text).
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "number/running_error.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const std::string kData = std::string(ECCD_SOURCE_DIR) + "/tests/data/float/";

nlohmann::json solve_with(const Scene& s, const std::string& arith, const std::string& method = "bezier",
                          InputMode input = InputMode::rounded) {
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  std::tie(o.method, o.grid) = parse_method(method);
  o.input = input;
  return solution_to_json(solve(s, o));
}

double approx(const nlohmann::json& i) { return std::stod(i["approx"].get<std::string>()); }

// "" if `fl` is consistent with the exact answer `ex` (or undecided), else
// what is wrong. tol: how far an interval end may be (the grid of sampling:N
// and marching:N puts their ends up to 1/N off by design).
std::string confidently_wrong(const nlohmann::json& fl, const nlohmann::json& ex, double tol = 1e-6) {
  if (!fl["undecided"].empty()) return "";
  if (fl["collides"] != ex["collides"]) return "collides differs";
  if (fl["intervals"].size() != ex["intervals"].size()) return "number of intervals differs";
  for (std::size_t i = 0; i < ex["intervals"].size(); ++i)
    for (int k = 0; k < 2; ++k)
      if (std::abs(approx(fl["intervals"][i][k]) - approx(ex["intervals"][i][k])) > tol)
        return "an interval end is off by more than tol";
  return "";
}

// Runs arith under a deadline; checks it ended within the deadline (plus slack) and is not confidently wrong.
void check_run(const Scene& s, const nlohmann::json& ex, const std::string& arith, const std::string& method,
               double budget, InputMode input = InputMode::rounded) {
  INFO(s.name << " " << arith << " " << method << " input " << to_string(input));
  // the budget and the bound are processor time of this thread (kernel/budget.hpp): a busy machine changes neither
  const double t0 = thread_cpu_seconds();
  nlohmann::json fl;
  {
    ScopedDeadline d(budget, DeadlineClock::thread_cpu);
    fl = solve_with(s, arith, method, input);
  }
  double secs = thread_cpu_seconds() - t0;
  INFO("answer " << fl["collides"] << " intervals " << fl["intervals"].size() << " undecided " << fl["undecided"].size()
                 << " reasons " << fl["undecided_reasons"].dump() << " in " << secs << " s");
  CHECK(secs < budget + 2.0);
  CHECK(fl["input"] == to_string(input));
  double tol = 1e-6;
  for (const char* grid : {"sampling:", "marching:"})
    if (method.rfind(grid, 0) == 0) tol = 1.0 / std::stod(method.substr(9));
  CHECK(confidently_wrong(fl, ex, tol) == "");
}

}  // namespace

TEST_CASE(
    "a degree-2 kinematic scene written with 6 significant digits: double and MPFR answer, never confidently wrong",
    "[float-input][floating][budget]") {
  Scene s = read_scene_file(kData + "kinematic-deg2-colliding-6digits.json");
  nlohmann::json ex = solve_with(s, "exact");
  REQUIRE(ex["collides"] == true);
  for (const char* a : {"double", "mpfr:53", "mpfr:128"}) {
    check_run(s, ex, a, "bezier", 5.0);
    check_run(s, ex, a, "bezier", 5.0, InputMode::prepared);
  }
  // The collision here is well conditioned: double finds it, to about 1e-5 at least.
  nlohmann::json d = solve_with(s, "double");
  REQUIRE(d["intervals"].size() == 1);
  CHECK(std::abs(approx(d["intervals"][0][0]) - approx(ex["intervals"][0][0])) < 1e-5);
}

TEST_CASE("003 Example 2 in rounded input (Δ of degree 192): an answer within the budget, never confidently wrong",
          "[float-input][floating][paper003][budget]") {
  Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  nlohmann::json ex = solve_with(s, "exact");
  for (const char* a : {"double", "mpfr:53", "mpfr:128"}) check_run(s, ex, a, "bezier", 5.0);
  nlohmann::json d = solve_with(s, "double");
  CHECK(d["projection_degree"] == 192);  // no exact gcd in rounded input (floating/rounded_input.hpp)
  CHECK(solve_with(s, "double", "bezier", InputMode::prepared)["projection_degree"] == 96);
}

TEST_CASE("003 Example 2 with a semi-axis 1.333333333333 and a shape entry -1e-300 terminates",
          "[float-input][floating][budget]") {
  Scene s = read_scene_file(kData + "paper003-example2-tiny-entries.json");
  nlohmann::json ex = solve_with(s, "exact");
  for (const char* a : {"double", "mpfr:53", "mpfr:128"}) {
    check_run(s, ex, a, "bezier", 5.0);
    check_run(s, ex, a, "bezier", 5.0, InputMode::prepared);
  }
}

TEST_CASE("the issue's 3D translating pair: every floating method ends within its budget, never confidently wrong",
          "[float-input][floating][ccd3][budget]") {
  Scene s = read_scene_file(kData + "missed-0.021-3d.json");
  nlohmann::json ex = solve_with(s, "exact");
  REQUIRE(ex["collides"] == true);
  for (const char* m : {"projection", "sampling:200", "marching:60"}) check_run(s, ex, "double", m, 5.0);
  check_run(s, ex, "mpfr:64", "projection", 5.0);
}

TEST_CASE("a deadline that has passed ends every floating method with undecided, never an answer",
          "[float-input][floating]") {
  Scene s2 = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  Scene s3 = read_scene_file(kData + "missed-0.021-3d.json");
  ScopedDeadline d(1e-9);
  while (!deadline_passed()) {}
  for (const char* m : {"bezier", "projection", "sampling:50", "marching:50"}) {
    INFO(m);
    nlohmann::json r = solve_with(s3, "double", m);
    CHECK(!r["undecided"].empty());
    CHECK(!r["undecided_reasons"].empty());
  }
  nlohmann::json r = solve_with(s2, "double");
  CHECK(!r["undecided"].empty());
}

TEST_CASE("numbers beyond double's range: overflow is reported as undecided with the reason",
          "[float-input][floating]") {
  Scene s = read_scene_file(kData + "kinematic-deg2-colliding-6digits.json");
  // Scale object b's motion coefficients to 1e200: N(t) then has entries ~1e400, beyond double.
  auto& k = std::get<KinematicMotion>(s.b.motion);
  for (auto& p : k.d)
    for (auto& c : p.c) c *= Rational(mpz_class("1" + std::string(200, '0')));
  nlohmann::json d = solve_with(s, "double");
  INFO(d.dump());
  REQUIRE(!d["undecided"].empty());
  REQUIRE(!d["undecided_reasons"].empty());
  CHECK(d["undecided_reasons"][0].get<std::string>().find("overflow") != std::string::npos);
  // MPFR's exponent range holds it: an answer, as exact's (the motion is only rescaled, the answer is the same).
  nlohmann::json ex = solve_with(s, "exact");
  nlohmann::json m = solve_with(s, "mpfr:128");
  CHECK(confidently_wrong(m, ex) == "");
}

TEST_CASE(
    "Bounded<double>: the value is plain double's, the bound covers the true error, and cancellation is uncertain",
    "[float-input][running-error]") {
  using B = Bounded<double>;
  B one(1.0, 0);
  auto in = [&](const char* q) { return scalar_traits<B>::from_rational(mpq_class(q), one); };
  B a = in("1/10"), b = in("2/10"), c = in("3/10");
  B r = (a + b) - c;
  CHECK(r.value() == (0.1 + 0.2) - 0.3);  // same operations as plain double
  CHECK(sign(r) == Sign::uncertain);      // exact value 0: no sign can be claimed
  CHECK(sign(B(1) + B(1)) == Sign::positive);
  CHECK(sign(B(2) - B(2)) == Sign::zero);  // exact inputs, exact result
  // A polynomial with cancellation, evaluated at an exact point: |value - exact| <= bound.
  mpq_class x("7/9"), exact = 0;
  B xb = scalar_traits<B>::from_rational(x, one), acc(0);
  const char* coef[] = {"-1/3", "5/7", "-11/13", "2/3", "1/1000000"};
  for (const char* k : coef) {
    acc = acc * xb + in(k);
    exact = exact * x + mpq_class(k);
  }
  double err = std::abs(mpq_class(mpq_class(acc.value()) - exact).get_d());
  CHECK(err <= acc.bound());
  CHECK(acc.bound() < 1e-14);  // and the bound is not vacuous
  // Division by a value within its bound of 0: infinite bound, uncertain sign.
  CHECK(sign(B(1) / r) == Sign::uncertain);
}

}  // namespace ECCD_UNITY_ID

// The guard on the needle family (compare/needle_family.hpp): a unit circle or
// sphere and a needle of semi-axes (1, R[, 1]), R = 1 ... 1e300, touching or
// missing by 1e-3 ... 1e-12. Every guarded floating answer (double and MPFR,
// the default method of each dimension) agrees with the exact answer or says
// undecided: never a confident wrong answer. Runs are bounded by processor
// time (kernel/budget.hpp), so a busy machine changes nothing.
#include "api/solve.hpp"
#include "compare/needle_family.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <sstream>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Scene scene_of(const NeedleSpec& sp) {
  GeneratedScene g = needle_scene(sp);
  return parse_scene(g.doc.dump(), g.name);
}

// "" if `got` (no undecided instant) agrees with `ex` (collides, the intervals' ends within tol), else what differs.
std::string confident_difference(const Answer& got, const Answer& ex, double tol) {
  if (got.collides != ex.collides)
    return std::string("collides ") + (got.collides ? "true" : "false") + ", exact " + (ex.collides ? "true" : "false");
  if (got.intervals.size() != ex.intervals.size())
    return std::to_string(got.intervals.size()) + " interval(s), exact " + std::to_string(ex.intervals.size());
  for (std::size_t i = 0; i < got.intervals.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      const double a = k ? got.intervals[i].second.value : got.intervals[i].first.value;
      const double b = k ? ex.intervals[i].second.value : ex.intervals[i].first.value;
      if (!(std::fabs(a - b) <= tol)) {
        std::ostringstream o;
        o << "interval " << i << " [" << got.intervals[i].first.approx << ", " << got.intervals[i].second.approx
          << "], exact [" << ex.intervals[i].first.approx << ", " << ex.intervals[i].second.approx << "]";
        return o.str();
      }
    }
  return "";
}

Solution run(const Scene& s, const std::string& arith, double cpu_budget) {
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  o.guard = Guard::bound;
  ScopedDeadline d(cpu_budget, DeadlineClock::thread_cpu);
  return solve(s, o);
}

}  // namespace

TEST_CASE("needle family: the scenes are what their construction says (exact pipeline)", "[needle][generator]") {
  for (const auto& sp : needle_family_plan()) {
    if (sp.r_exponent != 0 && sp.r_exponent != 20 && sp.r_exponent != 300)
      continue;  // the construction does not depend on R
    const Scene s = scene_of(sp);
    INFO(s.name);
    SolveOptions o;
    const Answer a = solve(s, o).answer;
    REQUIRE(a.undecided.empty());
    if (sp.kind == "miss") {
      CHECK_FALSE(a.collides);
    } else {
      REQUIRE(a.collides);
      REQUIRE(a.intervals.size() == 1);
      const Rational t0 = sp.kind == "touch-end" ? Rational(1) : Rational(1, 2);
      CHECK(a.intervals[0].first.lo.has_value());
      CHECK((*a.intervals[0].first.lo <= t0));
      CHECK((*a.intervals[0].second.hi >= t0));
      CHECK(a.intervals[0].second.value - a.intervals[0].first.value < 1e-12);  // one instant: a touch
    }
  }
}

TEST_CASE("needle family: the hard cases are undecided or right, never collides on a miss", "[needle][guard]") {
  // 3D, R = 1e20, missing by 1e-3: a guard trusting the peak found says "collides" on [0.4826, 0.5174] in double
  {
    const Scene s = scene_of({3, 20, "miss", 3});
    const Solution d = run(s, "double", 20);
    INFO("double: collides " << d.answer.collides << ", " << d.answer.intervals.size() << " interval(s), "
                             << d.answer.undecided.size() << " undecided");
    CHECK((!d.answer.collides || !d.answer.undecided.empty()));
    CHECK(d.answer.intervals.empty());
  }
  // R = 1e100: the same in mpfr:128 and mpfr:256
  for (const std::string arith : {"mpfr:128", "mpfr:256"}) {
    const Scene s = scene_of({3, 100, "miss", 3});
    const Solution m = run(s, arith, 20);
    INFO(arith << ": collides " << m.answer.collides << ", " << m.answer.intervals.size() << " interval(s)");
    CHECK(m.answer.intervals.empty());
  }
  // x(t) = -3 + t, R = 1e20: a touch at t = 1 only (not an interval [0.99994, 1])
  {
    const Scene s = scene_of({3, 20, "touch-end", 0});
    const Solution d = run(s, "double", 20);
    for (const auto& iv : d.answer.intervals) {
      INFO("interval [" << iv.first.approx << ", " << iv.second.approx << "]");
      CHECK(iv.first.value > 1 - 1e-6);
    }
  }
}

TEST_CASE("needle family: every guarded answer agrees with exact or is undecided", "[needle][guard]") {
  int runs = 0, undecided = 0;
  std::ostringstream wrong;
  for (const auto& sp : needle_family_plan()) {
    const Scene s = scene_of(sp);
    SolveOptions eo;
    const Answer ex = solve(s, eo).answer;
    for (const std::string arith : {"double", "mpfr:128", "mpfr:256"}) {
      const Solution got = run(s, arith, 10);
      ++runs;
      if (!got.answer.undecided.empty()) {
        ++undecided;
        continue;
      }
      const std::string why = confident_difference(got.answer, ex, 1e-6);
      if (!why.empty()) wrong << "  " << s.name << " " << arith << ": " << why << "\n";
    }
  }
  std::cout << "[needle] " << runs << " guarded runs, " << undecided << " undecided\n";
  INFO(wrong.str());
  CHECK(wrong.str().empty());
}

}  // namespace ECCD_UNITY_ID

// kernel/budget.hpp: a run's deadline on the running thread. Checked against
// the header's statement, without asserting any duration: a deadline of
// 1 ns is waited for by a loop bounded by a count of clock reads (it has
// passed long before the count runs out), then
//   - deadline_passed() stays true, check_deadline throws BudgetExhausted
//     naming the place and the budget ("time budget of ... s exhausted", with
//     "of processor time" for the thread-CPU clock);
//   - a polynomial product (kernel/polynomial.hpp) asks the deadline and throws;
//   - nested scopes keep the earlier deadline of each clock and restore the
//     outer state on exit; seconds <= 0 sets none; the deadline is per thread;
//   - a work budget passes at exactly its count of units (each deadline check
//     one, a product its coefficient products), whatever the clock says, and
//     the count of units done only grows across scopes.
#include "kernel/budget.hpp"
#include "kernel/polynomial.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <thread>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// Reads the clock until the deadline has passed; a count bounds the loop.
bool wait_for_deadline() {
  for (long k = 0; k < 200000000L; ++k)
    if (deadline_passed()) return true;
  return false;
}

}  // namespace

TEST_CASE("budget: no deadline set, nothing passes", "[kernel][budget]") {
  CHECK_FALSE(deadline_passed());
  CHECK_NOTHROW(check_deadline("nowhere"));
  {
    ScopedDeadline none(0);  // seconds <= 0: no deadline
    ScopedDeadline neg(-5, DeadlineClock::thread_cpu);
    CHECK_FALSE(deadline_passed());
  }
  const double a = thread_cpu_seconds(), b = thread_cpu_seconds();
  CHECK(a >= 0);
  CHECK(b >= a);  // processor time does not run backwards
}

TEST_CASE("budget: a passed wall deadline stays passed, throws with the place, and is restored on exit",
          "[kernel][budget]") {
  {
    ScopedDeadline outer(1000);
    CHECK_FALSE(deadline_passed());
    {
      ScopedDeadline inner(1e-9);  // the earlier one wins
      REQUIRE(wait_for_deadline());
      CHECK(deadline_passed());
      CHECK(deadline_passed());  // and from then on
      try {
        check_deadline("root isolation");
        FAIL("no BudgetExhausted");
      } catch (const BudgetExhausted& e) {
        const std::string w = e.what();
        CHECK(w.rfind("root isolation: time budget of ", 0) == 0);
        CHECK(w.find("exhausted") != std::string::npos);
        CHECK(w.find("processor") == std::string::npos);
      }
      // the pipelines' products ask the deadline too
      const Poly<Rational> p({Rational(1), Rational(2)});
      CHECK_THROWS_AS(p * p, BudgetExhausted);
    }
    CHECK_FALSE(deadline_passed());  // the outer state is back
    {
      ScopedDeadline later(5000);  // a later deadline does not replace the earlier one
      CHECK(deadline_reason() == "time budget of 1000.0 s exhausted");
    }
  }
  CHECK_FALSE(deadline_passed());
}

TEST_CASE("budget: the thread-CPU clock, and a deadline belongs to its thread", "[kernel][budget]") {
  ScopedDeadline cpu(1e-9, DeadlineClock::thread_cpu);
  REQUIRE(wait_for_deadline());
  CHECK(deadline_reason().find("of processor time") != std::string::npos);
  bool other = true;
  std::thread t([&] { other = deadline_passed(); });
  t.join();
  CHECK_FALSE(other);  // another thread has no deadline
}

TEST_CASE("budget: a work budget passes at its count of units, on every machine", "[kernel][budget]") {
  const unsigned long long start = work_units_done();
  long checks = 0;
  {
    ScopedWorkBudget work(1000);
    // the ScopedWorkBudget's own check counts nothing; each deadline_passed() counts one unit
    while (!deadline_passed() && checks < 100000) ++checks;
    CHECK(checks == 999);  // the 1000th check reaches the budget
    CHECK(deadline_reason() == "work budget of 1000 units exhausted");
    try {
      check_deadline("shots");
      FAIL("no BudgetExhausted");
    } catch (const BudgetExhausted& e) {
      CHECK(std::string(e.what()) == "shots: work budget of 1000 units exhausted");
    }
  }
  CHECK_FALSE(deadline_passed());            // the outer state is back
  CHECK(work_units_done() >= start + 1001);  // the count did not go back with the scope
  {
    // A product counts its coefficient products (here 3 x 3 = 9, then one unit for its deadline check if it has
    // 64 or more); a budget of 20 units holds two of them and not a third.
    ScopedWorkBudget work(20);
    const Poly<Rational> p({Rational(1), Rational(2), Rational(3)});
    const unsigned long long before = work_units_done();
    CHECK_NOTHROW(p * p);
    CHECK(work_units_done() - before == 9);
    CHECK_NOTHROW(p * p);
    CHECK_FALSE(deadline_passed());  // 18 + 1 units
    CHECK(deadline_passed());        // the 20th
    CHECK_THROWS_AS(p * p, BudgetExhausted);
  }
  {
    ScopedWorkBudget outer(50);
    {
      ScopedWorkBudget later(5000);  // the earlier budget holds
      CHECK(deadline_reason() == "work budget of 50 units exhausted");
      ScopedDeadline time(1000);  // and a time deadline beside it
      for (int k = 0; k < 49; ++k) CHECK_FALSE(deadline_passed());
      CHECK(deadline_passed());
    }
    CHECK(deadline_passed());  // the outer budget is the same budget, and its units are spent
  }
  CHECK_FALSE(deadline_passed());
  ScopedWorkBudget none(0);  // 0 units: no budget
  CHECK_FALSE(deadline_passed());
}

}  // namespace ECCD_UNITY_ID

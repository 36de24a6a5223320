// kernel/budget.hpp: a run's deadline on the running thread. Checked against
// the header's statement, without asserting any duration: a deadline of
// 1 ns is waited for by a loop bounded by a count of clock reads (it has
// passed long before the count runs out), then
//   - deadline_passed() stays true, check_deadline throws BudgetExhausted
//     naming the place and the budget ("time budget of ... s exhausted", with
//     "of processor time" for the thread-CPU clock);
//   - a polynomial product (kernel/polynomial.hpp) asks the deadline and throws;
//   - nested scopes keep the earlier deadline of each clock and restore the
//     outer state on exit; seconds <= 0 sets none; the deadline is per thread.
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

}  // namespace ECCD_UNITY_ID

#pragma once
// Budget: the time a pipeline run may take, and how a run learns it is over.
//
// Statement. Every pipeline run terminates: each method has
// its own work bounds (subdivision depth, shots, pieces), and on top of them
// each run has a deadline. The deadline is set once, by whoever starts the run
// (eccd::solve, the harness, certify, regress, report), with a
// `ScopedDeadline` on the running thread; the loops of the pipelines ask
// `deadline_passed()` (one clock read: an iteration of an MPFR loop can take
// milliseconds, so no call is skipped; only a small polynomial product, well
// under a microsecond, reads the flag an earlier check set instead of the
// clock: check_deadline_product) and
//   - a floating pipeline stops refining and reports the part of [0, 1] it has
//     not resolved as undecided, with the reason "time budget" (never a guess);
//   - the exact pipeline, which has nothing honest to say about a part it has
//     not decided, throws BudgetExhausted, which the command line turns into
//     its own exit code (5, README "Exit codes").
// Two clocks. A deadline is measured on one of
//   - DeadlineClock::wall, the steady clock: what a user's `--time-limit` of
//     seconds means (the time they wait), the command line's choice;
//   - DeadlineClock::thread_cpu, the processor time of the running thread
//     (CLOCK_THREAD_CPUTIME_ID): the work the run did, whatever else the
//     machine runs. The harness (compare/harness.hpp run_bounded) and the tests
//     bound runs this way, so that which runs are undecided, and whether a run
//     stops in time, do not depend on how busy the machine is. Reading it is a
//     system call (a few hundred nanoseconds), paid only by runs that set one.
//   - a work budget (ScopedWorkBudget): a number of work units, counted by
//     the checks themselves (each deadline_passed() one unit, each polynomial
//     product its coefficient products, check_deadline_product) and by the
//     de Casteljau triangles (count_work: one unit per step), so that
//     where a run stops is the same on every machine and under any load: the
//     same scene gives the same answer. The guarded face's second look
//     (api/solve.cpp) is bounded this way.
// All may be set at once (a harness budget inside solve's default limit);
// the run stops at the first that passes. Nested scopes keep, per clock, the
// earlier deadline and restore the outer ones on exit; the count of work units
// done only grows (work_units_done()), whatever the scopes.
// No paper section: this is the workbench's own contract with its users.
// Requirements on T: none (not templated).
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <time.h>

namespace eccd {

using Clock = std::chrono::steady_clock;

enum class DeadlineClock { wall, thread_cpu };

// A resource budget ran out while solving (time, memory or a work bound that
// the exact pipeline cannot turn into "undecided").
class BudgetExhausted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Processor time of the running thread, in seconds.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

namespace detail {
struct DeadlineState {
  Clock::time_point at = Clock::time_point::max();  // wall deadline
  double cpu_at = -1;                               // thread-CPU deadline in seconds (< 0: none)
  double seconds = 0;                               // the budget as given, for messages
  bool cpu = false;                                 // the message's budget is processor time
  bool work = false;                                // the message's budget is work units
  bool passed = false;
  unsigned long long work_at = 0;    // work-unit deadline: passed once work_done reaches it (0: none)
  unsigned long long work_done = 0;  // work units counted on this thread so far (never restored by a scope)
};
inline DeadlineState& deadline_state() {
  thread_local DeadlineState s;
  return s;
}
inline bool deadline_reached(DeadlineState& s) {
  if (s.at != Clock::time_point::max() && Clock::now() >= s.at) return true;
  if (s.cpu_at >= 0 && thread_cpu_seconds() >= s.cpu_at) return true;
  if (s.work_at != 0 && s.work_done >= s.work_at) return true;
  return false;
}
inline bool any_deadline(const DeadlineState& s) {
  return s.at != Clock::time_point::max() || s.cpu_at >= 0 || s.work_at != 0;
}
}  // namespace detail

namespace detail {
// The deadline state when a scope began, put back when it ends, but for the count of work done (which only grows).
// A scope's constructor then sets its own deadline (name_budget: the message's words).
class RestoredOnExit {
 public:
  RestoredOnExit() : saved_(deadline_state()) {}
  ~RestoredOnExit() {
    auto& s = deadline_state();
    const unsigned long long done = s.work_done;
    s = saved_;
    s.work_done = done;
  }
  RestoredOnExit(const RestoredOnExit&) = delete;
  RestoredOnExit& operator=(const RestoredOnExit&) = delete;

 private:
  DeadlineState saved_;
};
inline void name_budget(DeadlineState& s, double amount, bool cpu, bool work) {
  s.seconds = amount;
  s.cpu = cpu;
  s.work = work;
}
}  // namespace detail

// Sets the running thread's deadline to now + seconds on `clock` (seconds <= 0:
// none) for its lifetime; nested scopes keep the earlier deadline of each clock
// and restore the outer ones on exit.
class ScopedDeadline : detail::RestoredOnExit {
 public:
  explicit ScopedDeadline(double seconds, DeadlineClock clock = DeadlineClock::wall) {
    auto& s = detail::deadline_state();
    if (seconds > 0) {
      if (clock == DeadlineClock::wall) {
        auto at = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
        if (at < s.at) {
          s.at = at;
          detail::name_budget(s, seconds, false, false);
        }
      } else {
        double at = thread_cpu_seconds() + seconds;
        if (s.cpu_at < 0 || at < s.cpu_at) {
          s.cpu_at = at;
          detail::name_budget(s, seconds, true, false);
        }
      }
    }
    s.passed = s.passed || detail::deadline_reached(s);
  }
};

// A budget of work units for its lifetime (units == 0: none), on top of the time deadlines, restored on exit
// as ScopedDeadline's (the earlier of nested work budgets holds). The units are counted where the pipelines
// already ask for their deadline, so a run meets a work budget at the same step on every machine.
class ScopedWorkBudget : detail::RestoredOnExit {
 public:
  explicit ScopedWorkBudget(unsigned long long units) {
    auto& s = detail::deadline_state();
    if (units > 0) {
      const unsigned long long at = s.work_done + units;
      if (s.work_at == 0 || at < s.work_at) {
        s.work_at = at;
        detail::name_budget(s, double(units), false, true);
      }
    }
    s.passed = s.passed || detail::deadline_reached(s);
  }
};

// Work done without a deadline check of its own (a de Casteljau triangle, whose callers' loops ask):
// counted toward a work budget, so that the units follow the arithmetic operations a run does.
inline void count_work(std::size_t units) { detail::deadline_state().work_done += units; }

// The work units this thread has counted so far (only grows): the difference over a run is its work.
inline unsigned long long work_units_done() { return detail::deadline_state().work_done; }

// True once the running thread's deadline has passed (and from then on). Counts one work unit.
inline bool deadline_passed() {
  auto& s = detail::deadline_state();
  ++s.work_done;
  if (s.passed) return true;
  if (!detail::any_deadline(s)) return false;
  s.passed = detail::deadline_reached(s);
  return s.passed;
}

// The budget in words, for "undecided" reasons and error messages.
inline std::string deadline_reason() {
  const auto& s = detail::deadline_state();
  if (s.work) return "work budget of " + std::to_string((unsigned long long)s.seconds) + " units exhausted";
  return "time budget of " + std::to_string(s.seconds).substr(0, 6) + " s" + (s.cpu ? " of processor time" : "") +
         " exhausted";
}

// For code that cannot report "undecided" (the exact pipeline): throws once the deadline passed.
inline void check_deadline(const char* where) {
  if (deadline_passed()) throw BudgetExhausted(std::string(where) + ": " + deadline_reason());
}

// The check of a polynomial product of `work` coefficient products: as check_deadline, except that a small
// product (fewer than 64 coefficient products, well under a microsecond in double) reads no clock and only
// throws once another check has seen the deadline pass; a clock read would cost it a tenth of its time, and
// the loops around small products (subdivision, root refinement) check the clock themselves.
inline void check_deadline_product(std::size_t work) {
  auto& s = detail::deadline_state();
  s.work_done += work;
  if (work < 64 ? s.passed : deadline_passed())
    throw BudgetExhausted(std::string("polynomial product: ") + deadline_reason());
}

}  // namespace eccd

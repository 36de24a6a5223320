#pragma once
// Budget: the time a pipeline run may take, and how a run learns it is over.
//
// Statement. Every pipeline run terminates (issues 14 and 15): each method has
// its own work bounds (subdivision depth, shots, pieces), and on top of them
// each run has a wall-clock deadline. The deadline is set once, by whoever
// starts the run (eccd::solve, the harness, certify, regress, report), with a
// `ScopedDeadline` on the running thread; the loops of the pipelines ask
// `deadline_passed()` (one steady-clock read, tens of nanoseconds: an
// iteration of an MPFR loop can take milliseconds, so no call is skipped) and
//   - a floating pipeline stops refining and reports the part of [0, 1] it has
//     not resolved as undecided, with the reason "time budget" (never a guess);
//   - the exact pipeline, which has nothing honest to say about a part it has
//     not decided, throws BudgetExhausted, which the command line turns into
//     its own exit code (5, README "Exit codes").
// No paper section: this is the workbench's own contract with its users.
// Requirements on T: none (not templated).
#include <chrono>
#include <stdexcept>
#include <string>

namespace eccd {

using Clock = std::chrono::steady_clock;

// A resource budget ran out while solving (time, memory or a work bound that
// the exact pipeline cannot turn into "undecided").
class BudgetExhausted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {
struct DeadlineState {
  Clock::time_point at = Clock::time_point::max();
  double seconds = 0;  // the budget as given, for messages
  bool passed = false;
};
inline DeadlineState& deadline_state() {
  thread_local DeadlineState s;
  return s;
}
}  // namespace detail

// Sets the running thread's deadline to now + seconds (seconds <= 0: none) for
// its lifetime; nested scopes keep the earlier of the two deadlines and
// restore the outer one on exit.
class ScopedDeadline {
 public:
  explicit ScopedDeadline(double seconds) : saved_(detail::deadline_state()) {
    auto& s = detail::deadline_state();
    if (seconds > 0) {
      auto at = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
      if (at < s.at) { s.at = at; s.seconds = seconds; }
    }
    s.passed = Clock::now() >= s.at;
  }
  ~ScopedDeadline() { detail::deadline_state() = saved_; }
  ScopedDeadline(const ScopedDeadline&) = delete;
  ScopedDeadline& operator=(const ScopedDeadline&) = delete;

 private:
  detail::DeadlineState saved_;
};

// True once the running thread's deadline has passed (and from then on).
inline bool deadline_passed() {
  auto& s = detail::deadline_state();
  if (s.passed) return true;
  if (s.at == Clock::time_point::max()) return false;
  s.passed = Clock::now() >= s.at;
  return s.passed;
}

// The budget in words, for "undecided" reasons and error messages.
inline std::string deadline_reason() {
  return "time budget of " + std::to_string(detail::deadline_state().seconds).substr(0, 6) + " s exhausted";
}

// For code that cannot report "undecided" (the exact pipeline): throws once the deadline passed.
inline void check_deadline(const char* where) {
  if (deadline_passed()) throw BudgetExhausted(std::string(where) + ": " + deadline_reason());
}

}  // namespace eccd

// Time left of a run of tasks of several kinds (app/time_left.hpp), on
// hand-computed cases (what tests/app/test_cli_report.cpp and
// test_progress.cpp check — a synthetic report plan, the rate, the cadence of
// a log — is not repeated):
//  - cost(k): the mean of kind k's finished tasks; a kind with none its prior
//    times measured seconds / measured prior units over all finished tasks;
//  - wall(): the work left over min(workers, tasks) busy workers (at least
//    one), never below the longest running task's rest; a running task of an
//    unmeasured kind raises that kind's cost to the time it has run;
//  - time_left_text rounds to whole seconds (59.6 s is "1 min 0 s"), never
//    negative, and switches units at 60 s and 3600 s;
//  - ProgressCadence: the last line once, on a terminal too; begin/end
//    strings for a terminal redraw and a log.
#include "app/time_left.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("time left: costs of measured and unmeasured kinds", "[app][time-left]") {
  TimeLeft t({2.0, 8.0, 0.5});
  CHECK_FALSE(t.measured());
  CHECK_FALSE(t.wall({1, 1, 1}, {}, 4).has_value());
  t.add(0, 3.0);
  t.add(0, 5.0);  // kind 0: mean 4 s; 8 s measured for 4 prior units: 2 s per unit
  CHECK(t.measured());
  CHECK(t.cost(0) == 4.0);
  CHECK(t.cost(1) == 16.0);  // 8 units x 2 s
  CHECK(t.cost(2) == 1.0);   // 0.5 units x 2 s
  t.add(2, 0.25);            // kind 2 measured: 0.25 s; the scale is now 8.25 s / 4.5 units
  CHECK(t.cost(2) == 0.25);
  CHECK(t.cost(1) == Approx(8.0 * 8.25 / 4.5));
}

TEST_CASE("time left: wall time over the busy workers, never below the longest rest", "[app][time-left]") {
  TimeLeft t({1.0, 1.0});
  t.add(0, 2.0);
  t.add(1, 6.0);  // kind 0: 2 s, kind 1: 6 s
  // 3 of kind 0 and 1 of kind 1 queued = 12 s of work; 4 tasks on 8 workers: 4 busy, 3 s.
  CHECK(*t.wall({3, 1}, {}, 8) == Approx(3.0));
  // 3 queued of kind 0 (6 s) and a kind-1 task running for 1 s (5 s to go): 4 tasks on 4 busy workers give
  // 11 / 4 = 2.75 s, but the running task alone needs 5 s more.
  CHECK(*t.wall({3, 0}, {{1, 1.0}}, 8) == Approx(5.0));
  // One worker: the sum.
  CHECK(*t.wall({3, 1}, {}, 1) == Approx(12.0));
  // No workers given: still one busy.
  CHECK(*t.wall({3, 1}, {}, 0) == Approx(12.0));
  // Nothing left.
  CHECK(*t.wall({0, 0}, {}, 3) == 0.0);
  // A running task of a measured kind does not raise its cost: an overdue one has no rest left.
  CHECK(*t.wall({1, 0}, {{0, 50.0}}, 1) == Approx(2.0));
  // A running task of an unmeasured kind raises that kind's cost to its run time: prior-scaled 4 s (2 units at
  // 8 s / 2 units), but running for 9 s: each queued one counts 9 s, the running one 0.
  TimeLeft u({1.0, 1.0, 1.0});
  u.add(0, 2.0);
  u.add(1, 6.0);  // 8 s for 2 units: 4 s per unit; kind 2 unmeasured: 4 s
  CHECK(*u.wall({0, 0, 2}, {}, 1) == Approx(8.0));
  CHECK(*u.wall({0, 0, 2}, {{2, 9.0}}, 1) == Approx(18.0));
  CHECK(*u.wall({0, 0, 2}, {{2, 3.0}}, 1) == Approx(8.0 + 1.0));  // 3 s run of 4: 1 s to go
}

TEST_CASE("time left: text and progress-line framing", "[app][time-left]") {
  CHECK(time_left_text(0.0) == "about 0 s left");
  CHECK(time_left_text(-5.0) == "about 0 s left");
  CHECK(time_left_text(59.4) == "about 59 s left");
  CHECK(time_left_text(59.6) == "about 1 min 0 s left");
  CHECK(time_left_text(3599.0) == "about 59 min 59 s left");
  CHECK(time_left_text(3600.0) == "about 1 h 0 min left");
  CHECK(time_left_text(90061.0) == "about 25 h 1 min left");
  ProgressCadence tty(true, 10);
  CHECK(tty.tty());
  CHECK(tty.due(0, 0.0));
  CHECK_FALSE(tty.due(5, 0.1));   // within 0.5 s of the last redraw
  CHECK(tty.due(10, 0.2));        // the end, at once
  CHECK_FALSE(tty.due(10, 5.0));  // and once
  CHECK(std::string(tty.end(false)) == "\x1b[K");
  CHECK(std::string(tty.end(true)) == "\x1b[K\n");
  ProgressCadence log(false, 0);  // an empty run counts as one task
  CHECK_FALSE(log.tty());
  CHECK(log.due(0, 0.0));  // the first line
  CHECK(log.due(1, 0.0));  // done
  CHECK_FALSE(log.due(1, 1.0));
  CHECK(std::string(log.end(true)) == "\n");
}

}  // namespace ECCD_UNITY_ID

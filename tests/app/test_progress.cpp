// Progress of long commands (app/time_left.hpp): when a line is printed on a
// terminal and in a log, the time left from the measured rate ("unknown"
// before there is one), and `eccd table` printing each row as its scene
// finishes, its progress only on stderr.
#include "app/time_left.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::clitest;
namespace fs = std::filesystem;

TEST_CASE("ProgressCadence: a log gets one line per step of 5 %, a terminal a redraw at most every 0.5 s",
          "[progress]") {
  ProgressCadence log(false, 200);
  int lines = 0;
  for (long done = 0; done <= 200; ++done)
    if (log.due(done, 0.01 * double(done))) ++lines;  // 2 s in all: no heartbeat
  CHECK(lines == 21);                                 // 0 %, 5 %, ..., 100 %
  CHECK_FALSE(log.due(200, 3.0));                     // the end is printed once
  CHECK(std::string(log.begin()).empty());
  CHECK(std::string(log.end(false)) == "\n");

  // a log without progress for the heartbeat's span still gets a line
  ProgressCadence slow(false, 1000, 5, 0.5, 120);
  CHECK(slow.due(0, 0));
  CHECK_FALSE(slow.due(1, 60));
  CHECK(slow.due(2, 121));

  ProgressCadence tty(true, 1000000);
  int redraws = 0;
  for (long done = 0; done < 1000; ++done)
    if (tty.due(done, 0.001 * double(done))) ++redraws;  // 1 s of 1000 steps
  CHECK(redraws == 2);                                   // at 0 s and 0.5 s
  CHECK(std::string(tty.begin()) == "\r");
}

TEST_CASE("time left: unknown until a task has finished, then from the measured rate", "[progress]") {
  CHECK(time_left_text(std::nullopt) == "time left unknown");
  CHECK(time_left_text(42.4) == "about 42 s left");
  CHECK(time_left_text(185) == "about 3 min 5 s left");
  CHECK(time_left_text(7300) == "about 2 h 1 min left");

  TimeLeft est({1.0, 10.0});  // kind 0 cheap, kind 1 ten times dearer
  CHECK_FALSE(est.wall_by_rate({0, 2}, {}, 5.0).has_value());
  est.add(0, 1.0);  // one cheap task in the first second of wall time
  // 2 dear tasks left = 20 prior units at 1 unit per wall second
  REQUIRE(est.wall_by_rate({0, 2}, {}, 1.0).has_value());
  CHECK(*est.wall_by_rate({0, 2}, {}, 1.0) == Approx(20.0));
  // ten seconds later with nothing more finished the rate has dropped: the estimate grows instead of
  // repeating a number that has already passed
  CHECK(*est.wall_by_rate({0, 2}, {}, 10.0) == Approx(200.0));
  // a running task counts half
  CHECK(*est.wall_by_rate({0, 1}, {1}, 1.0) == Approx(15.0));
}

TEST_CASE("eccd table prints each row when its scene is done, with progress on stderr, one line per scene in a log",
          "[progress][cli]") {
  TempDir t;
  for (const char* f : {"example2.json", "example2-away-1e-3.json", "example2-towards-1e-3.json"})
    fs::copy_file(src(std::string("cases/paper003/") + f), t.path / f);
  Run r = run_eccd("table " + q(t.str()) + " --mpfr-bits 64", 240);
  REQUIRE(r.code == 0);
  // stdout: the header, then one row per scene in file order, then the legend
  std::istringstream out(r.out);
  std::string head, a, b, c;
  std::getline(out, head);
  std::getline(out, a);
  std::getline(out, b);
  std::getline(out, c);
  CHECK(head.rfind("scene", 0) == 0);
  CHECK(a.rfind("example2-away-1e-3.json", 0) == 0);
  CHECK(b.rfind("example2-towards-1e-3.json", 0) == 0);
  CHECK(c.rfind("example2.json", 0) == 0);
  // stderr is not a terminal here: no carriage return, a line per scene (3 scenes: each one > 5 %)
  CHECK(r.err.find('\r') == std::string::npos);
  CHECK(r.err.find("[1/3]") != std::string::npos);
  CHECK(r.err.find("[3/3]") != std::string::npos);
  CHECK(r.err.find("left") != std::string::npos);
  CHECK(r.out.find("[1/3]") == std::string::npos);  // progress never on stdout
}

}  // namespace ECCD_UNITY_ID

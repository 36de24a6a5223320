// The guard's record (design.md "two faces"): on generated families and the
// paper cases, every error of a floating pipeline as published (plain double,
// SolveOptions::guard = Guard::none) must be flagged by the guarded face
// (Guard::bound): where the as-published answer differs from the exact one,
// the guarded answer is undecided (or right). A guarded answer that is
// decided and differs from the exact answer, or that claims a collision
// where none happens (even beside undecided instants), is a miss of the
// guard: the test fails and prints the scene, the pipeline, the input mode
// and the differences (api/answer_difference.hpp).
//
// Families: realistic decimals and keyframes, near misses, overlaps, in 2D
// (CD-DISC, power / Bernstein / scaled Bernstein) and 3D (the Bézier method,
// f set up in Bernstein and in power form), both input modes (rounded,
// prepared); and cases/paper003, where as-published double is known to be
// wrong (Example 2 perturbed: a false collision on [0.42496, 0.56538]), so
// that the test is never vacuous. Work is bounded by the number of scenes and
// by each run's deadline (kernel/budget.hpp), not timed.
// ECCD_GUARD_SEED overrides the seed (printed); ECCD_GUARD_VERBOSE=1 prints
// each false alarm with the guarded run's reasons.
#include "api/answer_difference.hpp"
#include "api/solve.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

struct Tally {
  int runs = 0, published_errors = 0, caught = 0, right_anyway = 0, false_alarms = 0;
  int published_undecided_2d = 0;  // 2D as-published runs with an undecided instant (their reasons are checked)
  std::vector<std::string> misses;
};

SolveOptions options(const std::string& arith, Basis basis, InputMode input, Guard guard) {
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  o.basis = basis;
  o.input = input;
  o.guard = guard;
  o.time_limit_s = 2;  // a run that hits it is undecided ("time budget"): a work bound, not a timing
  return o;
}

std::string diff_text(const AnswerDifference& d) {
  std::string s;
  for (const auto& x : d.differences) s += (s.empty() ? "" : "; ") + x;
  return s;
}

// Both faces of every pipeline of the scene's dimension against the exact answer.
void check_scene(const Scene& s, Tally& t) {
  SolveOptions ex;
  ex.arith = Arithmetic::exact();
  const Solution exact = solve(s, ex);
  const std::vector<Basis> bases = s.dim == 2
                                       ? std::vector<Basis>{Basis::power, Basis::bernstein, Basis::scaled_bernstein}
                                       : std::vector<Basis>{Basis::bernstein, Basis::power};
  for (Basis b : bases)
    for (InputMode m : {InputMode::rounded, InputMode::prepared}) {
      const Solution pub = solve(s, options("double", b, m, Guard::none));
      const Solution grd = solve(s, options("double", b, m, Guard::bound));
      REQUIRE(pub.guard == "none");
      REQUIRE(grd.guard == "bound");
      ++t.runs;
      // As published has no error bound: its 2D reasons never say "too close to zero" (issue 30 point 4), they
      // name what happened (kernel/cd_disc.hpp collect_reasons).
      if (s.dim == 2 && !pub.answer.undecided.empty()) {
        ++t.published_undecided_2d;
        CHECK(!pub.undecided_reasons.empty());
        for (const auto& r : pub.undecided_reasons) {
          INFO(s.name << " double/" << to_string(b) << " input " << to_string(m) << " as published: " << r);
          CHECK(r.find("too close to zero") == std::string::npos);
        }
      }
      const AnswerDifference dp = answer_difference(pub.answer, exact.answer);
      const AnswerDifference dg = answer_difference(grd.answer, exact.answer);
      // Wrong: decided and not the exact answer, or a collision claimed where none happens (also beside
      // undecided instants: the collision reported is decided, and false).
      const bool pub_wrong = (!dp.agrees && dp.undecided == 0) || (pub.answer.collides && !exact.answer.collides);
      const bool grd_wrong = (!dg.agrees && dg.undecided == 0) || (grd.answer.collides && !exact.answer.collides);
      const bool grd_undecided = dg.undecided > 0 && !grd_wrong;
      const std::string where = s.name + " double/" + to_string(b) + " input " + to_string(m);
      if (pub_wrong) {
        ++t.published_errors;
        if (grd_undecided)
          ++t.caught;
        else if (dg.agrees)
          ++t.right_anyway;
      } else if (dp.agrees && grd_undecided) {
        ++t.false_alarms;
        if (std::getenv("ECCD_GUARD_VERBOSE")) {
          std::cout << "[false-alarm] " << where << " undecided " << dg.undecided << ":";
          for (const auto& r : grd.undecided_reasons) std::cout << " | " << r;
          std::cout << std::endl;
        }
      }
      // The guard is never confidently wrong, whatever the published face said.
      if (grd_wrong)
        t.misses.push_back(where + ": guarded differs: " + diff_text(dg) +
                           " (as published: " + (dp.agrees ? "right" : diff_text(dp)) + ")");
    }
}

std::uint64_t guard_seed() {
  const char* env = std::getenv("ECCD_GUARD_SEED");
  const std::uint64_t seed = env ? std::stoull(env) : 20261127;
  std::cout << "[guard-record] seed " << seed
            << (env ? " (from ECCD_GUARD_SEED)" : " (default; set ECCD_GUARD_SEED to change)") << std::endl;
  return seed;
}

void report(const char* what, const Tally& t) {
  std::cout << "[guard-record] " << what << ": " << t.runs << " pipeline runs per face, " << t.published_errors
            << " as-published errors, " << t.caught << " caught (guarded undecided), " << t.right_anyway
            << " guarded right anyway, " << t.misses.size() << " missed, " << t.false_alarms << " false alarms ("
            << t.published_undecided_2d << " 2D as-published runs undecided)" << std::endl;
}

}  // namespace

TEST_CASE("the guard flags every as-published error on the paper 003 cases", "[guard-record]") {
  Tally t;
  const std::string dir = std::string(ECCD_SOURCE_DIR) + "/cases/paper003";
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".json" && e.path().filename().string().rfind("example2", 0) == 0)
      files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 5);
  for (const auto& f : files) check_scene(read_scene_file(f), t);
  report("cases/paper003/example2*", t);
  for (const auto& m : t.misses) UNSCOPED_INFO(m);
  CHECK(t.misses.empty());
  // Not vacuous: Example 2 perturbed away by 1e-3 is a false collision of as-published double (rounded input).
  CHECK(t.published_errors > 0);
  CHECK(t.caught > 0);
  // and as published leaves instants undecided there (a root of Δ between separate cells that is no touch, f's
  // signs in an impossible pattern): the reasons checked in check_scene are not vacuous.
  CHECK(t.published_undecided_2d > 0);
}

TEST_CASE("the guard flags every as-published error on the generated families", "[guard-record]") {
  const std::uint64_t seed = guard_seed();
  std::vector<GeneratorSpec> specs;
  auto add = [&](int dim, int degree, const std::string& family, const std::string& motion, int d, int digits) {
    GeneratorSpec g;
    g.dim = dim;
    g.degree = degree;
    g.family = family;
    g.motion = motion;
    g.d_exponent = d;
    g.digits = digits;
    g.seed = scene_seed(seed, g, 0);
    specs.push_back(g);
  };
  for (int deg : {2, 3, 4, 5, 6}) {
    for (int digits : {6, 15}) add(2, deg, "decimal", "kinematic", 0, digits);
    add(2, deg, "keyframe", "kinematic", 0, 9);
    for (int d : {4, 6, 8, 10, 12, 14}) add(2, deg, "near-miss", "kinematic", d, 0);
  }
  for (int depth : {5, 9}) add(2, 1, "overlap", "translation", depth, 0);
  for (int deg : {2, 3, 4}) {
    add(3, deg, "decimal", "euler", 0, 15);
    add(3, deg, "keyframe", "euler", 0, 9);
    for (int d : {6, 10, 14}) add(3, deg, "near-miss", "euler", d, 0);
  }
  for (int depth : {5, 9}) add(3, 1, "overlap", "translation", depth, 0);
  Tally t;
  std::map<std::string, Tally> per_family;  // "2D near-miss", ...: the guard's record per family (issue 30 point 5)
  for (const auto& g : specs) {
    const GeneratedScene gs = generate_scene(g);
    INFO(gs.name);
    Tally f;
    check_scene(parse_scene(gs.doc.dump(), gs.name), f);
    Tally& pf = per_family[std::to_string(g.dim) + "D " + g.family];
    for (Tally* x : {&t, &pf}) {
      x->runs += f.runs;
      x->published_errors += f.published_errors;
      x->caught += f.caught;
      x->right_anyway += f.right_anyway;
      x->false_alarms += f.false_alarms;
      x->published_undecided_2d += f.published_undecided_2d;
      x->misses.insert(x->misses.end(), f.misses.begin(), f.misses.end());
    }
  }
  for (const auto& [name, pf] : per_family) report(("family " + name).c_str(), pf);
  report("generated families", t);
  for (const auto& m : t.misses) UNSCOPED_INFO(m);
  CHECK(t.misses.empty());
  int expected = 0;  // 2D: 3 bases, 3D: 2 bases; 2 input modes each
  for (const auto& g : specs) expected += (g.dim == 2 ? 3 : 2) * 2;
  CHECK(t.runs == expected);
}

// A scene the guard once missed: the Bézier method with f set up in power form, rounded input, decided
// "overlapping" at sample instants of a scene that never collides
// (tests/data/float/guard-miss-bezier-power-keyframe.json, its note says how it was found). "Overlapping" now needs
// every control point of F(., t0) surely negative, so the as-published error must be flagged.
TEST_CASE("the guard flags the as-published error on a 3D keyframe scene, Bezier method with the power-form setup",
          "[guard-record][guard-miss]") {
  Tally t;
  check_scene(read_scene_file(std::string(ECCD_SOURCE_DIR) + "/tests/data/float/guard-miss-bezier-power-keyframe.json"),
              t);
  report("tests/data/float/guard-miss-bezier-power-keyframe.json", t);
  for (const auto& m : t.misses) UNSCOPED_INFO(m);
  CHECK(t.misses.empty());
}

// The guarded 2D double face's second look (api/solve.cpp): 003's Example 2 moved 1e-3 away, rounded input,
// where double's bound is too wide to decide Δ's sign (the double run alone is undecided, the as-published
// run claims a false collision). The 128-bit bounded run decides it, and its answer is the exact one.
TEST_CASE("the guarded 2D double face decides by its second look where double's bound is too wide", "[guard-record]") {
  const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2-away-1e-3.json");
  SolveOptions ex;
  ex.arith = Arithmetic::exact();
  const Solution exact = solve(s, ex);
  const Solution grd = solve(s, options("double", Basis::bernstein, InputMode::rounded, Guard::bound));
  long look = 0;
  for (const auto& [name, n] : grd.work)
    if (name == "second_look") look = n;
  CHECK(look == 2);  // it ran and decided
  CHECK(grd.decided());
  CHECK(answer_difference(grd.answer, exact.answer).agrees);
  CHECK_FALSE(grd.answer.collides);
  const Solution pub = solve(s, options("double", Basis::bernstein, InputMode::rounded, Guard::none));
  CHECK(pub.answer.collides);  // the as-published face's false collision, unchanged
  for (const auto& [name, n] : pub.work) CHECK(name != "second_look");
}

// The guarded 3D double face's second look (api/solve.cpp): the Bézier method on near misses 1e-14 apart
// (the generated family above, same seed), where the double run's bound leaves statuses near the closest
// approach unread. Wherever the 128-bit bounded run took over (work counter second_look 2), its answer is
// decided and is the exact one; and on these scenes it does take over at least once (the double run alone left
// them undecided: the false alarms of the record above).
TEST_CASE("the guarded 3D double face decides by its second look on near misses", "[guard-record][second-look]") {
  const std::uint64_t seed = 20261127;
  int decided_by_look = 0;
  for (int deg : {3, 4}) {
    GeneratorSpec g;
    g.dim = 3;
    g.degree = deg;
    g.family = "near-miss";
    g.motion = "euler";
    g.d_exponent = 14;
    g.seed = scene_seed(seed, g, 0);
    const GeneratedScene gs = generate_scene(g);
    const Scene s = parse_scene(gs.doc.dump(), gs.name);
    SolveOptions ex;
    ex.arith = Arithmetic::exact();
    const Solution exact = solve(s, ex);
    for (Basis b : {Basis::bernstein, Basis::power})
      for (InputMode m : {InputMode::rounded, InputMode::prepared}) {
        INFO(gs.name << " double/" << to_string(b) << " input " << to_string(m));
        const Solution grd = solve(s, options("double", b, m, Guard::bound));
        long look = 0;
        for (const auto& [name, n] : grd.work)
          if (name == "second_look") look = n;
        if (look == 2) {
          ++decided_by_look;
          CHECK(grd.decided());
          CHECK(answer_difference(grd.answer, exact.answer).agrees);
        }
        const Solution pub = solve(s, options("double", b, m, Guard::none));
        for (const auto& [name, n] : pub.work) CHECK(name != "second_look");
      }
  }
  CHECK(decided_by_look > 0);
}

// The second look's budget is work, not time (api/solve.cpp, kernel/budget.hpp ScopedWorkBudget): the same scene
// gets the same answer, with the second look stopped at the same step, on a quiet machine and beside two busy
// threads. Two scenes: a 3D near miss whose second look decides (the family above), and a 3D touch of degree 6
// whose second look meets its budget (a processor-time budget made the shipped report's 3D near miss at 1e-12
// decided on one run and undecided on the next).
TEST_CASE("the second look stops at the same work whatever the machine's load", "[guard-record][second-look]") {
  GeneratorSpec g;
  g.dim = 3;
  g.degree = 3;
  g.family = "near-miss";
  g.motion = "euler";
  g.d_exponent = 14;
  g.seed = scene_seed(20261127, g, 0);
  const GeneratedScene gs = generate_scene(g);
  const std::vector<Scene> scenes = {
      parse_scene(gs.doc.dump(), gs.name),
      read_scene_file(std::string(ECCD_SOURCE_DIR) +
                      "/cases/generated/3d-euler/3d-deg6-touch-euler-6196066849619300.json")};
  auto look_of = [](const Solution& s, const char* key) {
    long n = -1;
    for (const auto& [name, v] : s.work)
      if (name == key) n = v;
    return n;
  };
  std::set<long> outcomes;
  for (const Scene& sc : scenes) {
    INFO(sc.name);
    SolveOptions o = options("double", Basis::bernstein, InputMode::rounded, Guard::bound);
    // The run's own deadline is wall time and holds over the look (api/solve.cpp): the 2 s of options() ended a
    // 1 s look early on a machine busy beyond these two threads (a CI build beside). Here it is only a backstop,
    // hundreds of times the look's processor time: the look must end by its work budget, not by a clock.
    o.time_limit_s = 600;
    const Solution quiet = solve(sc, o);
    std::atomic<bool> stop{false};
    std::vector<std::thread> busy;
    for (int k = 0; k < 2; ++k)
      busy.emplace_back([&stop] {
        volatile double x = 1;
        while (!stop.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
      });
    const Solution loaded = solve(sc, o);
    stop = true;
    for (auto& t : busy) t.join();
    REQUIRE(look_of(quiet, "second_look") >= 1);  // the second look ran
    outcomes.insert(look_of(quiet, "second_look"));
    CHECK(look_of(loaded, "second_look") == look_of(quiet, "second_look"));
    CHECK(look_of(loaded, "second_look_units") == look_of(quiet, "second_look_units"));
    CHECK(look_of(quiet, "second_look_units") > 0);
    CHECK(loaded.decided() == quiet.decided());
    CHECK(loaded.answer.collides == quiet.answer.collides);
    CHECK(loaded.undecided_reasons == quiet.undecided_reasons);
    CHECK(answer_to_json(loaded.answer) == answer_to_json(quiet.answer));  // the same answer, instant for instant
  }
  CHECK(outcomes == std::set<long>{1, 2});  // one look decided, one met its budget
}

}  // namespace ECCD_UNITY_ID

// eccd::animate_poses (api/pose_check.hpp), the per-pose mode of issue 36:
// every pair-pose's status equals the exact static status of the animation at
// that key time (eccd::status_at on pair_frame_scene at τ = 0, or τ = 1 for
// the last key: the exact pipeline is the ground truth), in double (where it
// decides), certified and exact, with and without kept planes; plane keeping
// changes no answer; on a coherent animation (paper 000 Table 1's set-up at a
// small rate) nearly every separate pair-pose is settled by the kept plane
// (work counts); and the sweep-and-prune broad phase (api/sweep_and_prune.hpp)
// looks at far fewer than n²/2 pairs on a sparse scene while giving the same
// candidates and answers as all pairs.
#include "api/pose_check.hpp"
#include "api/static_status.hpp"
#include "api/sweep_and_prune.hpp"
#include "io/animation_reader.hpp"
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

std::string shipped(const std::string& name) {
  std::ifstream in(eccd::test::case_path("animations/" + name));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The exact static status of bodies a and b at key pose k.
Status truth(const Animation& anim, std::size_t a, std::size_t b, std::size_t k) {
  if (k + 1 < anim.times.size()) return status_at(pair_frame_scene(anim, a, b, k), mpq_class(0), Arithmetic::exact());
  return status_at(pair_frame_scene(anim, a, b, k - 1), mpq_class(1), Arithmetic::exact());
}

// Every pair-pose of the run against the exact ground truth; returns the truth for reuse.
using Truth = std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Status>;
void check_against_truth(const Animation& anim, const PosesResult& r, Truth& t, bool floating) {
  auto get = [&](std::size_t a, std::size_t b, std::size_t k) {
    auto key = std::make_tuple(k, a, b);
    auto it = t.find(key);
    if (it == t.end()) it = t.emplace(key, truth(anim, a, b, k)).first;
    return it->second;
  };
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Status> seen;
  for (const auto& s : r.tested) seen[std::make_tuple(s.pose, s.body_a, s.body_b)] = s.status;
  std::size_t undecided = 0;
  for (std::size_t k = 0; k < anim.times.size(); ++k)
    for (const auto& [a, b] : anim.pairs) {
      INFO("pose " << k << " pair " << anim.bodies[a].name << " -- " << anim.bodies[b].name << " arith "
                   << r.arithmetic);
      const Status want = get(a, b, k);
      auto it = seen.find(std::make_tuple(k, a, b));
      if (it == seen.end()) {  // dropped by the bounding spheres: must be separate
        REQUIRE(want == Status::separate);
        continue;
      }
      if (it->second == Status::uncertain) {
        REQUIRE(floating);
        ++undecided;
        continue;
      }
      REQUIRE(to_string(it->second) == std::string(to_string(want)));
    }
  REQUIRE(undecided == r.undecided.size());
  std::size_t events = 0;
  for (const auto& s : r.tested) events += in_collision(s.status);
  REQUIRE(events == r.events.size());
}

// Paper 000 Table 1's set-up: ellipsoids 3, 3, 5 at (0,0,0) and (8,0,0), each turning about its own axis by
// `rate` radians per key, quaternions with 6 decimals (as cases/animations/make_repro.py table1 writes them).
std::string table1_like(double rate, int keys, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0, 1);
  json bodies = json::array();
  for (int b = 0; b < 2; ++b) {
    double u[3] = {g(gen), g(gen), g(gen)}, q0[4] = {g(gen), g(gen), g(gen), g(gen)};
    const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double nq = std::sqrt(q0[0] * q0[0] + q0[1] * q0[1] + q0[2] * q0[2] + q0[3] * q0[3]);
    json poses = json::array();
    for (int k = 0; k < keys; ++k) {
      const double h = k * rate / 2, c = std::cos(h), s = std::sin(h);
      const double r[4] = {c, s * u[0] / nu, s * u[1] / nu, s * u[2] / nu};
      const double* p = q0;
      double q[4] = {
          p[0] * r[0] - p[1] * r[1] - p[2] * r[2] - p[3] * r[3], p[0] * r[1] + p[1] * r[0] + p[2] * r[3] - p[3] * r[2],
          p[0] * r[2] - p[1] * r[3] + p[2] * r[0] + p[3] * r[1], p[0] * r[3] + p[1] * r[2] - p[2] * r[1] + p[3] * r[0]};
      json o = json::array();
      for (double x : q) o.push_back(Rational(long(std::llround(x / nq * 1e6)), 1000000L).get_str());
      poses.push_back({{"position", {b ? "8" : "0", "0", "0"}}, {"orientation", o}});
    }
    bodies.push_back({{"name", b ? "b" : "a"}, {"shape", {{"semi_axes", {"3", "3", "5"}}}}, {"poses", poses}});
  }
  json times = json::array();
  for (int k = 0; k < keys; ++k) times.push_back(std::to_string(k));
  return json{
      {"format", "ellipse-ccd-animation/1"}, {"name", "table1-like"}, {"dim", 3}, {"times", times}, {"bodies", bodies}}
      .dump();
}

AnimateOptions options(const char* arith, bool planes = true, int threads = 1) {
  AnimateOptions o;
  o.solve.arith = parse_arithmetic(arith);
  o.planes = planes;
  o.threads = threads;
  o.keep_tested = true;
  return o;
}

}  // namespace

TEST_CASE("animate_poses: every pair-pose equals the exact static status, in double, certified and exact",
          "[animation][poses]") {
  for (const char* file : {"swarm-2d.json", "two-rows-3d.json"}) {
    const Animation anim = animation_from_text(shipped(file), file);
    Truth t;
    for (const char* arith : {"double", "certified", "exact"})
      for (bool planes : {true, false}) {
        INFO(file << " " << arith << " planes " << planes);
        const PosesResult r = animate_poses(anim, options(arith, planes));
        check_against_truth(anim, r, t, std::string(arith) == "double");
        REQUIRE(r.per_pose.size() == anim.times.size());
        if (std::string(arith) != "double") REQUIRE(r.undecided.empty());
      }
  }
}

TEST_CASE("animate_poses: the table-1 set-up against the exact truth, and plane keeping changes no answer",
          "[animation][poses]") {
  const Animation anim = animation_from_text(table1_like(0.1, 300, 1), "t1");
  Truth t;
  for (const char* arith : {"double", "certified", "exact"}) {
    INFO(arith);
    const PosesResult with = animate_poses(anim, options(arith, true));
    const PosesResult without = animate_poses(anim, options(arith, false));
    check_against_truth(anim, with, t, std::string(arith) == "double");
    json a = poses_result_to_json(with), b = poses_result_to_json(without);
    REQUIRE(a["events"] == b["events"]);
    REQUIRE(a["undecided"] == b["undecided"]);
    REQUIRE(a["mode"] == "poses");
    REQUIRE(without.separating_plane == 0);
    REQUIRE(with.separating_plane > 0);  // the stage ran and settled something
    REQUIRE(with.events.size() > 0);     // and the set-up has overlapping poses (a test that could fail)
  }
}

TEST_CASE("animate_poses: on a coherent animation the kept plane settles nearly every separate pair-pose",
          "[animation][poses]") {
  // 000 section 4: at 0.01 rad per key the plane built at one pose nearly always still separates at the next.
  const Animation anim = animation_from_text(table1_like(0.01, 400, 3), "t1-slow");
  for (const char* arith : {"double", "certified"}) {
    INFO(arith);
    const PosesResult r = animate_poses(anim, options(arith));
    std::size_t separate = 0;
    for (const auto& s : r.tested) separate += s.status == Status::separate;
    REQUIRE(r.undecided.empty());
    REQUIRE(separate > 100);
    // every separate pair-pose either held its kept plane or built a new one (no construction failed here)
    REQUIRE(r.plane_build_failed == 0);
    REQUIRE(r.separating_plane + r.planes_built == separate);
    REQUIRE(r.planes_built * 10 <= separate);                        // at most a tenth rebuilt
    REQUIRE(r.plane_checks <= r.separating_plane + r.planes_built);  // a check per pose that had a plane
  }
}

TEST_CASE("animate_poses: threads do not change the answer, and bad options are refused", "[animation][poses]") {
  const Animation anim = animation_from_text(shipped("two-rows-3d.json"), "rows");
  json one = poses_result_to_json(animate_poses(anim, options("certified", true, 1)));
  json three = poses_result_to_json(animate_poses(anim, options("certified", true, 3)));
  REQUIRE(one["events"] == three["events"]);
  REQUIRE(one["stages"] == three["stages"]);
  REQUIRE(one["planes"] == three["planes"]);
  AnimateOptions o = options("mpfr:100");
  REQUIRE_THROWS_AS(animate_poses(anim, o), std::invalid_argument);
  o = options("double");
  o.all_intervals = true;
  REQUIRE_THROWS_AS(animate_poses(anim, o), std::invalid_argument);
}

TEST_CASE("animate_poses: touching balls are undecided in double, never an event, and touching when exact",
          "[animation][poses]") {
  for (int dim : {2, 3}) {
    json q = dim == 3 ? json::array({"1", "0", "0", "0"}) : json::array({"1", "0"});
    auto at = [&](const char* x, const char* y) {
      json p = json::array({x, y});
      if (dim == 3) p.push_back("0");
      return json{{"position", p}, {"orientation", q}};
    };
    json semi = dim == 3 ? json::array({"1", "1", "1"}) : json::array({"1", "1"});
    json doc = {{"format", "ellipse-ccd-animation/1"},
                {"name", "touch"},
                {"dim", dim},
                {"times", {"0", "1"}},
                {"bodies",
                 {{{"name", "a"}, {"shape", {{"semi_axes", semi}}}, {"poses", {at("0", "0"), at("0", "0")}}},
                  {{"name", "b"}, {"shape", {{"semi_axes", semi}}}, {"poses", {at("2", "0"), at("3", "0")}}}}}};
    const Animation anim = animation_from_text(doc.dump(), "touch");
    INFO(dim);
    const PosesResult d = animate_poses(anim, options("double"));
    for (const auto& e : d.events) REQUIRE(e.pose != 0);
    for (const char* arith : {"exact", "certified"}) {
      const PosesResult e = animate_poses(anim, options(arith));
      REQUIRE(e.events.size() == 1);
      REQUIRE(e.events[0].pose == 0);
      REQUIRE(e.events[0].status == Status::touching);
      REQUIRE(e.undecided.empty());
    }
  }
}

TEST_CASE(
    "sweep_and_prune: the pairs of overlapping intervals, as all pairs give them, looking at few on a sparse scene",
    "[animation][poses]") {
  std::mt19937 gen(36);
  std::uniform_real_distribution<double> x(0, 100), w(0, 3);
  std::vector<SweepInterval> box(300);
  for (auto& b : box) {
    b.lo = x(gen);
    b.hi = b.lo + w(gen);
  }
  std::size_t examined = 0;
  auto got = sweep_and_prune(box, examined);
  std::sort(got.begin(), got.end());
  std::vector<std::pair<std::size_t, std::size_t>> all;
  for (std::size_t i = 0; i < box.size(); ++i)
    for (std::size_t j = i + 1; j < box.size(); ++j)
      if (box[i].lo <= box[j].hi && box[j].lo <= box[i].hi) all.emplace_back(i, j);
  REQUIRE(got == all);
  REQUIRE(examined == all.size());
  REQUIRE(examined * 10 < box.size() * (box.size() - 1) / 2);
}

TEST_CASE(
    "animate_poses: the broad phase looks at far fewer than n²/2 pairs on a sparse scene, same answers as all pairs",
    "[animation][poses]") {
  // n bodies on a grid in a plane (spacing 4, or 3 for the small one; radii up to 1.2, a wobble of up to 1.8), 3 keys;
  // some pairs overlap.
  auto scene = [](int nx, int ny, int spacing) {
    std::mt19937 gen(11);
    std::uniform_int_distribution<int> jitter(-60, 60);
    json bodies = json::array();
    int id = 0;
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j)
        for (int l = 0; l < 1; ++l, ++id) {
          json poses = json::array();
          for (int k = 0; k < 3; ++k) {
            auto c = [&](int base) { return Rational(base * 100 + jitter(gen) * (k + 1), 100).get_str(); };
            poses.push_back({{"position", {c(spacing * i), c(spacing * j), c(spacing * l)}},
                             {"orientation", {"1", Rational(jitter(gen), 100).get_str(), "0", "0"}}});
          }
          bodies.push_back({{"name", std::string("b").append(std::to_string(id))},
                            {"shape", {{"semi_axes", {"1.2", "0.8", "0.7"}}}},
                            {"poses", poses}});
        }
    return json{{"format", "ellipse-ccd-animation/1"},
                {"name", "grid"},
                {"dim", 3},
                {"times", {"0", "1", "2"}},
                {"bodies", bodies}}
        .dump();
  };
  {  // sparse: 30·15 = 450 bodies in a layer, 101025 pairs per pose
    const Animation anim = animation_from_text(scene(30, 15, 4), "grid");
    const PosesResult r = animate_poses(anim, options("double"));
    const std::size_t n = anim.bodies.size(), half = n * (n - 1) / 2;
    for (const auto& p : r.per_pose) REQUIRE(p.sweep_examined * 20 < half);
    REQUIRE(r.bounding_volumes > 3 * half - r.sweep_examined - 1);
  }
  {  // small: 6·3 = 18 bodies; every pair's exact status agrees (check_against_truth walks all pairs)
    const Animation anim = animation_from_text(scene(6, 3, 3), "grid-small");
    Truth t;
    const PosesResult r = animate_poses(anim, options("certified"));
    check_against_truth(anim, r, t, false);
    std::size_t colliding = 0;
    for (const auto& [key, s] : t) colliding += in_collision(s);
    REQUIRE(colliding > 0);  // the scene has events to miss
  }
}

}  // namespace ECCD_UNITY_ID

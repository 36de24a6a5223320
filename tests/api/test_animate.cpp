// eccd::animate (api/animate.hpp) on the shipped example animations
// (cases/animations/, a cut-down copy of the 3D one): exact and certified
// give the same events, and every pair-frame's answer equals eccd::solve in
// exact arithmetic on that pair-frame's scene, built here INDEPENDENTLY from
// docs/animation-format.md: the scene JSON text is written from the poses by
// the spec's formulas (a `matrix` motion W·[[R·D, c], [0, 1]] with the
// rotation of scene-format.md's `euler` / `kinematic` forms, multiplied out by
// the small polynomial code below) and read with scene_from_text;
// pair_frame_scene and kernel/keyframe_motion.hpp are not used for it. A
// pair-frame dropped by the bounding volumes must be collision-free there.
#include "api/animate.hpp"
#include "api/answer_difference.hpp"
#include "api/solve.hpp"
#include "io/animation_reader.hpp"
#include "io/scene_reader.hpp"
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <sstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Polynomials in tau as coefficient vectors (lowest first), exact.
using P = std::vector<mpq_class>;
P add(const P& a, const P& b) {
  P r(std::max(a.size(), b.size()), mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += b[i];
  return r;
}
P mul(const P& a, const P& b) {
  P r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
P scale(const mpq_class& s, const P& a) {
  P r = a;
  for (auto& x : r) x *= s;
  return r;
}
json poly_json(const P& p) {
  json j = json::array();
  for (const auto& x : p) j.push_back(x.get_str());
  return j;
}
mpq_class num(const json& j) {
  mpq_class q = parse_rational(j.get<std::string>());
  return q;
}

// The spec's motion of body `b` (JSON) in frame k, as a scene `matrix` motion.
json spec_motion(const json& b, std::size_t k, int dim) {
  const json& p0 = b["poses"][k];
  const json& p1 = b["poses"][k + 1];
  std::vector<mpq_class> q0, q1;
  for (const auto& x : p0["orientation"]) q0.push_back(num(x));
  for (const auto& x : p1["orientation"]) q1.push_back(num(x));
  mpq_class dot = 0;
  for (std::size_t i = 0; i < q0.size(); ++i) dot += q0[i] * q1[i];
  if (dot < 0)
    for (auto& x : q1) x = -x;
  std::vector<P> q;  // q(tau) = (1 - tau) q0 + tau q1'
  for (std::size_t i = 0; i < q0.size(); ++i) q.push_back({q0[i], q1[i] - q0[i]});
  std::vector<std::vector<P>> R(dim, std::vector<P>(dim));  // W·R
  P W;
  if (dim == 3) {  // scene-format.md, `euler`, times E
    const P &e0 = q[0], &e1 = q[1], &e2 = q[2], &e3 = q[3];
    auto sq = [](const P& x) { return mul(x, x); };
    R[0][0] = add(add(sq(e0), sq(e1)), scale(-1, add(sq(e2), sq(e3))));
    R[0][1] = scale(2, add(mul(e1, e2), scale(-1, mul(e0, e3))));
    R[0][2] = scale(2, add(mul(e1, e3), mul(e0, e2)));
    R[1][0] = scale(2, add(mul(e1, e2), mul(e0, e3)));
    R[1][1] = add(add(sq(e0), sq(e2)), scale(-1, add(sq(e1), sq(e3))));
    R[1][2] = scale(2, add(mul(e2, e3), scale(-1, mul(e0, e1))));
    R[2][0] = scale(2, add(mul(e1, e3), scale(-1, mul(e0, e2))));
    R[2][1] = scale(2, add(mul(e2, e3), mul(e0, e1)));
    R[2][2] = add(add(sq(e0), sq(e3)), scale(-1, add(sq(e1), sq(e2))));
    W = add(add(sq(e0), sq(e1)), add(sq(e2), sq(e3)));
  } else {  // `kinematic` rotation with d2 = w, d3 = -z: [[d2² - d3², 2 d2 d3], [-2 d2 d3, d2² - d3²]]
    const P d2 = q[0], d3 = scale(-1, q[1]);
    R[0][0] = add(mul(d2, d2), scale(-1, mul(d3, d3)));
    R[0][1] = scale(2, mul(d2, d3));
    R[1][0] = scale(-2, mul(d2, d3));
    R[1][1] = R[0][0];
    W = add(mul(d2, d2), mul(d3, d3));
  }
  auto def = [&](const json& p, int i, int j) {
    return p.contains("deformation") ? num(p["deformation"][i][j]) : mpq_class(i == j ? 1 : 0);
  };
  json m = json::array();
  for (int i = 0; i < dim; ++i) {
    json row = json::array();
    for (int j = 0; j < dim; ++j) {
      P s{0};
      for (int l = 0; l < dim; ++l) s = add(s, mul(R[i][l], P{def(p0, l, j), def(p1, l, j) - def(p0, l, j)}));
      row.push_back(poly_json(s));
    }
    const mpq_class c0 = num(p0["position"][i]), c1 = num(p1["position"][i]);
    row.push_back(poly_json(mul(W, P{c0, c1 - c0})));
    m.push_back(row);
  }
  json last = json::array();
  for (int j = 0; j < dim; ++j) last.push_back("0");
  last.push_back(poly_json(W));
  m.push_back(last);
  return {{"type", "matrix"}, {"m", m}};
}

std::string spec_scene_text(const json& anim, std::size_t i, std::size_t j, std::size_t k) {
  const int dim = anim["dim"].get<int>();
  const json& a = anim["bodies"][i];
  const json& b = anim["bodies"][j];
  json s = {{"format", "ellipse-ccd-scene/1"},
            {"name", "reference"},
            {"dim", dim},
            {"a", {{"shape", a["shape"]}, {"motion", spec_motion(a, k, dim)}}},
            {"b", {{"shape", b["shape"]}, {"motion", spec_motion(b, k, dim)}}}};
  return s.dump();
}

// Every checked pair-frame of `text` against the reference, and exact vs certified.
void check_against_reference(const std::string& text, bool all_intervals, bool collides = true) {
  const json doc = json::parse(text);
  const Animation anim = animation_from_text(text, "anim");
  AnimateOptions o;
  o.all_intervals = all_intervals;
  o.keep_tested = true;
  o.solve.arith = parse_arithmetic("exact");
  const AnimationResult ex = animate(anim, o);
  REQUIRE(ex.undecided.empty());
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, const PairFrameAnswer*> tested;
  for (const auto& t : ex.tested) tested[{t.frame, t.body_a, t.body_b}] = &t;
  SolveOptions ref;
  ref.arith = parse_arithmetic("exact");
  // first-contact mode: the first collision interval (3D: the pipeline's first_contact; 2D: the whole answer
  // cut to its first interval here, independently of api/animate.cpp)
  if (!all_intervals) ref.first_contact = anim.dim == 3;
  std::size_t dropped = 0, collisions = 0;
  for (std::size_t k = 0; k < anim.frames(); ++k)
    for (const auto& [i, j] : anim.pairs) {
      Answer want = solve(scene_from_text(spec_scene_text(doc, i, j, k), "reference"), ref).answer;
      if (!all_intervals && want.intervals.size() > 1) want.intervals.resize(1);
      INFO("frame " << k << " pair " << anim.bodies[i].name << " " << anim.bodies[j].name);
      auto it = tested.find({k, i, j});
      if (it == tested.end()) {  // dropped by the bounding volumes or a kept plane: must be collision-free
        ++dropped;
        REQUIRE_FALSE(want.collides);
        continue;
      }
      const AnswerDifference d = answer_difference(it->second->local, want);
      INFO((d.differences.empty() ? std::string() : d.differences.front()));
      REQUIRE(d.agrees);
      collisions += want.collides;
    }
  REQUIRE(collisions == ex.events.size());
  // an event that collides names where: its first interval (both modes), or its contacts; never an empty answer
  for (const auto& e : ex.events) {
    INFO("frame " << e.frame << " pair " << anim.bodies[e.body_a].name << " " << anim.bodies[e.body_b].name);
    REQUIRE(e.answer.collides);
    REQUIRE((!e.answer.intervals.empty() || !e.answer.contacts.empty()));
    if (!all_intervals) REQUIRE(e.answer.intervals.size() <= 1);
    if (!e.answer.intervals.empty()) REQUIRE(e.answer.first_contact.has_value());
  }
  REQUIRE((collisions > 0) == collides);  // the examples do collide (the near miss does not)
  REQUIRE(ex.continuous_test > 0);
  REQUIRE(dropped > 0);  // and the bounding volumes do drop pairs
  REQUIRE(ex.bounding_volumes > 0);
  REQUIRE(ex.bounding_volumes + ex.separating_plane == dropped);

  // certified: the same events (the same pair-frames, the answers agree), instants in global time
  o.solve.arith = parse_arithmetic("certified");
  o.keep_tested = false;
  const AnimationResult ce = animate(anim, o);
  REQUIRE(ce.undecided.empty());
  REQUIRE(ce.events.size() == ex.events.size());
  for (std::size_t e = 0; e < ex.events.size(); ++e) {
    REQUIRE(ce.events[e].frame == ex.events[e].frame);
    REQUIRE(ce.events[e].body_a == ex.events[e].body_a);
    REQUIRE(ce.events[e].body_b == ex.events[e].body_b);
    REQUIRE(answer_difference(ce.events[e].answer, ex.events[e].answer).agrees);
    // global time: the first contact lies in [t_k, t_{k+1}], its bracket mapped exactly
    const auto& fc = ex.events[e].answer.first_contact;
    const auto& lc = ex.events[e].local.first_contact;
    REQUIRE(fc.has_value());
    REQUIRE(fc->certified());
    const std::size_t k = ex.events[e].frame;
    const mpq_class dt = anim.times[k + 1] - anim.times[k];
    REQUIRE(*fc->lo == anim.times[k] + *lc->lo * dt);
    REQUIRE(*fc->hi == anim.times[k] + *lc->hi * dt);
  }
}

std::string shipped(const std::string& name) { return slurp(eccd::test::case_path("animations/" + name)); }

// The 3D example cut down to key times [from, to] and the named bodies.
std::string cut_3d(std::size_t from, std::size_t to, const std::vector<std::string>& names) {
  json doc = json::parse(shipped("two-rows-3d.json"));
  json times = json::array();
  for (std::size_t k = from; k <= to; ++k) times.push_back(doc["times"][k]);
  json bodies = json::array();
  for (const auto& b : doc["bodies"]) {
    if (std::find(names.begin(), names.end(), b["name"].get<std::string>()) == names.end()) continue;
    json c = b;
    c["poses"] = json::array();
    for (std::size_t k = from; k <= to; ++k) c["poses"].push_back(b["poses"][k]);
    bodies.push_back(c);
  }
  doc["times"] = times;
  doc["bodies"] = bodies;
  return doc.dump();
}

}  // namespace

TEST_CASE("animate: the 2D example against independently built scenes, exact and certified", "[animation]") {
  check_against_reference(shipped("swarm-2d.json"), true);
  check_against_reference(shipped("swarm-2d.json"), false);
}

TEST_CASE("animate: the 3D example (cut down) against independently built scenes, exact and certified", "[animation]") {
  // Key times 17..22: left-2's punch into the turning right-2; 24..28: left-5's near miss under right-5
  // (and past right-4); 35..39: right-4's punch into the breathing (deformed) left-4.
  check_against_reference(cut_3d(17, 22, {"left-1", "left-2", "right-2", "right-3"}), false);
  check_against_reference(cut_3d(24, 28, {"left-5", "right-4", "right-5"}), true, false);
  check_against_reference(cut_3d(35, 39, {"left-4", "right-4", "right-5"}), true);
}

TEST_CASE("animate: threads and shards do not change the answer", "[animation]") {
  const Animation anim = animation_from_text(shipped("swarm-2d.json"), "swarm");
  AnimateOptions o;
  o.solve.arith = parse_arithmetic("exact");
  o.threads = 1;
  json one = animation_result_to_json(animate(anim, o));
  o.threads = 3;
  json three = animation_result_to_json(animate(anim, o));
  REQUIRE(one["events"] == three["events"]);
  REQUIRE(one["stages"] == three["stages"]);
  // two shards: contiguous blocks of frames whose events together are the whole run's
  json parts = json::array();
  std::size_t continuous = 0;
  for (std::size_t s = 0; s < 2; ++s) {
    o.shard_index = s;
    o.shard_count = 2;
    json p = animation_result_to_json(animate(anim, o));
    for (const auto& e : p["events"]) parts.push_back(e);
    continuous += p["stages"]["continuous_test"].get<std::size_t>();
  }
  REQUIRE(parts == one["events"]);
  REQUIRE(continuous == one["stages"]["continuous_test"].get<std::size_t>());
  o.shard_index = 2;
  REQUIRE_THROWS_AS(animate(anim, o), std::invalid_argument);
}

TEST_CASE("animate: the bounding sphere contains the body over the frame", "[animation]") {
  // A unit ball moving from (0,0,0) to (4,0,0), deformed by up to diag(2,1,1):
  // centre (2,0,0), radius 2 + ||D||_F <= 2 + sqrt(6) (rounded up, never below).
  json doc = json::parse(cut_3d(0, 1, {"left-0", "right-0"}));
  doc["bodies"][0]["shape"] = {{"semi_axes", {"1", "1", "1"}}};
  doc["bodies"][0]["poses"][0]["position"] = {"0", "0", "0"};
  doc["bodies"][0]["poses"][1]["position"] = {"4", "0", "0"};
  doc["bodies"][0]["poses"][1]["deformation"] = {{"2", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}};
  const Animation anim = animation_from_text(doc.dump(), "sphere");
  const BoundingSphere s = swept_bounding_sphere(anim, 0, 0);
  REQUIRE(s.centre == std::vector<Rational>{2, 0, 0});
  const Rational extra = s.radius - 2;
  REQUIRE(extra * extra >= 6);
  REQUIRE(extra < Rational(245, 100));  // sqrt(6) = 2.449...
  // the semi-axes bound: right-0 has semi-axes 0.9, 0.6, 0.5 and stands still: radius exactly 9/10
  REQUIRE(swept_bounding_sphere(anim, 1, 0).radius == Rational(9, 10));
  // a matrix shape off its body's origin: the unit ball centred at (3, 0, 0) in the body frame,
  // (x - 3)^2 + y^2 + z^2 <= 1: every point within |x0| + 1 = 4 of the origin
  doc["bodies"][1]["shape"] = {
      {"matrix", {{"1", "0", "0", "-3"}, {"0", "1", "0", "0"}, {"0", "0", "1", "0"}, {"-3", "0", "0", "8"}}}};
  REQUIRE(swept_bounding_sphere(animation_from_text(doc.dump(), "m"), 1, 0).radius == 4);
  // a tilted ellipse: A = [[2, 1, 0], [1, 2, 0], [0, 0, 1]]: |x|^2 <= tr(A^-1) = 2/3 + 2/3 + 1 (the bound used), and
  // the true radius 1 (along z; the tilted axes have 1/sqrt(1) and 1/sqrt(3)) lies below it
  doc["bodies"][1]["shape"] = {
      {"matrix", {{"2", "1", "0", "0"}, {"1", "2", "0", "0"}, {"0", "0", "1", "0"}, {"0", "0", "0", "-1"}}}};
  const Rational r = swept_bounding_sphere(animation_from_text(doc.dump(), "m"), 1, 0).radius;
  REQUIRE(r * r >= Rational(7, 3));
  REQUIRE(r < Rational(153, 100));  // sqrt(7/3) = 1.5275...
}

TEST_CASE("animate: a graze double cannot decide is undecided, never an event, and exact finds the touch",
          "[animation]") {
  // Two unit disks / balls; b passes a at centre distance 2 at tau = 1/2: an isolated touch at t = 1/2.
  for (int dim : {2, 3}) {
    json q = dim == 3 ? json::array({"1", "0", "0", "0"}) : json::array({"1", "0"});
    auto at = [&](const char* x, const char* y) {
      json p = json::array({x, y});
      if (dim == 3) p.push_back("0");
      return json{{"position", p}, {"orientation", q}};
    };
    json semi = dim == 3 ? json::array({"1", "1", "1"}) : json::array({"1", "1"});
    json doc = {{"format", "ellipse-ccd-animation/1"},
                {"name", "graze"},
                {"dim", dim},
                {"times", {"0", "1"}},
                {"bodies",
                 {{{"name", "a"}, {"shape", {{"semi_axes", semi}}}, {"poses", {at("0", "0"), at("0", "0")}}},
                  {{"name", "b"}, {"shape", {{"semi_axes", semi}}}, {"poses", {at("-1", "2"), at("1", "2")}}}}}};
    const Animation anim = animation_from_text(doc.dump(), "graze");
    AnimateOptions o;
    o.all_intervals = true;
    o.solve.arith = parse_arithmetic("double");
    const AnimationResult d = animate(anim, o);
    INFO(dim);
    REQUIRE(d.events.empty());
    REQUIRE(d.undecided.size() == 1);
    REQUIRE_FALSE(d.undecided[0].why.empty());
    o.solve.arith = parse_arithmetic("exact");
    const AnimationResult e = animate(anim, o);
    REQUIRE(e.undecided.empty());
    REQUIRE(e.events.size() == 1);
    REQUIRE(e.events[0].answer.contacts.size() == 1);
    REQUIRE(*e.events[0].answer.contacts[0].lo == Rational(1, 2));
    REQUIRE(*e.events[0].answer.contacts[0].hi == Rational(1, 2));
  }
}

}  // namespace ECCD_UNITY_ID

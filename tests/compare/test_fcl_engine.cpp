// FCL as a peer engine (compare/fcl_engine.hpp): the pose FCL receives
// reproduces the quadric in double; fcl/sample agrees with the exact static
// test at its samples on clearly separate / overlapping cases; which motions
// fcl/ccd can express; the harness rows; `eccd fcl` piped into `eccd judge`,
// including a shallow overlap that FCL, at its default tolerance, calls
// separate. The parts that call FCL are compiled only with ECCD_HAVE_FCL
// (CI installs libfcl-dev).
#include "api/judge.hpp"
#include "api/static_status.hpp"
#include "compare/fcl_engine.hpp"
#include "compare/harness.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"
#include "tests/app/cli_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::clitest;

namespace {

Scene shipped(const std::string& rel) { return read_scene(src(rel)); }

// The homogeneous matrix of the ellipse/ellipsoid FCL is given: shape
// S = R diag(1/r^2) R^T about the centre c, i.e. [[S, -S c], [-c^T S, c^T S c - 1]].
std::vector<std::vector<double>> pose_matrix(const FclPose& p, int d) {
  std::vector<std::vector<double>> S(d, std::vector<double>(d, 0.0)), A(d + 1, std::vector<double>(d + 1, 0.0));
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      for (int k = 0; k < d; ++k) S[i][j] += p.rotation[i][k] * p.rotation[j][k] / (p.radii[k] * p.radii[k]);
  double cSc = 0;
  for (int i = 0; i < d; ++i) {
    double Sc = 0;
    for (int j = 0; j < d; ++j) {
      A[i][j] = S[i][j];
      Sc += S[i][j] * p.centre[j];
    }
    A[i][d] = A[d][i] = -Sc;
    cSc += p.centre[i] * Sc;
  }
  A[d][d] = cSc - 1;
  return A;
}

// max |P - s Q| / max |P| with s > 0 the least-squares factor (Q is a positive multiple of the quadric).
double relative_mismatch(const std::vector<std::vector<double>>& P, const std::vector<std::vector<double>>& Q) {
  double pq = 0, qq = 0, pmax = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = 0; j < P.size(); ++j) {
      pq += P[i][j] * Q[i][j];
      qq += Q[i][j] * Q[i][j];
      pmax = std::max(pmax, std::abs(P[i][j]));
    }
  REQUIRE(pq > 0);  // a positive multiple, not a negative one
  const double s = pq / qq;
  double e = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = 0; j < P.size(); ++j) e = std::max(e, std::abs(P[i][j] - s * Q[i][j]));
  return e / pmax;
}

bool in_intervals(const Answer& a, double t) {
  return std::any_of(a.intervals.begin(), a.intervals.end(),
                     [&](const auto& iv) { return iv.first.value <= t && t <= iv.second.value; });
}

}  // namespace

TEST_CASE("FCL pose: radii, rotation and centre give back the quadric A(t) in double", "[fcl]") {
  const char* cases[] = {"cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json",
                         "cases/paper003/example2.json",  // 2D matrix motion (affine, rotating)
                         "cases/generated/3d-euler/3d-deg2-colliding-euler-3526122894755803.json",
                         "cases/generated/3d-affine/3d-deg2-colliding-affine-2295206434708192.json",
                         "cases/spheres/spheres-crossing.json"};
  for (const char* c : cases) {
    Scene s = shipped(c);
    const int d = s.dim;
    for (double t : {0.0, 0.3, 0.71, 1.0}) {
      INFO(c << " at t = " << t);
      FclScenePose p = fcl_pose_at(s, t);
      double ea = relative_mismatch(pose_matrix(p.a, d), p.qa), eb = relative_mismatch(pose_matrix(p.b, d), p.qb);
      CHECK(ea < 1e-12);
      CHECK(eb < 1e-12);
      for (const FclPose* x : {&p.a, &p.b}) {
        // a proper rotation: R^T R = I, det +1 (FCL's Transform3d needs one)
        const auto& R = x->rotation;
        const double det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) -
                           R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
                           R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
        CHECK(det == Approx(1).margin(1e-12));
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            double dot = 0;
            for (int k = 0; k < 3; ++k) dot += R[k][i] * R[k][j];
            CHECK(dot == Approx(i == j ? 1.0 : 0.0).margin(1e-12));
          }
      }
      if (d == 2) {  // the embedding: the same third semi-axis for both, along z, centres in z = 0
        CHECK(p.a.radii[2] == p.b.radii[2]);
        CHECK(p.a.radii[2] == std::max({p.a.radii[0], p.a.radii[1], p.b.radii[0], p.b.radii[1]}));
        CHECK(p.a.rotation[2][2] == 1);
        CHECK(p.a.centre[2] == 0);
      }
    }
  }
}

TEST_CASE("fcl/ccd expresses constant shapes translating linearly, nothing else", "[fcl]") {
  // A linear translation (the generator's overlap family: degree 1, motion translation).
  GeneratorSpec o;
  o.dim = 3;
  o.degree = 1;
  o.family = "overlap";
  o.motion = "translation";
  o.d_exponent = 3;
  o.seed = 7;
  Scene lin = scene_from_text(generate_scene(o).doc.dump(), "overlap");
  CHECK(fcl_ccd_inexpressible(lin).empty());
  o.dim = 2;
  CHECK(fcl_ccd_inexpressible(scene_from_text(generate_scene(o).doc.dump(), "overlap-2d")).empty());
  // Rotating bodies are refused, with the reason.
  std::string why =
      fcl_ccd_inexpressible(shipped("cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json"));
  CHECK(why.find("not expressible by FCL's translation motion") != std::string::npos);
  CHECK(why.find("(kinematic): ") != std::string::npos);  // names the object and its motion
  CHECK_FALSE(
      fcl_ccd_inexpressible(shipped("cases/generated/3d-euler/3d-deg2-colliding-euler-3526122894755803.json")).empty());
  CHECK_FALSE(fcl_ccd_inexpressible(shipped("cases/paper003/example2.json")).empty());
  // The first-contact view keeps what fcl/ccd claims.
  Answer ex = solve(lin).answer;
  Answer v = first_contact_view(ex);
  CHECK(v.collides == ex.collides);
  CHECK(v.intervals.empty());
  CHECK(v.contacts.empty());
  CHECK(v.first_contact.has_value() == ex.first_contact.has_value());
}

TEST_CASE("eccd fcl: a bad option or scene is exit 2, with or without FCL", "[fcl][cli-fcl]") {
  const std::string crossing = q(src("cases/spheres/spheres-crossing.json"));
  for (const std::string& args :
       {"fcl " + crossing + " --samples 0", "fcl " + crossing + " --ccd 1", "fcl " + crossing + " --samples 5 --ccd 5",
        "fcl " + crossing + " --bogus", "fcl " + q(src("tests/data/judge/malformed.json")),
        std::string("fcl /nonexistent/scene.json")}) {
    INFO(args);
    Run r = run_eccd(args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.err.empty());
  }
}

#ifdef ECCD_HAVE_FCL

TEST_CASE("fcl/sample agrees with the exact static test at its samples on clear cases", "[fcl]") {
  REQUIRE(fcl_availability().available);
  CHECK(fcl_availability().version == "0.7.0");
  CHECK(fcl_tolerances().find("gjk_tolerance 1e-06") != std::string::npos);
  const char* cases[] = {"cases/spheres/spheres-crossing.json",
                         "cases/spheres/spheres-free.json",
                         "cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json",
                         "cases/generated/2d/2d-deg2-free-kinematic-2054184850131159.json",
                         "cases/generated/3d-euler/3d-deg2-colliding-euler-3526122894755803.json",
                         "cases/generated/3d-euler/3d-deg2-free-euler-311914328102894.json"};
  const int n = 20;
  for (const char* c : cases) {
    Scene s = shipped(c);
    Answer a = fcl_sample(s, n);
    bool any = false;
    for (int k = 0; k <= n; ++k) {
      INFO(c << " at t = " << k << "/" << n);
      Status st = status_at(s, mpq_class(k, n), Arithmetic::exact());
      REQUIRE(st != Status::touching);  // clear cases: no sample at a touch
      const bool meets = st == Status::overlapping;
      CHECK(in_intervals(a, double(k) / n) == meets);
      any = any || meets;
    }
    CHECK(a.collides == any);
    if (a.collides) CHECK(a.first_contact->value == a.intervals.front().first.value);
  }
}

TEST_CASE("fcl/ccd on a linear translation: collides as the exact answer on a clear overlap", "[fcl]") {
  Scene s = shipped("cases/spheres/spheres-crossing.json");  // two spheres on straight lines
  REQUIRE(fcl_ccd_inexpressible(s).empty());
  Answer ex = solve(s).answer;
  Answer a = fcl_ccd(s, 1000);
  CHECK(a.collides == ex.collides);
  CHECK(a.intervals.empty());
  // its contact time is a sample i/999 at or after the certified first contact, within one step
  if (a.collides) CHECK(std::abs(a.first_contact->value - ex.first_contact->value) <= 1.0 / 999 + 1e-12);
  CHECK_THROWS_AS(fcl_ccd(shipped("cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json"), 10),
                  std::invalid_argument);
}

TEST_CASE("harness: certified and fcl rows, fcl/ccd only where expressible", "[fcl]") {
  HarnessOptions o;
  o.mpfr_bits = {};
  o.fcl_samples = {10, 100};
  o.budget_s = 20;
  auto labels = [&](int dim) {
    std::vector<std::string> v;
    for (const auto& p : harness_pipelines(dim, o)) v.push_back(p.label);
    return v;
  };
  const std::vector<std::string> l3 = labels(3);
  for (const char* l : {"certified", "fcl/sample:10", "fcl/sample:100", "fcl/ccd:10", "fcl/ccd:100"})
    CHECK(std::count(l3.begin(), l3.end(), std::string(l)) == 1);
  Scene rot = shipped("cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json");
  std::vector<std::string> csv;
  for (const auto& r : run_scene(rot, scene_info(rot, "cases"), o)) {
    csv.push_back(results_csv_line(r));
    CHECK(r.pipeline.rfind("fcl/ccd", 0) != 0);  // a rotating scene: no fcl/ccd row
    if (r.pipeline == "certified") {
      CHECK(r.arith == "certified");
      CHECK(r.bits == 0);
      CHECK(r.basis == "none");
      CHECK(r.method == "ladder");
      CHECK(r.m.outcome == "correct");
      CHECK(r.m.structure_ok);
    }
    if (r.pipeline == "fcl/sample:100") {
      CHECK(r.arith == "fcl");
      CHECK(r.bits == 53);
      CHECK(r.input == "rounded");
      CHECK(r.m.outcome == "correct");  // a clear collision
    }
  }
  Scene lin = shipped("cases/spheres/spheres-crossing.json");
  int ccd_rows = 0;
  for (const auto& r : run_scene(lin, scene_info(lin, "cases"), o)) {
    csv.push_back(results_csv_line(r));
    if (r.pipeline.rfind("fcl/ccd", 0) == 0) {
      ++ccd_rows;
      CHECK(r.m.exact_intervals == 0);  // compared with the first-contact view: no intervals charged
      CHECK_FALSE(r.m.endpoint_err.has_value());
      CHECK(r.m.first_contact_err.has_value());
      CHECK(r.m.outcome == "correct");
    }
  }
  CHECK(ccd_rows == 2);
  // of the two scenes, the rotating one has no fcl/ccd rows
  auto skipped = fcl_skipped(l3, csv);
  REQUIRE(skipped.size() == 2);
  CHECK(skipped[0] == std::make_pair(std::string("fcl/ccd:10"), 1));
  CHECK(skipped[1] == std::make_pair(std::string("fcl/ccd:100"), 1));
}

TEST_CASE("eccd fcl | eccd judge: the verdict judge computes, and FCL misses a shallow overlap", "[fcl][cli-fcl]") {
  const std::string crossing = src("cases/spheres/spheres-crossing.json");
  Run f = run_eccd("fcl " + q(crossing) + " --samples 10 --json");
  REQUIRE(f.code == 0);
  nlohmann::json j = nlohmann::json::parse(f.out);
  CHECK(j["format"] == "eccd-fcl-answer/1");
  CHECK(j.contains("version"));
  CHECK(j["engine"] == "fcl/sample:10");
  CHECK(j["fcl_version"] == "0.7.0");
  // the answer as judge reads it, judged through the API ...
  Judgement api = judge(read_scene(crossing), answer_from_text(f.out, "fcl.json").answer);
  // ... and through the command line, piped
  Run p =
      run_eccd("fcl " + q(crossing) + " --samples 10 | " + exe() + " judge " + q(crossing) + " - --name fcl --json");
  REQUIRE((p.code == 0 || p.code == 1));
  nlohmann::json v = nlohmann::json::parse(p.out);
  CHECK(v["verdict"] == api.verdict);
  CHECK(v["answer_taken"] == "the \"answer\" of an eccd-fcl-answer/1 object");
  CHECK(p.code == (api.agrees ? 0 : 1));
  CHECK(api.verdict != "wrong collides");  // a clear crossing: collides right, the sampled ends off
  CHECK(api.difference.endpoints_off == 2);

  // A shallow overlap (the generator's overlap family, depth 1e-7): certified collides, FCL says separate.
  GeneratorSpec o;
  o.dim = 3;
  o.degree = 1;
  o.family = "overlap";
  o.motion = "translation";
  o.d_exponent = 7;
  o.seed = 20261121;
  TempDir dir;
  const std::string path = dir.str() + "/overlap.json";
  spit(path, generate_scene(o).doc.dump(2));
  // The cause is FCL's tolerance, not the sampling: at the middle of the certified collision interval
  // the exact static test says overlapping and FCL's static test (default request) says separate.
  Scene ov = read_scene(path);
  Answer ex = solve(ov).answer;
  REQUIRE(ex.intervals.size() == 1);
  const mpq_class mid = (*ex.intervals[0].first.lo + *ex.intervals[0].second.hi) / 2;
  CHECK(status_at(ov, mid, Arithmetic::exact()) == Status::overlapping);
  CHECK_FALSE(fcl_collides_at(ov, mid.get_d()));
  // and a sample of fcl/sample:1000 lies inside the certified interval (so sampling alone would have caught it)
  const double lo = ex.intervals[0].first.value, hi = ex.intervals[0].second.value;
  CHECK(std::floor(hi * 1000) / 1000 >= lo);
  for (const std::string how : {"--samples 1000", "--ccd 1000"}) {
    INFO(how);
    Run w = run_eccd("fcl " + q(path) + " " + how + " | " + exe() + " judge " + q(path) + " -");
    CHECK(w.code == 1);
    CHECK(w.out.find("verdict: wrong collides") != std::string::npos);
    CHECK(w.out.find("collides: certified true, yours false") != std::string::npos);
  }
  // Refused: --ccd on a rotating scene (exit 3, the reason).
  Run r = run_eccd("fcl " + q(src("cases/paper003/example2.json")) + " --ccd 10");
  CHECK(r.code == 3);
  CHECK(r.err.find("not expressible by FCL's translation motion") != std::string::npos);
}

#else

TEST_CASE("without FCL: the pipelines do not exist and eccd fcl refuses (exit 3)", "[fcl]") {
  CHECK_FALSE(fcl_availability().available);
  CHECK_FALSE(fcl_availability().reason.empty());
  CHECK_THROWS_AS(fcl_sample(shipped("cases/spheres/spheres-crossing.json"), 10), FclUnavailable);
  HarnessOptions o;
  o.fcl = true;
  for (const auto& p : harness_pipelines(3, o)) CHECK(p.label.rfind("fcl/", 0) != 0);
  Run r = run_eccd("fcl " + q(src("cases/spheres/spheres-crossing.json")));
  CHECK(r.code == 3);
}

#endif

}  // namespace ECCD_UNITY_ID

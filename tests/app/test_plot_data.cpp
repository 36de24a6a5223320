// The data of `eccd plot` (app/plot_data.hpp, add_scene_data; reached through
// the program ECCD_EXE, whose --data file is that object, eccd-plot-data/1),
// on a scene whose every part is known by hand: A the unit circle at the
// origin, B an ellipse of semi-axes (2, 1) whose centre moves along x as
// 6 - 4t (they touch at t = 3/4 at (1, 0) and overlap after).
//  - snapshots at k/4 (--instants 5): the centres, outline points on the
//    boundaries x² + y² = 1 and ((x - c)/2)² + y² = 1, the contact instant
//    marked; the centres' paths;
//  - the curve is the discriminant Δ(t) of f(λ; t) = det(λA - B(t)) (003 eq.
//    (2)), of degree 8, sampled and divided by its largest sampled |Δ|: checked
//    against Δ computed here exactly at each sample from the hand-made
//    matrices A = diag(1, 1, -1), B(t) = [[1/4, 0, -c/4], [0, 1, 0],
//    [-c/4, 0, c²/4 - 1]] and the cubic discriminant 18abcd - 4b³d + b²c² -
//    4ac³ - 27a²d² (a positive scale of the quadrics changes nothing after the
//    division);
//  - the contact at t = 3/4, at (1, 0).
#include "cli_run.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;

namespace {
const char* kScene = R"({"format": "ellipse-ccd-scene/1", "name": "plot-hand", "dim": 2,
  "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}},
  "b": {"shape": {"semi_axes": ["2", "1"]}, "motion": {"type": "matrix",
        "m": [["1", "0", ["6", "-4"]], ["0", "1", "0"], ["0", "0", "1"]]}}})";

// Δ(t) of det(λA - B(t)) = (λ - 1) [(λ - 1/4)(1 - c²/4 - λ) - c²/16], c = 6 - 4t, exactly.
mpq_class delta(const mpq_class& t) {
  const mpq_class c = 6 - 4 * t, c2 = c * c;
  // (λ - 1/4)(1 - c²/4 - λ) - c²/16 = -λ² + (1 - c²/4 + 1/4) λ - (1 - c²/4)/4 - c²/16
  const mpq_class q2 = -1, q1 = mpq_class(5, 4) - c2 / 4, q0 = -(1 - c2 / 4) / 4 - c2 / 16;
  // times (λ - 1): a λ³ + b λ² + c λ + d
  const mpq_class a = q2, b = q1 - q2, cc = q0 - q1, d = -q0;
  return 18 * a * b * cc * d - 4 * b * b * b * d + b * b * cc * cc - 4 * a * cc * cc * cc - 27 * a * a * d * d;
}
}  // namespace

TEST_CASE("plot data: snapshots, paths, the discriminant curve and the contact of a hand-made scene",
          "[app][plot-data]") {
  TempDir d;
  spit(d.path / "s.json", kScene);
  Run r = run_eccd("plot " + q((d.path / "s.json").string()) + " --out " + q((d.path / "s.png").string()) + " --data " +
                       q((d.path / "data.json").string()) + " --instants 5",
                   120);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const json data = json::parse(slurp(d.path / "data.json"));
  CHECK(data["format"] == "eccd-plot-data/1");
  CHECK(data["dim"] == 2);

  REQUIRE(data["snapshots"].size() == 5);
  for (int k = 0; k < 5; ++k) {
    const json& s = data["snapshots"][k];
    const double t = k / 4.0, c = 6 - 4 * t;
    INFO("t = " << t);
    CHECK(s["t"].get<double>() == t);
    CHECK(s["contact"] == (k == 3));
    CHECK(s["a"]["centre"] == json::array({0.0, 0.0}));
    CHECK(std::abs(s["b"]["centre"][0].get<double>() - c) < 1e-12);
    CHECK(std::abs(s["b"]["centre"][1].get<double>()) < 1e-12);
    for (const char* o : {"a", "b"}) {
      const json& x = s[o]["x"];
      const json& y = s[o]["y"];
      REQUIRE(x.size() == y.size());
      REQUIRE(x.size() >= 16);
      double worst = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        const double px = x[i].get<double>(), py = y[i].get<double>();
        const double on = std::string(o) == "a" ? px * px + py * py : (px - c) * (px - c) / 4 + py * py;
        worst = std::max(worst, std::abs(on - 1));
      }
      CHECK(worst < 1e-5);  // the outline's decimals carry about 7 significant digits
    }
  }
  const json& paths = data["paths"];
  REQUIRE(paths["t"].size() == paths["b"]["x"].size());
  for (std::size_t i = 0; i < paths["t"].size(); ++i) {
    const double t = paths["t"][i].get<double>();
    CHECK(std::abs(paths["b"]["x"][i].get<double>() - (6 - 4 * t)) < 1e-5);
    CHECK(std::abs(paths["b"]["y"][i].get<double>()) < 1e-12);
    CHECK(std::abs(paths["a"]["x"][i].get<double>()) < 1e-12);
  }

  const json& curve = data["curve"];
  CHECK(curve["kind"] == "discriminant");
  CHECK(curve["degree"] == 8);
  CHECK(curve["identically_zero"] == false);
  const json& ts = curve["t"];
  const json& vs = curve["value"];
  REQUIRE(ts.size() == vs.size());
  REQUIRE(ts.size() >= 1000);
  std::vector<mpq_class> mine;
  mpq_class largest = 0;
  for (const auto& t : ts) {
    mine.push_back(delta(mpq_class(t.get<double>())));
    if (abs(mine.back()) > largest) largest = abs(mine.back());
  }
  REQUIRE(largest > 0);
  double worst = 0, top = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double want = mpq_class(mine[i] / largest).get_d();
    worst = std::max(worst, std::abs(vs[i].get<double>() - want));
    top = std::max(top, std::abs(vs[i].get<double>()));
  }
  CHECK(worst < 1e-9);
  CHECK(top == Approx(1.0).epsilon(1e-12));

  REQUIRE(data["contacts"].size() == 1);
  CHECK(data["contacts"][0]["t"] == 0.75);
  CHECK(std::abs(data["contacts"][0]["point"][0].get<double>() - 1) < 1e-9);
  CHECK(std::abs(data["contacts"][0]["point"][1].get<double>()) < 1e-9);
}

}  // namespace ECCD_UNITY_ID

// The JSON form of a separation (api/separate_json.hpp, format
// eccd-separate/1):
//  - a hand-made Separation gives the keys in the header's order (scene, file,
//    dim, arith, t, status, plane, tangent_points, checks, why), the plane and
//    exact checks as rational strings, floating checks as decimals with their
//    error bound, the centre when given; "plane"/"tangent_points" only when
//    there is a plane, "checks" only when there are checks, "why" only when
//    there is a reason;
//  - on real separations (separate_at, 2D and 3D, exact and double): the
//    plane read back from the JSON text alone separates the two objects, by a
//    hand check: for an axis-aligned ellipse of semi-axes r_i centred at c,
//    the line/plane n.x + o = 0 misses it iff (n.c + o)^2 > sum r_i^2 n_i^2,
//    with a on the negative and b on the positive side; the tangent points lie
//    on their objects' boundaries; touching and overlapping have no plane.
#include "api/separate_json.hpp"

#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
mpq_class rat(const std::string& s) {
  mpq_class q(s);
  q.canonicalize();
  return q;
}
std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> k;
  for (auto it = j.begin(); it != j.end(); ++it) k.push_back(it.key());
  return k;
}
// a: unit circle/sphere at the origin; b: semi-axes (2, 1[, 1]) with centre (6 - 4t, 0[, 0]): separate before
// t = 3/4, touching at 3/4 (centre 3 = 1 + 2), overlapping after.
Scene moving_pair(int dim) {
  std::string doc;
  if (dim == 2)
    doc = R"({"format": "ellipse-ccd-scene/1", "name": "sep2", "dim": 2,
      "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}},
      "b": {"shape": {"semi_axes": ["2", "1"]}, "motion": {"type": "matrix",
            "m": [["1", "0", ["6", "-4"]], ["0", "1", "0"], ["0", "0", "1"]]}}})";
  else
    doc = R"({"format": "ellipse-ccd-scene/1", "name": "sep3", "dim": 3,
      "a": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "static"}},
      "b": {"shape": {"semi_axes": ["2", "1", "1"]}, "motion": {"type": "euler", "e": ["1", "0", "0", "0"],
            "translation": [["6", "-4"], "0", "0"], "translation_denominator": "1"}}})";
  return parse_scene(doc, "sep.json");
}
}  // namespace

TEST_CASE("separate json: a hand-made separation in the format's order", "[api][separate-json]") {
  Scene s;
  s.name = "hand";
  s.dim = 2;
  Separation sep;
  sep.status = "separate";
  sep.plane = SeparatingPlane{{rat("1/2"), rat("-3")}, rat("7/4")};
  sep.tangent_points = {{rat("1/3"), rat("0")}, {rat("2"), rat("-1/8")}};
  sep.checks.push_back(PlaneInequality{"a", "q^T adj(Q) q, q = M(t)^T (n, o)", "> 0", rat("5/3"), 0, {}});
  sep.checks.push_back(PlaneInequality{"b", "n.c + o", "> 0", rat("9/4"), 0, {rat("4"), rat("1/2")}});
  const nlohmann::ordered_json j = separation_to_json(s, "hand.json", rat("3/8"), parse_arithmetic("exact"), sep);
  CHECK(keys(j) == std::vector<std::string>{"scene", "file", "dim", "arith", "t", "status", "plane", "tangent_points",
                                            "tangent_points_note", "checks", "checks_note"});
  CHECK(j["scene"] == "hand");
  CHECK(j["file"] == "hand.json");
  CHECK(j["dim"] == 2);
  CHECK(j["arith"] == "exact");
  CHECK(j["t"] == "3/8");
  CHECK(j["status"] == "separate");
  CHECK(j["plane"]["normal"] == nlohmann::ordered_json::array({"1/2", "-3"}));
  CHECK(j["plane"]["offset"] == "7/4");
  CHECK(keys(j["plane"]) == std::vector<std::string>{"normal", "offset", "meaning"});
  // Tangent points: decimals (20 significant digits) even in exact arithmetic.
  CHECK(j["tangent_points"][0][0] == "0.33333333333333333333");
  CHECK(j["tangent_points"][1][1] == "-0.125");
  REQUIRE(j["checks"].size() == 2);
  CHECK(j["checks"][0]["object"] == "a");
  CHECK(j["checks"][0]["value"] == "5/3");
  CHECK_FALSE(j["checks"][0].contains("error_bound"));
  CHECK_FALSE(j["checks"][0].contains("centre"));
  CHECK(j["checks"][1]["centre"] == nlohmann::ordered_json::array({"4", "1/2"}));
  CHECK(keys(j["checks"][1]) == std::vector<std::string>{"object", "quantity", "relation", "value", "centre"});

  // Floating: decimals with error bounds; the plane stays exact (the rationals of its doubles).
  sep.checks[0].value = rat("1/3");
  sep.checks[0].error_bound = 1e-15;
  const nlohmann::ordered_json f = separation_to_json(s, "hand.json", rat("1"), parse_arithmetic("mpfr:128"), sep);
  CHECK(f["arith"] == "mpfr:128");
  CHECK(f["t"] == "1");
  CHECK(f["plane"]["offset"] == "7/4");
  CHECK(f["checks"][0]["value"] == "0.33333333333333333");  // 17 significant digits
  CHECK(f["checks"][0]["error_bound"] == 1e-15);
  CHECK(f["checks"][1]["centre"] == nlohmann::ordered_json::array({"4", "0.5"}));
  CHECK(f["checks_note"].get<std::string>().find("mpfr:128") != std::string::npos);

  // Undecided: no plane, no checks, the reason.
  Separation u;
  u.status = "undecided";
  u.why = "the static test is within its error bound";
  const nlohmann::ordered_json w = separation_to_json(s, "", rat("1/2"), parse_arithmetic("double"), u);
  CHECK(keys(w) == std::vector<std::string>{"scene", "file", "dim", "arith", "t", "status", "why"});
  CHECK(w["why"] == u.why);
}

TEST_CASE("separate json: the plane in the JSON separates the objects by a hand check", "[api][separate-json]") {
  for (int dim : {2, 3}) {
    const Scene s = moving_pair(dim);
    for (const char* ar : {"exact", "double", "certified"}) {
      for (const char* tt : {"0", "1/4", "1/2", "23/32"}) {
        INFO(dim << "D " << ar << " t = " << tt);
        SolveOptions o;
        o.arith = parse_arithmetic(ar);
        const mpq_class t = rat(tt);
        const nlohmann::ordered_json j = separation_to_json(s, "sep.json", t, o.arith, separate_at(s, t, o));
        // Read back from the text, as a user would.
        const nlohmann::json back = nlohmann::json::parse(j.dump());
        CHECK(back["t"] == tt);
        if (back["status"] == "undecided") {
          CHECK(std::string(ar) == "double");  // only a floating run may leave it open
          continue;
        }
        REQUIRE(back["status"] == "separate");
        std::vector<mpq_class> n;
        for (const auto& x : back["plane"]["normal"]) n.push_back(rat(x.get<std::string>()));
        REQUIRE(int(n.size()) == dim);
        const mpq_class off = rat(back["plane"]["offset"].get<std::string>());
        // Centres: a at 0, b at (6 - 4t, 0, ...); semi-axes a: 1, b: (2, 1, ...).
        const mpq_class cb = 6 - 4 * t;
        const mpq_class sa = off, sb = n[0] * cb + off;  // n.c + o
        mpq_class ra = 0, rb = 4 * n[0] * n[0];
        for (int i = 0; i < dim; ++i) ra += n[i] * n[i];
        for (int i = 1; i < dim; ++i) rb += n[i] * n[i];
        CHECK(sa < 0);
        CHECK(sb > 0);
        CHECK(sa * sa > ra);
        CHECK(sb * sb > rb);
        // The tangent points on their objects' boundaries (decimals of 20 digits).
        REQUIRE(back["tangent_points"].size() == 2);
        double on_a = 0, on_b = 0;
        for (int i = 0; i < dim; ++i) {
          const double pa = std::stod(back["tangent_points"][0][i].get<std::string>());
          const double pb = std::stod(back["tangent_points"][1][i].get<std::string>());
          on_a += pa * pa;
          on_b += i == 0 ? (pb - cb.get_d()) * (pb - cb.get_d()) / 4 : pb * pb;
        }
        CHECK(std::abs(on_a - 1) < 1e-9);
        CHECK(std::abs(on_b - 1) < 1e-9);
        CHECK(back.contains("checks"));
      }
      // Touching at 3/4 and overlapping at 1: no plane.
      SolveOptions o;
      o.arith = parse_arithmetic(ar);
      for (const char* tt : {"3/4", "1"}) {
        const nlohmann::ordered_json j =
            separation_to_json(s, "sep.json", rat(tt), o.arith, separate_at(s, rat(tt), o));
        CHECK_FALSE(j.contains("plane"));
        CHECK_FALSE(j.contains("tangent_points"));
        if (std::string(ar) != "double") CHECK(j["status"] == (std::string(tt) == "1" ? "overlapping" : "touching"));
      }
    }
  }
}

}  // namespace ECCD_UNITY_ID

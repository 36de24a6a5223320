// The checker's own scene reader (certificate/check/scene.hpp, scene.cpp;
// the format of /work/shared/spec/scene-format.md), against values worked
// out by hand:
//   - scene_number: JSON integers (also 2^64 - 1), "-63", "3/7", "6/4" (in
//     lowest terms), decimals "1.8" = 9/5, "2.5e-3" = 1/400, "+.5", "5.",
//     "1E2"; refused: a zero or signed denominator, two dots, no digits, an
//     exponent beyond 10000, spaces, a JSON float (parse_strict's
//     "json-float:" text, with its own message), non-strings; every message
//     names the file and the JSON place;
//   - shapes: semi_axes a -> diag(1/a², .., -1), semi_axes_squared s ->
//     diag(1/s, .., -1), matrix as written (symmetry required);
//   - motions: static I; matrix as written (polynomials in power form, in
//     Bernstein form, bare numbers; last row (0, .., 0, w) required);
//     kinematic (003 eq. (3)): the upper-left block is w·(rotation) with
//     c² + s² = w²; euler: the upper-left block is v3·R with RᵀR = E² I and
//     the corner E·v3; cycloidal: its six parameters, flagged;
//   - the document: format, dim 2 or 3, "parameters": "independent", and
//     refusals (wrong format, dim 4, missing key, unknown motion type,
//     kinematic in 3D) with the place in the message.
#include "certificate/check/pencil.hpp"
#include "certificate/check/scene.hpp"
#include "certificate/check/strict_json.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::check;
using nlohmann::json;

namespace {

mpq_class num(const json& j) { return scene_number(j, "s.json", "/x"); }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneReadError& e) {
    return e.what();
  }
  return "";
}

json doc2(const json& a_shape, const json& a_motion) {
  return json{{"format", "ellipse-ccd-scene/1"},
              {"dim", 2},
              {"a", {{"shape", a_shape}, {"motion", a_motion}}},
              {"b", {{"shape", {{"semi_axes", {"1", "1"}}}}, {"motion", {{"type", "static"}}}}}};
}

QMatrix transpose_times(const QMatrix& a, const QMatrix& b) {  // aᵀ b
  const std::size_t n = a.size();
  QMatrix r(n, std::vector<mpq_class>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k) r[i][j] += a[k][i] * b[k][j];
  return r;
}

}  // namespace

TEST_CASE("check scene_number reads exact numbers and refuses the rest", "[certificate][check_scene]") {
  CHECK(num(json(-63)) == -63);
  CHECK(num(json(std::uint64_t(18446744073709551615ull))) == mpq_class(mpz_class("18446744073709551615")));
  CHECK(num("3/7") == mpq_class(3, 7));
  CHECK(num("6/4") == mpq_class(3, 2));
  CHECK(num("-6/4").get_den() == 2);
  CHECK(num("1.8") == mpq_class(9, 5));
  CHECK(num("2.5e-3") == mpq_class(1, 400));
  CHECK(num("+.5") == mpq_class(1, 2));
  CHECK(num("5.") == 5);
  CHECK(num("1E2") == 100);
  CHECK(num("-0") == 0);
  CHECK(num("123456789012345678901234567890") == mpq_class(mpz_class("123456789012345678901234567890")));
  for (const char* bad : {"1/0", "3/-7", "/7", "3/", "1.2.3", "e5", ".", "1e10001", "", " 1", "1 ", "abc", "0x10"}) {
    INFO(bad);
    const std::string m = error_of([&] { num(bad); });
    CHECK(m.rfind("s.json: /x: expected an exact number", 0) == 0);
  }
  // a JSON number with a fraction, as parse_strict keeps it
  const json floaty = parse_strict(R"({"v": 1.8})", "s.json").value["v"];
  CHECK(error_of([&] { num(floaty); }).find("not exact: write it as a string") != std::string::npos);
  CHECK_FALSE(error_of([&] { num(json::array()); }).empty());
  CHECK_FALSE(error_of([&] { num(json(true)); }).empty());
}

TEST_CASE("check read_check_scene: shapes and simple motions", "[certificate][check_scene]") {
  CheckScene s = read_check_scene(doc2({{"semi_axes", {"2", "3/2"}}}, {{"type", "static"}}), "s.json");
  CHECK(s.dim == 2);
  CHECK_FALSE(s.independent);
  CHECK_FALSE(s.cycloidal);
  CHECK(s.a.Q == QMatrix{{mpq_class(1, 4), 0, 0}, {0, mpq_class(4, 9), 0}, {0, 0, -1}});
  CHECK(s.a.M.size() == 3);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) CHECK(s.a.M[i][j] == (i == j ? QPoly::constant(1) : QPoly()));
  s = read_check_scene(doc2({{"semi_axes_squared", {"2", "1/3"}}}, {{"type", "static"}}), "s.json");
  CHECK(s.a.Q == QMatrix{{mpq_class(1, 2), 0, 0}, {0, 3, 0}, {0, 0, -1}});
  s = read_check_scene(
      doc2({{"matrix", {{"1", "1/2", "0"}, {"1/2", "2", "0"}, {"0", "0", "-1"}}}},
           {{"type", "matrix"},
            {"m",
             {{"1", "0", {"1", "2"}}, {"0", "1", json{{"bernstein", {"0", "3"}}}}, {"0", "0", json::array({"1"})}}}}),
      "s.json");
  CHECK(s.a.Q[0][1] == mpq_class(1, 2));
  CHECK(s.a.M[0][2] == QPoly(std::vector<mpq_class>{1, 2}));
  CHECK(s.a.M[1][2] == QPoly(std::vector<mpq_class>{0, 3}));  // Bernstein (0, 3): 3t
  CHECK(s.a.M[2][2] == QPoly::constant(1));
  s = read_check_scene(doc2({{"semi_axes", {"1", "1"}}},
                            {{"type", "cycloidal"},
                             {"angle_over_pi", {"0", "10/9"}},
                             {"translation", json::array({json::array({"-80", "115"}), json::array({"-38", "55"})})}}),
                       "s.json");
  CHECK(s.cycloidal);
  CHECK(s.a.motion_type == "cycloidal");
  CHECK(s.a.cycloid == std::vector<mpq_class>{0, mpq_class(10, 9), -80, 115, -38, 55});
  json d = doc2({{"semi_axes", {"1", "1"}}}, {{"type", "static"}});
  d["parameters"] = "independent";
  CHECK(read_check_scene(d, "s.json").independent);
}

TEST_CASE("check read_check_scene: kinematic and euler motions are similarities", "[certificate][check_scene]") {
  // kinematic d = (1 + t, -t, 2, t): the upper-left 2 x 2 block is w R with c² + s² = w², w = d2² + d3²
  const CheckScene k = read_check_scene(
      doc2({{"semi_axes", {"1", "1"}}}, {{"type", "kinematic"}, {"d", {{"1", "1"}, {"0", "-1"}, "2", {"0", "1"}}}}),
      "s.json");
  for (const mpq_class& t : {mpq_class(0), mpq_class(1, 3), mpq_class(1)}) {
    const QMatrix M = at_point(k.a.M, t);
    const mpq_class w = 4 + t * t;
    CHECK(M[2][2] == w);
    CHECK(M[0][0] * M[0][0] + M[1][0] * M[1][0] == w * w);
    CHECK(M[0][0] == M[1][1]);
    CHECK(M[0][1] == -M[1][0]);
    CHECK(M[2][0] == 0);
    CHECK(M[2][1] == 0);
  }
  // euler e = (1, 1 + t, -2, t/2), translation (t, 2, -1), denominator 3: block v3 R with RᵀR = E² I
  json d = {{"format", "ellipse-ccd-scene/1"},
            {"dim", 3},
            {"a",
             {{"shape", {{"semi_axes", {"1", "2", "3"}}}},
              {"motion",
               {{"type", "euler"},
                {"e", {{"1"}, {"1", "1"}, {"-2"}, {"0", "1/2"}}},
                {"translation", {{"0", "1"}, {"2"}, {"-1"}}},
                {"translation_denominator", {"3"}}}}}},
            {"b", {{"shape", {{"semi_axes", {"1", "1", "1"}}}}, {"motion", {{"type", "static"}}}}}};
  const CheckScene e = read_check_scene(d, "s.json");
  CHECK(e.dim == 3);
  CHECK(e.a.Q[2][2] == mpq_class(1, 9));
  for (const mpq_class& t : {mpq_class(0), mpq_class(2, 5), mpq_class(1)}) {
    const QMatrix M = at_point(e.a.M, t);
    const mpq_class E = 1 + (1 + t) * (1 + t) + 4 + t * t / 4;
    QMatrix R(3, std::vector<mpq_class>(3));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) R[i][j] = M[i][j];
    const QMatrix RtR = transpose_times(R, R);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) CHECK(RtR[i][j] == (i == j ? 9 * E * E : mpq_class(0)));
    CHECK(M[3][3] == 3 * E);
    CHECK(M[0][3] == E * t);
    CHECK(M[1][3] == 2 * E);
    CHECK(M[3][0] == 0);
  }
}

TEST_CASE("check read_check_scene refuses with the place", "[certificate][check_scene]") {
  auto err = [](const json& d) { return error_of([&] { read_check_scene(d, "bad.json"); }); };
  json d = doc2({{"semi_axes", {"1", "1"}}}, {{"type", "static"}});
  d["format"] = "ellipse-ccd-scene/2";
  CHECK(err(d).find("bad.json: /format:") == 0);
  d = doc2({{"semi_axes", {"1", "1"}}}, {{"type", "static"}});
  d["dim"] = 4;
  CHECK(err(d).find("bad.json: /dim: expected 2 or 3") == 0);
  d.erase("dim");
  CHECK(err(d).find("missing key \"dim\"") != std::string::npos);
  CHECK(err(doc2({{"semi_axes", {"1", "1"}}}, {{"type", "spinning"}})).find("/a/motion/type: unknown motion type") !=
        std::string::npos);
  CHECK(err(doc2({{"semi_axes", {"1"}}}, {{"type", "static"}})).find("/a/shape/semi_axes: expected 2 entries") !=
        std::string::npos);
  CHECK(err(doc2({{"semi_axes", {"1", "-1"}}}, {{"type", "static"}})).find("/a/shape/semi_axes/1: must be positive") !=
        std::string::npos);
  CHECK(err(doc2({{"matrix", {{"1", "1", "0"}, {"0", "1", "0"}, {"0", "0", "-1"}}}}, {{"type", "static"}}))
            .find("not symmetric") != std::string::npos);
  CHECK(err(doc2({{"semi_axes", {"1", "1"}}, {"semi_axes_squared", {"1", "1"}}}, {{"type", "static"}}))
            .find("exactly one of") != std::string::npos);
  CHECK(err(doc2({{"semi_axes", {"1", "1"}}},
                 {{"type", "matrix"}, {"m", {{"1", "0", "0"}, {"0", "1", "0"}, {"1", "0", "1"}}}}))
            .find("the last row must be (0, ..., 0, w(t))") != std::string::npos);
  CHECK(err(doc2({{"semi_axes", {"1", "1"}}}, {{"type", "euler"}})).find("3D only") != std::string::npos);
  CHECK(err(json::array()).find("bad.json: top level:") == 0);
}

}  // namespace ECCD_UNITY_ID

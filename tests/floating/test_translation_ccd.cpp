// The translating-pair shortcut of the 3D floating pipeline
// (floating/translation_ccd.hpp, routed by api/solve.cpp): on seeded random
// pairs of ellipsoids in straight-line relative translation, and on sphere
// pairs built to touch exactly or to miss or overlap by 1e-9, each face's
// answer is compared with the exact pipeline's (api/answer_difference.hpp,
// tolerance 1e-6). The guarded face must never be confidently wrong: a
// decided answer agrees, an undecided one claims no collision the exact
// answer lacks. The as-published face is 001's Bézier method, never the
// shortcut, and must agree on the random pairs, which are not built near a
// touch. Most random pairs must be decided by the shortcut itself in the
// guarded face (Solution::method "translation"), so the comparison tests it
// and not the Bézier method it falls back to; every constructed touch must
// fall back (a touch cannot be proved by strict signs).
#include "api/answer_difference.hpp"
#include "api/solve.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

std::string q(long num, long den) { return std::to_string(num) + "/" + std::to_string(den); }

// One body: semi-axes, a constant quaternion, and a translation c + t v (each given as num/den strings).
std::string body(const std::string (&axes)[3], const long (&e)[4], const std::string (&c)[3],
                 const std::string (&v)[3]) {
  std::string s = R"({"shape": {"semi_axes": [")" + axes[0] + R"(", ")" + axes[1] + R"(", ")" + axes[2] +
                  R"("]}, "motion": {"type": "euler", "e": [)";
  for (int i = 0; i < 4; ++i) s += (i ? ", \"" : "\"") + std::to_string(e[i]) + "\"";
  s += R"(], "translation": [)";
  for (int i = 0; i < 3; ++i) s += std::string(i ? ", " : "") + "[\"" + c[i] + "\", \"" + v[i] + "\"]";
  return s + "]}}";
}

Scene scene_of(const std::string& a, const std::string& b, const std::string& name) {
  return scene_from_text(
      R"({"format": "ellipse-ccd-scene/1", "name": ")" + name + R"(", "dim": 3, "a": )" + a + ", \"b\": " + b + "}",
      name);
}

// A random pair whose paths pass near each other around a random instant.
Scene random_pair(std::mt19937_64& rng, int k) {
  std::uniform_int_distribution<long> ax(8, 24), quat(-3, 3), off(-24, 24), vel(-64, 64), when(2, 8);
  const long ts = when(rng);  // the instant ts/10 near which the centres pass
  auto make = [&](long dx) {
    std::string axes[3], c[3], v[3];
    long e[4];
    for (auto& a : axes) a = q(ax(rng), 8);
    do {
      for (long& x : e) x = quat(rng);
    } while (!e[0] && !e[1] && !e[2] && !e[3]);
    for (int i = 0; i < 3; ++i) {
      const long vi = vel(rng), oi = off(rng) + (i == 0 ? dx : 0);
      v[i] = q(vi, 8);
      c[i] = q(oi * 10 - vi * ts, 80);  // c + (ts/10) v = oi/8
    }
    return body(axes, e, c, v);
  };
  return scene_of(make(0), make(0), "translating-" + std::to_string(k));
}

// Spheres of radii ra (static, at 0) and rb moving along (x0 + t vx, D, 0): D = ra + rb touches at x = 0.
Scene sphere_pass(long ra, long rb, long x0, long vx, const std::string& D, const std::string& name) {
  const std::string sa[3] = {std::to_string(ra), std::to_string(ra), std::to_string(ra)};
  const std::string sb[3] = {std::to_string(rb), std::to_string(rb), std::to_string(rb)};
  const long id[4] = {1, 0, 0, 0};
  const std::string z[3] = {"0", "0", "0"}, c[3] = {std::to_string(x0), D, "0"}, v[3] = {std::to_string(vx), "0", "0"};
  return scene_of(body(sa, id, z, z), body(sb, id, c, v), name);
}

struct Tally {
  int shortcut = 0, decided = 0, runs = 0;
};

// Both faces against the exact answer; published must agree when `published_exact`.
void check_faces(const Scene& s, bool published_exact, Tally& tally) {
  SolveOptions ex;
  ex.arith = Arithmetic::exact();
  const Solution exact = solve(s, ex);
  for (const Guard g : {Guard::bound, Guard::none}) {
    SolveOptions o;
    o.arith = Arithmetic::double_precision();
    o.guard = g;
    const Solution got = solve(s, o);
    ++tally.runs;
    if (g == Guard::bound)
      tally.shortcut += got.method == "translation";
    else
      CHECK(got.method != "translation");
    const AnswerDifference d = answer_difference(got.answer, exact.answer);
    INFO(s.name << " guard " << to_string(g) << " method " << got.method << ": "
                << (d.differences.empty() ? "" : d.differences[0]));
    if (g == Guard::bound) {
      if (got.decided()) {
        ++tally.decided;
        CHECK(d.agrees);
      } else if (got.answer.collides) {
        CHECK(exact.answer.collides);
      }
    } else if (published_exact) {
      CHECK(d.agrees);
    }
  }
}

}  // namespace

TEST_CASE("translating pairs: both faces equal the exact answer on seeded random pairs", "[translation][exact]") {
  std::mt19937_64 rng(3636);
  Tally t;
  const int n = 40;
  for (int k = 0; k < n; ++k) check_faces(random_pair(rng, k), true, t);
  INFO("shortcut " << t.shortcut << " of " << t.runs << " runs, guarded decided " << t.decided);
  CHECK(t.decided == n);
  CHECK(t.shortcut >= n * 9 / 10);
}

TEST_CASE("translating pairs: touches fall back, near touches are never confidently wrong", "[translation][exact]") {
  Tally t;
  int k = 0;
  for (const auto& [ra, rb, x0, vx] : {std::array<long, 4>{1, 2, -4, 8}, {2, 1, 3, -5}, {3, 3, -1, 3}}) {
    const std::string D = std::to_string(ra + rb);
    for (const std::string& d : {D, D + "+1/1000000000", D + "-1/1000000000"}) {
      // The reader takes rationals only: D ± 1e-9 as one fraction.
      std::string text = d;
      if (d != D) text = q((ra + rb) * 1000000000 + (d.find('+') != std::string::npos ? 1 : -1), 1000000000);
      const Scene s = sphere_pass(ra, rb, x0, vx, text, "sphere-pass-" + std::to_string(k++));
      Tally one;
      check_faces(s, false, one);
      t.runs += one.runs;
      if (d == D) {
        SolveOptions o;
        o.arith = Arithmetic::double_precision();
        CHECK(solve(s, o).method != "translation");  // a touch is not proved by strict signs
      }
    }
  }
  CHECK(t.runs == 18);
}

}  // namespace ECCD_UNITY_ID

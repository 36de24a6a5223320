#pragma once
// `eccd solve`: one scene, one arithmetic, one answer (JSON and a summary).
//
// Arithmetic names: "double", "mpfr:BITS" (53 <= BITS <= 65536), "exact",
// "certified" (interval arithmetic, escalating where a sign is uncertain to
// MPFI intervals of 256 bits, then to exact: certified/certified_policy.hpp;
// the JSON says where it was decided), "certified:B1,B2,..." (other MPFI
// rungs, increasing) or "certified:none" (straight from doubles to exact).
// Errors: std::invalid_argument for a request the pipeline refuses (a
// cycloidal motion in exact arithmetic, an unknown arithmetic or method); io/scene_reader.hpp's SceneError for bad files.
#include "kernel/prepared_scene.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace eccd {

struct Arithmetic {
  enum Kind { Double, Mpfr, Exact, Certified } kind = Exact;
  int bits = 0;  // MPFR precision; 53 for double and certified (intervals of doubles); 0 for exact
  std::vector<int> rungs;  // certified: the MPFI precisions tried after intervals of doubles, before exact
  std::string name() const;
};
Arithmetic parse_arithmetic(const std::string& text);
// Throws std::invalid_argument unless method is bezier, projection, sampling:N or marching:N.
void check_method(const std::string& method);

struct SolveOptions {
  Arithmetic arith;
  std::string basis = "bernstein";  // floating only: power | bernstein | scaled-bernstein
  int variant = 0;                   // 2D: 0 answer, 1 collides, 2 first contact, 3 all contacts
  std::string method = "bezier";     // 3D floating: bezier | projection | sampling:N | marching:N
  bool first_contact = false;        // 3D: stop after the first collision interval (001 section 4)
  // Floating only (double, mpfr): start from the scene's numbers rounded to the
  // arithmetic (default) or from the exactly prepared scene (kernel/prepared_scene.hpp).
  // Ignored by exact and certified runs (the JSON then says "prepared").
  InputMode input = InputMode::rounded;
};

// The deadline a floating run gets when its caller set none (or a later one):
// it then ends with what it has not resolved undecided, reason "time budget".
inline constexpr double kDefaultFloatingSeconds = 30.0;

// Runs the 2D or 3D pipeline; returns the full JSON report (spec answer + extras).
nlohmann::json solve_scene(const Scene& scene, const SolveOptions& opt);
// The spec's answer (collides, intervals, first_contact, contacts, in that
// order) out of that JSON: what a scene file stores under "answer".
nlohmann::ordered_json stored_answer_of(const nlohmann::json& report);
// A few human-readable lines from that JSON.
std::string summary_text(const nlohmann::json& report);

}  // namespace eccd

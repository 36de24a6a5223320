// The plane check of 000 section 4: per pair-frame cost of
// eccd::plane_separates_on_frame (api/separate.hpp) on a 000 Table 1 pair
// (semi-axes 3, 3, 5, centres 8 apart, each rotating about its own axis by
// about 0.1 rad over the frame: quaternions (1, t/20, 0, 0) and (1, 0, t/20, 0),
// motion degree 2, h_a and h_b of degree 4), the kept plane being the exact
// plane of separate_at at t = 0. Baseline: the continuous test of the same
// pair-frame in double (eccd::solve, Bézier method), which a plane that
// separates saves (000 section 4).
#include "bench/groups.hpp"

namespace eccd_bench::groups {

void register_planes() {
  group(
      "plane-check", "Plane check over one frame (000 section 4), per pair-frame",
      "eccd::plane_separates_on_frame(scene, plane, arith) for a kept plane on a 000 Table 1 pair-frame (semi-axes 3, "
      "3, 5, "
      "centres 8 apart, rotations of about 0.1 rad per frame, motion degree 2): h_a, h_b built from M(t) and adj(Q), "
      "Bernstein "
      "signs (double: with error bounds; exact: rationals, Sturm only if a coefficient is not positive). The plane is "
      "separate_at(scene, 0, exact). Baseline: the continuous test of the same pair-frame in double (eccd::solve, "
      "Bézier).",
      "000 Table 1: separating planes save the characteristic-equation solve in most frames (µs per frame with and "
      "without "
      "planes)");
  static Lazy<std::pair<Scene, SeparatingPlane>> pair([] {
    Scene s = scene_from_text(R"({"format": "ellipse-ccd-scene/1", "name": "table1-pair", "dim": 3,
      "a": {"shape": {"semi_axes": ["3", "3", "5"]}, "motion": {"type": "euler", "e": ["1", ["0", "1/20"], "0", "0"], "translation": ["-4", "0", "0"]}},
      "b": {"shape": {"semi_axes": ["3", "3", "5"]}, "motion": {"type": "euler", "e": ["1", "0", ["0", "1/20"], "0"], "translation": ["4", "0", "0"]}}})",
                              "table1-pair");
    SolveOptions ex;
    Separation sep = separate_at(s, 0, ex);
    if (!sep.plane) throw std::runtime_error("bench plane-check: the pair is not separate at t = 0");
    // The measured case is a kept plane that holds over the frame (the check's whole work, no early refutation).
    if (plane_separates_on_frame(s, *sep.plane, ex) != PlaneCheck::separates)
      throw std::runtime_error("bench plane-check: the plane of t = 0 does not separate over the frame");
    return std::make_pair(s, *sep.plane);
  });
  auto opts = [](const char* a) {
    SolveOptions o;
    o.arith = parse_arithmetic(a);
    return o;
  };
  row("plane-check", "continuous test, double (baseline)", true, Cost::slow,
      "eccd::solve(scene, double): the Bézier method", [opts](benchmark::State& st) {
        const SolveOptions o = opts("double");
        timed(
            st, "plane-check/continuous test, double (baseline)",
            [&] { return solve(pair.get().first, o).answer.collides; },
            [](bool c) {
              return json{{"collides", c}};
            });
      });
  for (const char* a : {"double", "exact", "certified", "mpfr:128"}) {
    const std::string label = std::string("plane check, ") + a;
    row("plane-check", label, false, Cost::slow, std::string("eccd::plane_separates_on_frame, arith ") + a,
        [opts, a, label](benchmark::State& st) {
          const SolveOptions o = opts(a);
          timed(
              st, "plane-check/" + label,
              [&] { return int(plane_separates_on_frame(pair.get().first, pair.get().second, o)); },
              [](int r) {
                return json{{"result", to_string(PlaneCheck(r))}};
              });
        });
  }
  row("plane-check", "new plane, separate_at exact", false, Cost::slow,
      "eccd::separate_at(scene, 1, exact): a new proved plane", [opts](benchmark::State& st) {
        const SolveOptions o = opts("exact");
        timed(
            st, "plane-check/new plane, separate_at exact", [&] { return separate_at(pair.get().first, 1, o).status; },
            [](const std::string& s) {
              return json{{"status", s}};
            });
      });
}

}  // namespace eccd_bench::groups

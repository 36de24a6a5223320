// One 3D continuous query of two ellipsoids translating linearly
// (motion degree 1; B also turned by a fixed rotation), colliding on about
// [0.32, 0.67], through eccd::solve in double (the default 3D method, the
// Bézier zero-set analysis, with everything `eccd solve` does per call:
// rounding the scene, g_k, F(u, t), the contact points). Baseline: the same
// call; the row "pipeline only" times characteristic_bernstein + ccd_bezier
// from the prepared pair (what the call adds around it is the difference).
#include "bench/groups.hpp"

namespace eccd_bench::groups {

void register_translation3d() {
  const char* grp = "ccd3d-deg1-translation";
  group(
      grp, "3D CCD, both ellipsoids translating linearly (motion degree 1), colliding, one query",
      "eccd::solve(scene, double) on two ellipsoids (semi-axes 1, 2, 3 and 2, 1, 1, B turned by a fixed rotation) "
      "translating towards each other along x, colliding on about [0.32, 0.67]: the default 3D method (001 section 4, "
      "the Bézier zero-set analysis). Baseline: the same call. Rows certified: the same call with --arith certified, "
      "and the certified ladder (run_certified) from the prepared pair.",
      "speed targets: double at most 50 µs, certified at most 150 µs; FCL's continuous test (1000 samples) 0.39 ms");
  static Lazy<Scene3D> sc([] {
    Scene s = scene_from_text(R"({"format": "ellipse-ccd-scene/1", "name": "deg1-translating-pair", "dim": 3,
      "a": {"shape": {"semi_axes": ["1", "2", "3"]}, "motion": {"type": "euler", "e": ["1", "0", "0", "0"], "translation": [["-4", "8"], "0", "0"]}},
      "b": {"shape": {"semi_axes": ["2", "1", "1"]}, "motion": {"type": "euler", "e": ["1", "1/3", "0", "1/5"], "translation": [["4", "-8"], ["1/2", "0"], "0"]}}})",
                              "deg1-translating-pair");
    Scene3D out{"deg1-translating-pair", s, prepare_pair<4>(s), json::object()};
    out.info = {{"dim", 3},
                {"file", "(inline, bench/group_translation3d.cpp)"},
                {"what", "two ellipsoids translating linearly, colliding"}};
    return out;
  });
  row(grp, "double solve (API)", true, Cost::slow,
      "eccd::solve(scene, double): the Bézier method, contact points included", [grp](benchmark::State& st) {
        note_scene(sc.get(), grp);
        SolveOptions o;
        o.arith = parse_arithmetic("double");
        timed(
            st, std::string(grp) + "/double solve (API)", [&] { return solve(sc.get().scene, o).answer.collides; },
            [](bool c) {
              return json{{"collides", c}};
            });
      });
  // The certified query, target 150 µs: the same call with --arith certified, and the ladder alone.
  row(grp, "certified solve (API)", false, Cost::slow,
      "eccd::solve(scene, certified): the certified ladder (interval Bézier proof first)", [grp](benchmark::State& st) {
        SolveOptions o;
        o.arith = Arithmetic::certified();
        timed(
            st, std::string(grp) + "/certified solve (API)", [&] { return solve(sc.get().scene, o); },
            [](const Solution& r) { return summarise_solution(r); });
      });
  row(grp, "certified ladder only (run_certified)", false, Cost::slow, "run_certified<4> from the prepared pair",
      [grp](benchmark::State& st) {
        const std::vector<int> rungs = Arithmetic::certified().mpfi_rungs;
        timed(
            st, std::string(grp) + "/certified ladder only (run_certified)",
            [&] { return run_certified<4>(sc.get().p, rungs, Variant::answer, false); },
            [](const Solution& r) { return summarise_solution(r); });
      });
  // The anchor (FCL's continuous test of such a pair, 1000 samples, 0.39 ms) in the same run.
  row(grp, "FCL continuous, 1000 samples (fcl_ccd)", false, Cost::slow,
      "compare/fcl_engine fcl_ccd(scene, 1000): fcl::continuousCollide, CCDC_NAIVE, CCDM_TRANS (first contact only)",
      [grp](benchmark::State& st) {
        const std::string why = eccd_bench::fcl_bench_unavailable(),
                          bad = why.empty() ? fcl_ccd_inexpressible(sc.get().scene) : "";
        if (!why.empty() || !bad.empty()) {
          st.SkipWithError((why + bad).c_str());
          return;
        }
        timed(
            st, std::string(grp) + "/FCL continuous, 1000 samples (fcl_ccd)",
            [&] { return fcl_ccd(sc.get().scene, 1000); },
            [](const Answer& a) {
              json j{{"collides", a.collides}};
              if (a.first_contact) j["first_contact"] = short_instant(*a.first_contact);
              return j;
            });
      });
  row(grp, "double pipeline only", false, Cost::slow,
      "characteristic_bernstein<double,4> + ccd_bezier from the prepared pair", [grp](benchmark::State& st) {
        timed(
            st, std::string(grp) + "/double pipeline only",
            [&] { return run3d_floating<double>(sc.get().p, "bezier", Basis::bernstein, 53, 1.0, false); },
            [](const auto& r) { return summarise_ccd(r); });
      });
}

}  // namespace eccd_bench::groups

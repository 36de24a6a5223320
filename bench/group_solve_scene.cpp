// Rows through eccd::solve_scene: a table of (label, SolveOptions).
//
// The certified interval mode (`--arith certified`, certified/ladder.hpp and
// api/solve.cpp) is measured here, through solve_scene, as `eccd solve` runs it
// (it may escalate to exact; the JSON says so and the row's result shows it).
// More of its rows go into kSolveSceneRows below; a target for it goes into
// TARGETS in bench/perf_report/targets.py.
#include "bench/groups.hpp"

namespace eccd_bench::groups {

struct SolveRow {
  const char* group;
  const char* label;
  int dim;  // 2: the 2D degree-6 scene; 3: paper 002's example
  SolveOptions (*options)();
};

const SolveRow kSolveSceneRows[] = {
    {"solve_scene-2d-deg6", "double v3", 2, [] { return opts("double", 3); }},
    {"solve_scene-2d-deg6", "mpfr:128 v3", 2, [] { return opts("mpfr:128", 3); }},
    {"solve_scene-2d-deg6", "exact v3", 2, [] { return opts("exact", 3); }},
    {"solve_scene-2d-deg6", "exact v0", 2, [] { return opts("exact", 0); }},
    {"solve_scene-2d-deg6", "certified v3", 2, [] { return opts("certified", 3); }},
    {"solve_scene-2d-deg6", "certified v0", 2, [] { return opts("certified", 0); }},
    {"solve_scene-paper002", "double bezier", 3, [] { return opts("double", 0); }},
    {"solve_scene-paper002", "exact", 3, [] { return opts("exact", 0); }},
    {"solve_scene-paper002", "certified", 3, [] { return opts("certified", 0); }},
    // further certified rows go here (see above)
};

void register_solve_scene() {
  group("solve_scene-2d-deg6", "eccd::solve_scene on the 2D degree-6 scene (JSON included)",
        "What `eccd solve` computes, through solve(scene, SolveOptions) then solution_to_json: the pipeline plus "
        "preparation of the "
        "scene (prepare_pair) and the JSON report; rows of the certified interval mode (`--arith certified`) included.",
        "the first row of the table (double)");
  group("solve_scene-paper002", "eccd::solve_scene on paper 002's example (JSON included)", "As above, 3D.",
        "the first row of the table (double Bézier)");
  std::map<std::string, bool> seen;
  for (const SolveRow& r : kSolveSceneRows) {
    std::string grp = r.group, label = r.label;
    bool baseline = !seen[grp];
    seen[grp] = true;
    SolveOptions o = r.options();
    int dim = r.dim;
    row(grp, label, baseline, label.find("exact") != std::string::npos && dim == 3 ? Cost::very_slow : Cost::slow,
        "solve_scene, arith " + o.arith.name() +
            (dim == 2 ? ", variant " + std::to_string(int(o.variant)) : ", method " + o.method_name()),
        [grp, label, o, dim](benchmark::State& st) {
          const Scene& sc = dim == 2 ? s2d_deg6.get().scene : s3d_paper002.get().scene;
          timed(
              st, grp + "/" + label, [&] { return solution_to_json(solve(sc, o)); },
              [](const json& j) {
                json out{{"collides", j["collides"]},
                         {"time_ms_inside", j["time_ms"]},
                         {"contacts", j["contacts"].is_array() ? j["contacts"].size() : 0},
                         {"intervals", j["intervals"].is_array() ? j["intervals"].size() : 0}};
                for (const char* k : {"escalated", "decided_in", "escalation_reason", "certified"})
                  if (j.contains(k)) out[k] = j[k];
                return out;
              });
        });
  }
}

}  // namespace eccd_bench::groups

// The certified mode's own target: its median cost against the
// double pipeline over the degree-4 generated sets of the corpus. One group per
// set; per scene a row `SCENE double` (what `eccd solve` runs by default: 2D
// double Bernstein CD-DISC, 3D double Bézier) and a row `SCENE certified`
// (`--arith certified`, through solve_scene). The report takes the per-scene
// ratio certified / double and its median over the set
// (bench/perf_report/targets.py, SET_TARGETS).
#include "bench/groups.hpp"

namespace eccd_bench::groups {

void register_certified_sets() {
  struct Set {
    const char* id;
    const char* title;
    std::vector<const char*> dirs;
    const char* prefix;
  };
  const Set sets[] = {
      {"certified-set-2d-deg4",
       "certified mode against double on the degree-4 2D generated set",
       {"cases/generated/2d"},
       "2d-deg4-"},
      {"certified-set-3d-deg4",
       "certified mode against double on the degree-4 3D generated set",
       {"cases/generated/3d-euler", "cases/generated/3d-affine"},
       "3d-deg4-"},
  };
  for (const Set& set : sets) {
    std::vector<std::string> files;
    for (const char* d : set.dirs)
      for (const auto& e : std::filesystem::directory_iterator(src(d)))
        if (e.path().extension() == ".json" && e.path().filename().string().rfind(set.prefix, 0) == 0)
          files.push_back(std::string(d) + "/" + e.path().filename().string());
    std::sort(files.begin(), files.end());
    group(
        set.id, set.title,
        "Per scene of the set (every scene of `cases/` whose name starts with the set's prefix), `eccd::solve_scene` "
        "with --arith double (2D: CD-DISC with Δ in Bernstein form; 3D: the Bézier method) and with --arith certified "
        "(intervals of doubles, escalating to MPFI and then exact where a sign is uncertain). The report gives each "
        "scene's ratio certified / double and their median.",
        "the certified mode's cost target: median cost of the certified mode at most 3x the double pipeline");
    bool first = true;
    for (const std::string& rel : files) {
      std::string name = std::filesystem::path(rel).stem().string();
      auto sc = std::make_shared<Lazy<Scene>>([rel] { return read_scene_file(src(rel)); });
      for (const char* arith : {"double", "certified"}) {
        SolveOptions o = opts(arith, 0);
        bool is_double = std::string(arith) == "double";
        row(set.id, name + " " + arith, first && is_double, is_double ? Cost::slow : Cost::very_slow,
            std::string("solve_scene, arith ") + arith + ", " + rel,
            [key = std::string(set.id) + "/" + name + " " + arith, sc, o](benchmark::State& st) {
              timed(
                  st, key, [&] { return solution_to_json(solve(sc->get(), o)); },
                  [](const json& j) {
                    json r{{"collides", j["collides"]},
                           {"time_ms_inside", j["time_ms"]},
                           {"contacts", j["contacts"].is_array() ? j["contacts"].size() : 0},
                           {"intervals", j["intervals"].is_array() ? j["intervals"].size() : 0}};
                    for (const char* k : {"escalated", "decided_in", "escalation_reason"})
                      if (j.contains(k)) r[k] = j[k];
                    return r;
                  });
            });
        first = false;
      }
    }
  }
}

}  // namespace eccd_bench::groups

// The certified ladder's cost guarantee (certified/ladder.hpp,
// "Cost guarantee"): certified against exact on the same scene, over a
// sample of short overlaps, near misses and grazes (the generator's families
// near-miss, overlap and graze at gap / depth 1e-3 ... 1e-12, 2D degrees 2, 4,
// 6 and 3D degrees 2, 4; the short-overlap cases, cases/short-overlap) and the corpus
// scenes where an MPFI rung without a budget costs more than exact. Per scene a row
// `SCENE exact` and a row `SCENE certified`, both through solve_scene; the
// report gives the ratio certified / exact per scene, its median, and the
// ratio to the guarantee's bound exact + 2 x (interval rung).
#include "bench/groups.hpp"

namespace eccd_bench::groups {

void register_certified_cost() {
  std::vector<std::pair<std::string, std::shared_ptr<Lazy<Scene>>>> scenes;
  auto file = [&](const std::string& rel) {
    scenes.push_back({std::filesystem::path(rel).stem().string(),
                      std::make_shared<Lazy<Scene>>([rel] { return read_scene_file(src(rel)); })});
  };
  auto generated = [&](int dim, int degree, const char* family, const char* motion, int e) {
    GeneratorSpec g;
    g.dim = dim;
    g.degree = degree;
    g.family = family;
    g.motion = motion;
    g.d_exponent = e;
    g.seed = 1800 + 100 * dim + 10 * degree + e;
    GeneratedScene gs = generate_scene(g);
    std::string text = gs.doc.dump();
    scenes.push_back(
        {gs.name, std::make_shared<Lazy<Scene>>([text, name = gs.name] { return parse_scene(text, name); })});
  };
  for (const auto& e : std::filesystem::directory_iterator(src("cases/short-overlap")))
    if (e.path().extension() == ".json") file("cases/short-overlap/" + e.path().filename().string());
  // The corpus scenes where the MPFI rung was slower than exact before the budgets (reports/performance.md).
  for (const char* rel : {"cases/generated/2d/2d-deg4-colliding-kinematic-572211152701880.json",
                          "cases/generated/2d/2d-deg6-near-miss-1e-10-kinematic-3150273877033932.json",
                          "cases/generated/3d-affine/3d-deg2-colliding-affine-2295206434708192.json",
                          "cases/generated/3d-affine/3d-deg3-colliding-affine-8679402440173936.json"})
    if (std::filesystem::exists(src(rel))) file(rel);
  for (int e : {3, 6, 9, 12}) {
    for (int deg : {2, 4, 6}) generated(2, deg, "near-miss", "kinematic", e);
    for (int deg : {2, 4}) generated(3, deg, "near-miss", "euler", e);
    for (int dim : {2, 3}) generated(dim, 1, "overlap", "translation", e);
  }
  for (int dim : {2, 3}) generated(dim, 1, "graze", "translation", 0);
  std::sort(scenes.begin(), scenes.end());
  const char* grp = "certified-cost";
  group(
      grp, "the certified ladder against exact on short overlaps, near misses and grazes",
      "Per scene, `eccd::solve_scene` with --arith exact and with --arith certified (the ladder with its budgets: "
      "certified/ladder.hpp, \"Cost guarantee\"). The report gives each scene's ratio certified / exact, their median, "
      "and certified / (exact + 2 x the interval rung's time), the guarantee's bound (at most 1 up to a constant).",
      "the ladder's cost guarantee: the certified ladder never costs much more than exact (guarantee: exact + 2 x the "
      "interval rung + c)");
  bool first = true;
  for (const auto& [name, sc] : scenes) {
    for (const char* arith : {"exact", "certified"}) {
      SolveOptions o = opts(arith, 0);
      std::string key = std::string(grp) + "/" + name + " " + arith;
      row(grp, name + " " + arith, first, Cost::very_slow, std::string("solve_scene, arith ") + arith,
          [key, sc = sc, o](benchmark::State& st) {
            timed(
                st, key, [&] { return solution_to_json(solve(sc->get(), o)); },
                [](const json& j) {
                  json r{{"collides", j["collides"]},
                         {"time_ms_inside", j["time_ms"]},
                         {"intervals", j["intervals"].is_array() ? j["intervals"].size() : 0}};
                  if (j.contains("decided_in")) {
                    r["decided_in"] = j["decided_in"];
                    if (j.contains("escalation_reason")) r["escalation_reason"] = j["escalation_reason"];
                    // The interval rung's time (the guarantee's I): its escalation, or the whole run when it decided.
                    double interval_ms = j["time_ms"].get<double>();
                    for (const auto& e : j["escalations"])
                      if (e["rung"] == "interval") interval_ms = e.value("spent_ms", 0.0);
                    r["interval_ms"] = interval_ms;
                  }
                  return r;
                });
          });
      first = false;
    }
  }
}

}  // namespace eccd_bench::groups

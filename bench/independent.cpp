// eccd::solve on the scenes of cases/independent, four arithmetics (bench/independent.hpp).
#include "independent.hpp"

#include "api/solve.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

namespace eccd_bench {

using namespace eccd;
using json = nlohmann::json;

void register_independent_rotating(const IndependentHooks& h);

void register_independent(const IndependentHooks& h) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases/independent"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) {
    const std::string name = std::filesystem::path(f).stem().string();
    const std::string grp = "independent-" + name;
    h.group(grp, "Independent motions, cases/independent/" + name + ".json: eccd::solve in four arithmetics",
            "eccd::solve(scene, SolveOptions) on the scene file's independent motions (paper 001 section 4): double "
            "and mpfr:128 "
            "run the subdivision of floating/independent_ccd.hpp (both under the run's default budget), exact and "
            "certified the "
            "proofs of certified/independent_proof.hpp (exact: exact/independent_balls.hpp for two balls or discs on "
            "lines). "
            "Baseline double: the mpfr row's ratio is MPFR / double on the same scene (target: at most 20).",
            "the mpfr:128 row's ratio (target <= 20) and the exact and certified times (target <= 5 s)");
    auto scene = std::make_shared<std::pair<std::once_flag, Scene>>();
    for (const char* a : {"double", "mpfr:128", "exact", "certified"}) {
      SolveOptions o;
      o.arith = parse_arithmetic(a);
      const std::string label = a, key = grp + "/" + label;
      h.row(grp, label, label == "double", true, "eccd::solve, arith " + o.arith.name(),
            [f, o, key, scene, h](benchmark::State& st) {
              std::call_once(scene->first, [&] { scene->second = read_scene(f); });
              std::optional<Solution> last;
              for (auto _ : st) {
                Solution s = solve(scene->second, o);
                benchmark::DoNotOptimize(s);
                last.emplace(std::move(s));
              }
              if (!last) return;
              json r{{"collides", last->answer.collides},
                     {"s_intervals", last->answer.s_intervals.size()},
                     {"t_intervals", last->answer.t_intervals.size()},
                     {"undecided", last->answer.undecided.size()},
                     {"certified", last->certified}};
              h.result(key, r);
            });
    }
  }
  register_independent_rotating(h);
}

// Generated pairs of ellipsoids turning by degree-2 Euler parameters (eccd generate --dims 3 --degrees 2
// --motions euler --families colliding --count 4 --seed 7, made independent: A's parameter s, B's t).
void register_independent_rotating(const IndependentHooks& h) {
  const std::string grp = "independent-rotating";
  h.group(grp,
          "Independent motions, generated rotating ellipsoid pairs (degree-2 Euler parameters): exact and certified "
          "per scene",
          "The four colliding scenes of `eccd generate --dims 3 --degrees 2 --motions euler --families colliding "
          "--count 4 --seed 7` "
          "with \"parameters\": \"independent\" (A moves with s, B with t); eccd::solve in exact and certified "
          "arithmetic, one row "
          "per scene (target: at most 5 s each). Baseline: double on all four.",
          "the exact and certified rows (target <= 5 s each)");
  auto scenes = std::make_shared<std::pair<std::once_flag, std::vector<Scene>>>();
  auto load = [scenes] {
    std::call_once(scenes->first, [&] {
      GeneratorSpec c;
      c.dim = 3;
      c.degree = 2;
      c.family = "colliding";
      c.motion = "euler";
      for (int k = 0; k < 4; ++k) {
        GeneratorSpec sp = c;
        sp.seed = scene_seed(7, c, k);
        nlohmann::ordered_json doc = generate_scene(sp).doc;
        doc["parameters"] = "independent";
        doc.erase("answer");
        scenes->second.push_back(scene_from_text(doc.dump(), "rotating-" + std::to_string(k + 1)));
      }
    });
    return &scenes->second;
  };
  for (int k = -1; k < 4; ++k)
    for (const char* a : {"double", "exact", "certified"}) {
      if ((k < 0) != (std::string(a) == "double")) continue;
      SolveOptions o;
      o.arith = parse_arithmetic(a);
      const std::string label = k < 0 ? std::string("double (all four)") : std::string(a) + " " + std::to_string(k + 1);
      const std::string key = grp + "/" + label;
      h.row(grp, label, k < 0, true, "eccd::solve, arith " + o.arith.name(),
            [o, k, key, load, h](benchmark::State& st) {
              const std::vector<Scene>& all = *load();
              std::optional<Solution> last;
              for (auto _ : st)
                for (int i = 0; i < 4; ++i) {
                  if (k >= 0 && i != k) continue;
                  Solution s = solve(all[std::size_t(i)], o);
                  benchmark::DoNotOptimize(s);
                  last.emplace(std::move(s));
                }
              if (!last || k < 0) return;
              h.result(key, json{{"collides", last->answer.collides},
                                 {"undecided", last->answer.undecided.size()},
                                 {"certified", last->certified}});
            });
    }
}

}  // namespace eccd_bench

// eccd::solve on the scenes of cases/independent, four arithmetics (bench/independent.hpp).
#include "independent.hpp"

#include "api/solve.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

namespace eccd_bench {

using namespace eccd;
using json = nlohmann::json;

void register_independent(const IndependentHooks& h) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases/independent"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) {
    const std::string name = std::filesystem::path(f).stem().string();
    const std::string grp = "independent-" + name;
    h.group(grp, "Independent motions, cases/independent/" + name + ".json: eccd::solve in four arithmetics",
            "eccd::solve(scene, SolveOptions) on the scene file's independent motions (paper 001 section 4): double and mpfr:128 "
            "run the subdivision of floating/independent_ccd.hpp (both under the run's default budget), exact and certified the "
            "proofs of certified/independent_proof.hpp (exact: exact/independent_balls.hpp for two balls or discs on lines). "
            "Baseline double: the mpfr row's ratio is MPFR / double on the same scene (issue 33: at most 20).",
            "the mpfr:128 row's ratio (target <= 20) and the exact and certified times (target <= 5 s)");
    auto scene = std::make_shared<std::pair<std::once_flag, Scene>>();
    for (const char* a : {"double", "mpfr:128", "exact", "certified"}) {
      SolveOptions o;
      o.arith = parse_arithmetic(a);
      const std::string label = a, key = grp + "/" + label;
      h.row(grp, label, label == "double", true, "eccd::solve, arith " + o.arith.name(), [f, o, key, scene, h](benchmark::State& st) {
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
}

}  // namespace eccd_bench

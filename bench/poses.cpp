// Benchmark group "poses": eccd::animate_poses
// (api/pose_check.hpp), the papers' per-pose mode, per pair-pose, in double
// and certified, on paper 000's Table 1 animations (make_repro.py table1
// --seed 1, 0.1 and 1 rad per key, 1001 keys), Table 2's orbit
// (make_repro.py table2 --radius 5.49, 1001 keys) and the boxers (001 section
// 5 in spirit, 11 keys, 576 pairs). One iteration runs the whole animation on
// one thread; the per pair-pose cost is the median divided by the result's
// "pair_poses" (poses × checked pairs, every stage included: bounding spheres,
// kept planes, static tests, plane construction), and "past_bounding" pair-poses
// reached stages 2-3. "plane_share" is the share of those settled by the kept
// plane (000 section 4). Baseline: double on Table 1 at 0.1 rad.
#include "bench/poses.hpp"

#include "api/pose_check.hpp"
#include "io/animation_reader.hpp"

#include <memory>
#include <mutex>

namespace eccd_bench {

void register_poses(const PosesBenchHooks& h) {
  using namespace eccd;
  h.group(
      "poses", "Per-pose mode (eccd animate --poses): per pair-pose, the static test with the kept plane",
      "eccd::animate_poses(animation, arith, threads 1) on 000 Table 1 (bench/data/table1-{0.1,1}-1000.anim.json: "
      "make_repro.py table1 --rate R --frames 1000 --seed 1), 000 Table 2 (bench/data/table2-main-1000.anim.json: "
      "make_repro.py table2 --frames 1000 --radius 5.49) and the boxers (bench/data/boxers-10.anim.json, 11 keys, "
      "576 pairs). One iteration is the whole animation; per pair-pose = median / pair_poses (every stage: bounding "
      "spheres, the kept plane's check, the static test, building planes). plane_share: pair-poses past the bounding "
      "spheres settled by the kept plane. Baseline: double, Table 1 at 0.1 rad.",
      "speed target: at most 0.5 µs per pair-pose in double and 1 µs certified; 000 Tables 1-2: 2.1-5 µs per frame "
      "(one pair, static pose per frame)");
  struct R {
    const char* label;
    const char* file;
    const char* arith;
    bool planes, baseline;
  };
  static const R rows[] = {
      {"table1 0.1 rad, double", "bench/data/table1-0.1-1000.anim.json", "double", true, true},
      {"table1 0.1 rad, double, no planes", "bench/data/table1-0.1-1000.anim.json", "double", false, false},
      {"table1 0.1 rad, certified", "bench/data/table1-0.1-1000.anim.json", "certified", true, false},
      {"table1 1 rad, double", "bench/data/table1-1-1000.anim.json", "double", true, false},
      {"table1 1 rad, certified", "bench/data/table1-1-1000.anim.json", "certified", true, false},
      {"table2 main orbit, double", "bench/data/table2-main-1000.anim.json", "double", true, false},
      {"table2 main orbit, certified", "bench/data/table2-main-1000.anim.json", "certified", true, false},
      {"boxers, double", "bench/data/boxers-10.anim.json", "double", true, false},
      {"boxers, certified", "bench/data/boxers-10.anim.json", "certified", true, false},
  };
  for (const R& r : rows) {
    const std::string key = std::string("poses/") + r.label, path = h.source_dir + "/" + r.file;
    AnimateOptions o;
    o.solve.arith = parse_arithmetic(r.arith);
    o.threads = 1;
    o.planes = r.planes;
    auto anim = std::make_shared<std::pair<std::once_flag, std::unique_ptr<Animation>>>();
    auto result = h.result;
    h.row("poses", r.label, r.baseline,
          std::string("eccd::animate_poses, arith ") + r.arith + (r.planes ? "" : ", planes off") + ", threads 1, " +
              r.file,
          [key, path, o, anim, result](benchmark::State& st) {
            std::call_once(anim->first, [&] { anim->second = std::make_unique<Animation>(read_animation(path)); });
            std::unique_ptr<PosesResult> last;
            for (auto _ : st) {
              auto res = std::make_unique<PosesResult>(animate_poses(*anim->second, o));
              benchmark::DoNotOptimize(res);
              last = std::move(res);
            }
            if (!last) return;
            const PosesResult& a = *last;
            const std::size_t past = a.separating_plane + a.static_test;
            result(key, nlohmann::json{{"poses", a.poses},
                                       {"pairs_per_pose", a.pairs_per_pose},
                                       {"pair_poses", a.poses * a.pairs_per_pose},
                                       {"past_bounding", past},
                                       {"separating_plane", a.separating_plane},
                                       {"static_test", a.static_test},
                                       {"planes_built", a.planes_built},
                                       {"plane_share", past ? double(a.separating_plane) / double(past) : 0.0},
                                       {"events", a.events.size()},
                                       {"undecided", a.undecided.size()}});
          });
  }
}

}  // namespace eccd_bench

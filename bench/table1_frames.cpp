// Paper 000's Table 1 set-up as an animation, per frame, through eccd::animate:
// two ellipsoids (semi-axes 3, 3, 5, centres 8 apart) turning by 0.1 rad per
// frame over 1000 frames (bench/data/table1-0.1-1000.anim.json, made by
// make_repro.py table1 --rate 0.1 --frames 1000 --seed 1). Each frame runs the
// bounding spheres, the separating plane kept from the frame before (000
// section 4), and the continuous test when the plane does not settle it. One
// iteration animates all frames with one thread (process CPU time: the
// pair-frames run on a worker thread); the per-frame figure is the median
// divided by the frame count. 000 Table 1 reports 2.47 µs per frame for a
// static test at one pose per frame; this row does the continuous test over
// the whole frame, so the two measure different questions (the per-pose mode,
// group `poses`, is 000's own).
#include "bench/speed_targets.hpp"

#include "api/animate.hpp"
#include "io/animation_reader.hpp"

#include <memory>
#include <mutex>
#include <string>

namespace eccd_bench {

void register_table1_frames() {
  using namespace eccd;
  const std::string grp = "speed-table1-frames";
  const std::string rel = "bench/data/table1-0.1-1000.anim.json";
  add_group(
      grp, "Paper 000's Table 1 pair as an animation, per frame (eccd::animate, kept planes)",
      "eccd::animate(" + rel +
          ", arith, threads 1): 1000 frames of two ellipsoids turning 0.1 rad per frame; per "
          "frame the bounding spheres, the kept plane (000 section 4) and, where the plane fails, the continuous test. "
          "One iteration is the whole animation; per frame = median / frames. Baseline: double (guarded).",
      "target: at most 25 µs per frame in double; 000 Table 1: 2.47 µs per frame (a static test at one pose per "
      "frame, Pentium 4)");
  for (const char* a : {"double", "certified"}) {
    const bool base = std::string(a) == "double";
    const std::string label = std::string("eccd::animate ") + a + (base ? " (baseline)" : ""), key = grp + "/" + label;
    auto anim = std::make_shared<std::pair<std::once_flag, std::unique_ptr<Animation>>>();
    const std::string path = source_path(rel);
    add_row(
        grp, label, base, base ? 1 : 3, std::string("eccd::animate(table1 0.1 rad, ") + a + "), threads 1",
        [key, path, anim, a](benchmark::State& st) {
          std::call_once(anim->first, [&] { anim->second = std::make_unique<Animation>(read_animation(path)); });
          AnimateOptions o;
          o.solve.arith = parse_arithmetic(a);
          o.threads = 1;
          std::unique_ptr<AnimationResult> last;
          for (auto _ : st) {
            auto r = std::make_unique<AnimationResult>(animate(*anim->second, o));
            benchmark::DoNotOptimize(r);
            last = std::move(r);
          }
          if (!last) return;
          const AnimationResult& r = *last;
          record_result(key, nlohmann::json{{"frames", r.per_frame.size()},
                                            {"pairs_per_frame", r.pairs_per_frame},
                                            {"bounding_volumes", r.bounding_volumes},
                                            {"separating_plane", r.separating_plane},
                                            {"continuous_test", r.continuous_test},
                                            {"events", r.events.size()},
                                            {"undecided", r.undecided.size()}});
        },
        true);
  }
}

}  // namespace eccd_bench

// Reproduction (c) of the animation benchmarks (paper 001 section 5 in spirit): the boxers,
// two figures of 24 ellipsoids (make_repro.py boxers), 576 pairs per frame,
// through eccd::animate (api/animate.hpp: bounding spheres, the kept plane,
// the continuous test), one thread. The input is bench/data/boxers-10.anim.json
// (`python3 cases/animations/make_repro.py boxers --frames 10`): keys 0..10,
// so frames 0..9, the same as the first ten frames of the report's 1000-frame
// animation (a key's pose depends on its index only; the arms' period is 20
// keys, the legs' 40). One iteration animates all ten frames; the report
// divides by "frames" in the result. Baseline: double. CPU time of the whole
// process (animate's stages 2-3 run on a worker thread, even with threads 1).
#include "bench/groups.hpp"

namespace eccd_bench::groups {

void register_animation() {
  const char* rel = "bench/data/boxers-10.anim.json";
  group(
      "animate-boxers", "Animation of the boxers (001 section 5 in spirit), 576 pairs per frame, frames 0-9",
      "eccd::animate(animation, arith, threads 1) on bench/data/boxers-10.anim.json (make_repro.py boxers --frames 10: "
      "two figures of 24 ellipsoids, pairs between the groups, frames 0 to 9 of the report's animation): per frame "
      "the bounding spheres of the swept volumes, the separating plane kept from the previous frame, then the "
      "continuous test of the surviving pairs (first contact). One iteration is the ten frames; the per-frame cost is "
      "the median divided by 10 (CPU time of the process: the pair-frames run on a worker thread). Baseline: double. "
      "The row without planes shows what the kept planes save.",
      "001 section 5: 3.4 ms per frame (1000 frames, 576 pairs, 3 GHz Pentium IV, double)");
  static Lazy<Animation> anim([rel] { return read_animation(src(rel)); });
  struct R {
    const char* label;
    const char* arith;
    bool planes, baseline;
    Cost cost;
  };
  for (const R& r : {R{"double, 10 frames (baseline)", "double", true, true, Cost::slow},
                     R{"double without planes, 10 frames", "double", false, false, Cost::slow},
                     R{"certified, 10 frames", "certified", true, false, Cost::heavy}}) {
    const std::string label = r.label, key = "animate-boxers/" + label;
    AnimateOptions o;
    o.solve.arith = parse_arithmetic(r.arith);
    o.threads = 1;
    o.planes = r.planes;
    row(
        "animate-boxers", label, r.baseline, r.cost,
        std::string("eccd::animate, arith ") + r.arith + (r.planes ? "" : ", planes off") + ", threads 1, " + rel,
        [key, o](benchmark::State& st) {
          timed(
              st, key, [&] { return animate(anim.get(), o); },
              [](const AnimationResult& a) {
                return json{{"frames", a.per_frame.size()},           {"pairs_per_frame", a.pairs_per_frame},
                            {"bounding_volumes", a.bounding_volumes}, {"separating_plane", a.separating_plane},
                            {"continuous_test", a.continuous_test},   {"events", a.events.size()},
                            {"undecided", a.undecided.size()}};
              });
        },
        true);  // process CPU time: animate runs its pair-frames on a worker std::thread even with threads 1
  }
}

}  // namespace eccd_bench::groups

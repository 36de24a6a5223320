// The speed targets on the path users run (scene ->
// eccd::solve / eccd::animate, or the static test from two poses), each group
// with FCL beside it where FCL has a counterpart, all in the same process as
// the rest of eccd_bench (bench/speed_targets.hpp: registered through its
// registry). Groups:
//   speed-deg1      one degree-1 translating 3D pair (the scene of
//                   ccd3d-deg1-translation), eccd::solve guarded double from the
//                   scene (baseline; target 30 µs), certified, and FCL's
//                   continuous test with 1000 samples.
//   speed-static    the 3D static test from two poses: eccd::static_status one
//                   pair (baseline; target 40 ns), static_status_batch on 64
//                   pairs per iteration for each instruction set the CPU runs
//                   (the label names it; target 15 ns per pair = 960 ns per
//                   iteration; never slower than single pairs), and
//                   fcl::collide on the same pairs.
//   speed-paper002  paper 002's example from its scene file: eccd::solve
//                   guarded double (baseline; target 0.5 ms) and exact (20 ms).
//   speed-frame     per pair-frame of 000 Table 1's pair (rotations of 0.05
//                   rad per frame): the kept-plane check in double (target
//                   2 µs) from the scene (plane_separates_on_frame) and as
//                   animate's stage 2 runs it first (KeptPlaneCheck, from
//                   numbers prepared once per animation, on the Table 1
//                   animation at 0.1 rad), against the continuous test
//                   (baseline); and the
//                   boxers (576 pairs): eccd::animate double (1 ms per frame)
//                   and certified (2 ms), ten frames per iteration.
#include "bench/speed_targets.hpp"

#include "api/animate.hpp"
#include "api/separate.hpp"
#include "api/solve.hpp"
#include "api/static_filter_simd.hpp"
#include "api/static_status.hpp"
#include "bench/fcl_side.hpp"
#include "compare/fcl_engine.hpp"
#include "io/animation_reader.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

using namespace eccd;
using json = nlohmann::json;

namespace eccd_bench {
namespace {

template <class F, class S>
void timed(benchmark::State& st, const std::string& key, F f, S summarise) {
  using R = decltype(f());
  std::unique_ptr<R> last;
  for (auto _ : st) {
    R r = f();
    benchmark::DoNotOptimize(r);
    last = std::make_unique<R>(std::move(r));
  }
  if (last) record_result(key, summarise(*last));
}

json answer_summary(const Solution& s) {
  json j{{"collides", s.answer.collides},
         {"intervals", s.answer.intervals.size()},
         {"undecided", s.answer.undecided.size()}};
  if (s.answer.first_contact) j["first_contact"] = s.answer.first_contact->approx.substr(0, 10);
  return j;
}

const char* kDeg1Scene = R"({"format": "ellipse-ccd-scene/1", "name": "deg1-translating-pair", "dim": 3,
  "a": {"shape": {"semi_axes": ["1", "2", "3"]}, "motion": {"type": "euler", "e": ["1", "0", "0", "0"], "translation": [["-4", "8"], "0", "0"]}},
  "b": {"shape": {"semi_axes": ["2", "1", "1"]}, "motion": {"type": "euler", "e": ["1", "1/3", "0", "1/5"], "translation": [["4", "-8"], ["1/2", "0"], "0"]}}})";

void register_deg1() {
  const std::string grp = "speed-deg1";
  add_group(
      grp, "Speed target: one degree-1 translating 3D pair through eccd::solve, FCL beside",
      "eccd::solve(scene) from the scene of ccd3d-deg1-translation (two ellipsoids translating linearly, B turned by a "
      "fixed rotation, colliding on about [0.32, 0.67]): guarded double (the default of `eccd solve`; baseline) and "
      "certified; FCL's continuous test with 1000 samples (compare/fcl_engine fcl_ccd, first contact only).",
      "speed target: guarded double at most 30 µs (×3.4 faster than FCL's 1000 samples)");
  static Scene scene = scene_from_text(kDeg1Scene, "deg1-translating-pair");
  for (const char* a : {"double", "certified"}) {
    const std::string label =
        std::string("eccd::solve ") + a + (std::string(a) == "double" ? " guarded (baseline)" : "");
    add_row(grp, label, std::string(a) == "double", 1, std::string("eccd::solve(scene, ") + a + ")",
            [grp, label, a](benchmark::State& st) {
              SolveOptions o;
              o.arith = parse_arithmetic(a);
              timed(
                  st, grp + "/" + label, [&] { return solve(scene, o); }, answer_summary);
            });
  }
  add_row(grp, "FCL continuous, 1000 samples", false, 1, "fcl_ccd(scene, 1000): fcl::continuousCollide, CCDC_NAIVE",
          [grp](benchmark::State& st) {
            const std::string why = fcl_bench_unavailable(), bad = why.empty() ? fcl_ccd_inexpressible(scene) : "";
            if (!why.empty() || !bad.empty()) {
              st.SkipWithError((why + bad).c_str());
              return;
            }
            timed(
                st, grp + "/FCL continuous, 1000 samples", [&] { return fcl_ccd(scene, 1000); },
                [](const Answer& a) {
                  return json{{"collides", a.collides}};
                });
          });
}

// 1024 random pairs from two poses: semi-axes in [1, 3], rotations from random unit quaternions, centres of b
// up to 7 from a's (about half the pairs overlap).
struct StaticPairs {
  std::vector<Ellipsoid> a, b;
  std::vector<FclBody> fa, fb;
};
constexpr int kPairs = 1024;

const StaticPairs& static_pairs() {
  static const StaticPairs s = [] {
    StaticPairs p;
    std::mt19937_64 rng(360036);
    std::uniform_real_distribution<double> ax(1.0, 3.0), nrm(-1.0, 1.0), dist(0.0, 7.0);
    auto body = [&](double dx) {
      double q[4], n = 0;
      for (double& x : q) {
        x = nrm(rng);
        n += x * x;
      }
      n = std::sqrt(n);
      for (double& x : q) x /= n;
      const double w = q[0], x = q[1], y = q[2], z = q[3];
      const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                              {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                              {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
      Ellipsoid e;
      FclBody f;
      e.semi_axes = {ax(rng), ax(rng), ax(rng)};
      const double c[3] = {dx * nrm(rng), dx * nrm(rng), dx * nrm(rng)};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          e.pose[i][j] = R[i][j];
          f.rotation[i][j] = R[i][j];
        }
        e.pose[i][3] = c[i];
        f.centre[i] = c[i];
        f.radii[i] = e.semi_axes[i];
      }
      e.pose[3] = {0, 0, 0, 1};
      return std::make_pair(e, f);
    };
    for (int i = 0; i < kPairs; ++i) {
      auto [ea, fa] = body(0.0);
      auto [eb, fb] = body(dist(rng) / std::sqrt(3.0));
      p.a.push_back(ea);
      p.b.push_back(eb);
      p.fa.push_back(fa);
      p.fb.push_back(fb);
    }
    return p;
  }();
  return s;
}

json status_counts(const std::vector<Status>& v) {
  json j = json::object();
  for (Status s : v) j[to_string(s)] = j.value(to_string(s), 0) + 1;
  return j;
}

void register_static() {
  const std::string grp = "speed-static";
  add_group(
      grp, "Speed target: the 3D static test from two poses, one pair and batched per instruction set, FCL beside",
      "1024 random ellipsoid pairs given as semi-axes and poses (the API's input). eccd::static_status one pair per "
      "iteration (baseline); eccd::static_status_batch on 64 pairs per iteration with the batch's instruction set "
      "limited to the one the label names (api/static_filter_simd.hpp: AVX-512 lanes, AVX2 lanes on explicit "
      "4-lane vectors, or pair by pair); a row whose instruction set this CPU lacks is skipped. fcl::collide on the "
      "same pairs (GJK libccd, default request; bench/fcl_side.hpp), one pair per iteration. Per pair: the batch "
      "rows' median / 64.",
      "speed target: at most 40 ns one pair, 15 ns per pair batched (960 ns per iteration); the batch never slower "
      "than "
      "single pairs (64 x the baseline)");
  add_row(grp, "static_status one pair (baseline)", true, 0, "eccd::static_status(a, b), double",
          [grp](benchmark::State& st) {
            const StaticPairs& s = static_pairs();
            int i = 0;
            timed(
                st, grp + "/static_status one pair (baseline)",
                [&] {
                  i = (i + 1) & (kPairs - 1);
                  return static_status(s.a[i], s.b[i]);
                },
                [&](Status) {
                  std::vector<Status> v;
                  for (int k = 0; k < kPairs; ++k) v.push_back(static_status(s.a[k], s.b[k]));
                  return status_counts(v);
                });
          });
  for (simd::Isa isa : {simd::Isa::avx512, simd::Isa::avx2, simd::Isa::none}) {
    const std::string label = std::string("static_status_batch, 64 pairs, ") + simd::to_string(isa);
    add_row(grp, label, false, 0,
            "eccd::static_status_batch over 64 pairs, instruction set " + std::string(simd::to_string(isa)),
            [grp, label, isa](benchmark::State& st) {
              if (simd::cpu_isa() < isa) {
                st.SkipWithError((std::string("this CPU does not run ") + simd::to_string(isa)).c_str());
                return;
              }
              simd::set_static_batch_isa_limit(isa);
              const StaticPairs& s = static_pairs();
              std::size_t i = 0;
              std::array<Status, 64> out;
              timed(
                  st, grp + "/" + label,
                  [&] {
                    i = (i + 64) & (kPairs - 1);
                    static_status_batch(std::span<const Ellipsoid>(s.a).subspan(i, 64),
                                        std::span<const Ellipsoid>(s.b).subspan(i, 64), std::span<Status>(out));
                    return out[0];
                  },
                  [&](Status) {
                    std::vector<Status> v(kPairs);
                    static_status_batch(std::span<const Ellipsoid>(s.a), std::span<const Ellipsoid>(s.b),
                                        std::span<Status>(v));
                    json j = status_counts(v);
                    j["isa"] = simd::to_string(simd::static_batch_isa());
                    return j;
                  });
              simd::set_static_batch_isa_limit(simd::Isa::avx512);
            });
  }
  add_row(grp, "FCL collide one pair", false, 0, "fcl::collide(ellipsoid, ellipsoid), GJK libccd, default request",
          [grp](benchmark::State& st) {
            const std::string why = fcl_bench_unavailable();
            if (!why.empty()) {
              st.SkipWithError(why.c_str());
              return;
            }
            const StaticPairs& s = static_pairs();
            std::unique_ptr<PreparedFclPairs> p = prepare_fcl_pairs(s.fa, s.fb, false);
            std::size_t i = 0;
            timed(
                st, grp + "/FCL collide one pair",
                [&] {
                  i = (i + 1) & (kPairs - 1);
                  return p->collide(i);
                },
                [&](bool) {
                  int n = 0;
                  for (std::size_t k = 0; k < kPairs; ++k) n += p->collide(k);
                  return json{{"colliding", n}};
                });
          });
}

void register_paper002() {
  const std::string grp = "speed-paper002";
  const std::string rel = "cases/paper002/example.json";
  add_group(
      grp, "Speed target: paper 002's example from its scene file through eccd::solve",
      "eccd::read_scene(" + rel +
          ") once, then eccd::solve(scene) per iteration: guarded double, rounded input (the "
          "default of `eccd solve`; baseline) and exact.",
      "speed target: guarded double at most 0.5 ms, exact at most 20 ms; 001: 3.7 ms for a degree-4 affine pair (3 GHz "
      "Pentium 4)");
  for (const char* a : {"double", "exact"}) {
    const bool base = std::string(a) == "double";
    const std::string label = std::string("eccd::solve ") + a + (base ? " guarded (baseline)" : "");
    add_row(grp, label, base, base ? 1 : 2, std::string("eccd::solve(read scene, ") + a + ")",
            [grp, label, a, rel](benchmark::State& st) {
              static const Scene scene = read_scene(source_path(rel));
              SolveOptions o;
              o.arith = parse_arithmetic(a);
              timed(
                  st, grp + "/" + label, [&] { return solve(scene, o); }, answer_summary);
            });
  }
}

void register_frames() {
  const std::string grp = "speed-frame";
  add_group(
      grp, "Speed target: per pair-frame (000 Table 1's pair, kept plane) and per frame (the boxers, 576 pairs)",
      "000 Table 1's pair-frame as in the plane-check group (semi-axes 3, 3, 5, centres 8 apart, rotations of about "
      "0.1 rad per frame): eccd::solve double guarded (baseline), eccd::plane_separates_on_frame double with the plane "
      "of t = 0 (separate_at exact, once); eccd::animate on bench/data/boxers-10.anim.json (ten frames per iteration, "
      "threads 1, process CPU time; per frame: the median / 10) in double and certified.",
      "speed target: kept-plane check at most 2 µs per pair-frame; boxers at most 1 ms per frame double (10 ms per "
      "iteration), 2 ms certified (20 ms per iteration); 001 section 5: 3.4 ms per frame (3 GHz Pentium 4)");
  static const Scene table1 = scene_from_text(R"({"format": "ellipse-ccd-scene/1", "name": "table1-pair", "dim": 3,
      "a": {"shape": {"semi_axes": ["3", "3", "5"]}, "motion": {"type": "euler", "e": ["1", ["0", "1/20"], "0", "0"], "translation": ["-4", "0", "0"]}},
      "b": {"shape": {"semi_axes": ["3", "3", "5"]}, "motion": {"type": "euler", "e": ["1", "0", ["0", "1/20"], "0"], "translation": ["4", "0", "0"]}}})",
                                              "table1-pair");
  add_row(grp, "Table 1 pair-frame, eccd::solve double (baseline)", true, 1, "eccd::solve(pair-frame, double guarded)",
          [grp](benchmark::State& st) {
            SolveOptions o;
            timed(
                st, grp + "/Table 1 pair-frame, eccd::solve double (baseline)", [&] { return solve(table1, o); },
                answer_summary);
          });
  add_row(grp, "Table 1 pair-frame, kept-plane check double", false, 1,
          "eccd::plane_separates_on_frame(pair-frame, plane, double)", [grp](benchmark::State& st) {
            SolveOptions ex;
            ex.arith = Arithmetic::exact();
            static const Separation sep = separate_at(table1, 0, ex);
            if (!sep.plane) {
              st.SkipWithError("the Table 1 pair is not separate at t = 0");
              return;
            }
            SolveOptions o;
            timed(
                st, grp + "/Table 1 pair-frame, kept-plane check double",
                [&] { return int(plane_separates_on_frame(table1, *sep.plane, o)); },
                [](int r) {
                  return json{{"result", to_string(PlaneCheck(r))}};
                });
          });
  add_row(grp, "Table 1 pair-frame, kept-plane check from prepared poses", false, 1,
          "eccd::KeptPlaneCheck::check (animate's stage 2, intervals from numbers prepared once per animation)",
          [grp](benchmark::State& st) {
            struct Case {
              KeptPlaneCheck::Plane plane;
              std::size_t frame;
            };
            static const Animation anim = read_animation(source_path("bench/data/table1-0.1-1000.anim.json"));
            static const KeptPlaneCheck check(anim);
            static const std::vector<Case> cases = [] {
              std::vector<Case> v;  // the plane animate keeps: separate_at(frame k - 1, τ = 1), checked on frame k
              SolveOptions ex;
              ex.arith = Arithmetic::exact();
              for (std::size_t k = 1; v.size() < 64 && k < anim.frames(); ++k) {
                const Separation sep = separate_at(pair_frame_scene(anim, 0, 1, k - 1), 1, ex);
                if (sep.plane) v.push_back({check.prepare(sep.plane->normal, sep.plane->offset), k});
              }
              return v;
            }();
            if (cases.empty()) {
              st.SkipWithError("no separate frame end in the Table 1 animation");
              return;
            }
            std::size_t i = 0;
            timed(
                st, grp + "/Table 1 pair-frame, kept-plane check from prepared poses",
                [&] {
                  i = (i + 1) % cases.size();
                  return int(check.check(cases[i].plane, 0, 1, cases[i].frame));
                },
                [&](int) {
                  json j = json::object();
                  for (const Case& c : cases) {
                    const FrameSides f = check.check(c.plane, 0, 1, c.frame);
                    const char* name = f == FrameSides::separates ? "separates"
                                       : f == FrameSides::fails   ? "fails"
                                                                  : "unknown";
                    j[name] = j.value(name, 0) + 1;
                  }
                  return j;
                });
          });
  const std::string rel = "bench/data/boxers-10.anim.json";
  for (const char* a : {"double", "certified"}) {
    const std::string label = std::string("boxers, 10 frames, eccd::animate ") + a;
    add_row(
        grp, label, false, std::string(a) == "double" ? 1 : 3,
        std::string("eccd::animate(boxers, ") + a + "), threads 1",
        [grp, label, a, rel](benchmark::State& st) {
          static const Animation anim = read_animation(source_path(rel));
          AnimateOptions o;
          o.solve.arith = parse_arithmetic(a);
          o.threads = 1;
          timed(
              st, grp + "/" + label, [&] { return animate(anim, o); },
              [](const AnimationResult& r) {
                return json{{"events", r.events.size()}, {"undecided", r.undecided.size()}};
              });
        },
        true);
  }
}

}  // namespace

void register_speed_targets() {
  register_deg1();
  register_static();
  register_paper002();
  register_frames();
}

}  // namespace eccd_bench

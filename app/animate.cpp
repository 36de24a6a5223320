// `eccd animate`: every checked pair of an animation file in every frame
// (docs/animation-format.md; api/animate.hpp), in one arithmetic. Prints the
// spec's answer object with --json (format ellipse-ccd-animation-answer/1),
// otherwise a summary table (frames, pairs per frame, pair-frames settled by
// each stage, events, time per frame) and the events. --out FILE writes that
// output to FILE instead of stdout (atomically: nothing is written on error).
// Progress (pair-frames done, time left) on stderr unless --quiet.
// Exit codes (docs/exit-codes.md): 2 bad options or a bad animation file
// (checked before any work), 3 a request the pipeline refuses, 5 a budget.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/option_names.hpp"
#include "app/time_left.hpp"
#include "api/animate.hpp"
#include "api/pose_check.hpp"
#include "io/animation_reader.hpp"
#include "io/scene_reader.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace eccd {

namespace {

struct AnimateArgs {
  std::string path, arith = "exact", shard, out;
  bool json = false, all_intervals = false, quiet = false, no_planes = false, force = false, poses = false;
  int threads = 2;
};

std::string fixed(double x, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

std::string summary_text(const AnimationResult& r) {
  std::ostringstream o;
  o << "animation " << r.animation << " (" << r.file << "), " << r.dim << "D, arithmetic " << r.arithmetic << ", "
    << (r.all_intervals ? "all intervals" : "first contact") << "\n";
  o << "frames " << r.frames
    << (r.shard_count > 1 ? " (this shard: " + std::to_string(r.per_frame.size()) + ")" : std::string())
    << ", pairs per frame " << r.pairs_per_frame << ", separating-plane stage "
    << (r.planes_disabled     ? "off"
        : r.plane_stage_built ? "built"
                              : "not built")
    << "\n\n";
  o << "frame   pairs  bounding  plane  continuous  events  undecided       ms\n";
  for (const auto& f : r.per_frame) {
    char line[160];
    std::snprintf(line, sizeof line, "%5zu  %6zu  %8zu  %5zu  %10zu  %6zu  %9zu  %7.1f\n", f.frame, f.pairs,
                  f.bounding_volumes, f.separating_plane, f.continuous_test, f.events, f.undecided, f.seconds * 1e3);
    o << line;
  }
  const double total = double(r.bounding_volumes + r.separating_plane + r.continuous_test);
  auto pct = [&](std::size_t x) { return total > 0 ? fixed(100.0 * double(x) / total, 1) + " %" : std::string("-"); };
  o << "\nstages: bounding volumes " << r.bounding_volumes << " (" << pct(r.bounding_volumes) << "), separating plane "
    << r.separating_plane << " (" << pct(r.separating_plane) << "), continuous test " << r.continuous_test << " ("
    << pct(r.continuous_test) << ")\n";
  o << "events " << r.events.size() << ", undecided " << r.undecided.size() << ", " << fixed(r.seconds, 3) << " s ("
    << (r.per_frame.empty() ? std::string("-") : fixed(r.seconds * 1e3 / double(r.per_frame.size()), 1))
    << " ms per frame)\n";
  if (!r.events.empty()) o << "\nevents (global time t):\n";
  for (const auto& e : r.events) {
    o << "  frame " << e.frame << "  " << r.body_names[e.body_a] << " -- " << r.body_names[e.body_b];
    if (e.answer.first_contact) o << "  first contact t ~ " << e.answer.first_contact->approx;
    for (const auto& [s, t] : e.answer.intervals) o << "  [" << s.approx << ", " << t.approx << "]";
    o << "\n";
  }
  if (!r.undecided.empty()) o << "\nundecided:\n";
  for (const auto& u : r.undecided)
    o << "  frame " << u.frame << "  " << r.body_names[u.body_a] << " -- " << r.body_names[u.body_b] << ": " << u.why
      << "\n";
  return o.str();
}

// --poses: the per-pose table (api/pose_check.hpp).
std::string poses_summary_text(const PosesResult& r) {
  std::ostringstream o;
  o << "animation " << r.animation << " (" << r.file << "), " << r.dim << "D, arithmetic " << r.arithmetic
    << ", per pose (static test at each key pose)\n";
  o << "poses " << r.poses << ", pairs per pose " << r.pairs_per_pose << ", separating-plane stage "
    << (r.planes_disabled ? "off" : "built") << "\n\n";
  o << " pose   pairs  bounding  plane  static  built  events  undecided       ms\n";
  for (const auto& p : r.per_pose) {
    char line[160];
    std::snprintf(line, sizeof line, "%5zu  %6zu  %8zu  %5zu  %6zu  %5zu  %6zu  %9zu  %7.3f\n", p.pose, p.pairs,
                  p.bounding_volumes, p.separating_plane, p.static_test, p.planes_built, p.events, p.undecided,
                  p.seconds * 1e3);
    o << line;
  }
  const double total = double(r.bounding_volumes + r.separating_plane + r.static_test);
  auto pct = [&](std::size_t x) { return total > 0 ? fixed(100.0 * double(x) / total, 1) + " %" : std::string("-"); };
  o << "\nstages: bounding volumes " << r.bounding_volumes << " (" << pct(r.bounding_volumes) << "), separating plane "
    << r.separating_plane << " (" << pct(r.separating_plane) << "), static test " << r.static_test << " ("
    << pct(r.static_test) << ")\nplanes: " << r.plane_checks << " kept planes checked, " << r.separating_plane
    << " held, " << r.planes_built << " built, " << r.plane_build_failed << " constructions failed; sweep looked at "
    << r.sweep_examined << " pairs\n";
  o << "events " << r.events.size() << ", undecided " << r.undecided.size() << ", " << fixed(r.seconds, 3) << " s ("
    << (r.per_pose.empty() ? std::string("-") : fixed(r.seconds * 1e3 / double(r.per_pose.size()), 3))
    << " ms per pose)\n";
  if (!r.events.empty()) o << "\nevents:\n";
  for (const auto& e : r.events)
    o << "  pose " << e.pose << " (t = " << r.times[e.pose].get_str() << ")  " << r.body_names[e.body_a] << " -- "
      << r.body_names[e.body_b] << "  " << to_string(e.status) << "\n";
  if (!r.undecided.empty()) o << "\nundecided:\n";
  for (const auto& u : r.undecided)
    o << "  pose " << u.pose << "  " << r.body_names[u.body_a] << " -- " << r.body_names[u.body_b] << ": " << u.why
      << "\n";
  return o.str();
}

// --frame-block i/n: the i-th of n contiguous blocks of frames.
void parse_frame_block(const std::string& s, AnimateOptions& o) {
  const auto slash = s.find('/');
  bool ok = slash != std::string::npos && slash > 0 && slash + 1 < s.size() &&
            s.find_first_not_of("0123456789/") == std::string::npos && s.find('/', slash + 1) == std::string::npos &&
            slash <= 6 && s.size() - slash - 1 <= 6;
  if (ok) {
    o.shard_index = std::stoul(s.substr(0, slash));
    o.shard_count = std::stoul(s.substr(slash + 1));
    ok = o.shard_count >= 1 && o.shard_index < o.shard_count;
  }
  if (!ok) throw std::invalid_argument("--frame-block " + s + ": expected i/n with 0 <= i < n");
}

void add_animate_options(CLI::App* sub, AnimateArgs& args) {
  sub->add_option("ANIMATION", args.path, "Animation file (format ellipse-ccd-animation/1)")->required();
  sub->add_option("--arith", args.arith, "Arithmetic of the continuous test: double, mpfr:BITS, exact or certified")
      ->capture_default_str();
  sub->add_flag("--json", args.json, "Print the answer object (format ellipse-ccd-animation-answer/1)");
  sub->add_flag("--all-intervals", args.all_intervals,
                "Every collision interval of each pair-frame (default: the first contact)");
  sub->add_flag(
      "--no-planes", args.no_planes,
      "Skip the separating-plane stage (no plane kept from frame to frame): paper 000 Table 1's run without planes");
  sub->add_flag(
      "--poses", args.poses,
      "Per-pose mode (papers 000 and 001): the static test of each pair at each key pose, keeping the separating "
      "plane from pose to pose (000 section 4); arithmetic double, exact or certified; answer \"mode\": \"poses\"");
  sub->add_option("--jobs", args.threads, "Threads running pair-frames (the output does not depend on it)")
      ->capture_default_str();
  add_old_spelling(sub, "--threads", "--threads", "--jobs", args.threads);
  // report --shard takes every n-th task; a block of frames is another partition, so it has its own name.
  sub->add_option("--frame-block", args.shard, "i/n: run the i-th of n contiguous blocks of frames (0 <= i < n)");
  add_old_spelling(sub, "--shard", "--shard", "--frame-block", args.shard);
  sub->add_option(
      "--out", args.out,
      "Write the output to this file (atomically) instead of standard output: a new name, or with --force an "
      "existing regular file that is not the animation (a directory, device, FIFO, socket or symbolic link: exit 2)");
  sub->add_flag("--force", args.force, "Replace an existing --out file");
}

}  // namespace

Command add_animate_command(CLI::App& app) {
  auto args = std::make_shared<AnimateArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "animate",
      "Every checked pair of an animation (docs/animation-format.md) in every frame: bounding spheres, "
      "the kept separating plane, then the continuous test in the chosen arithmetic.");
  add_animate_options(c.sub, *args);

  c.run = [args]() -> int {
    AnimateOptions o;
    o.solve.arith = parse_arithmetic(args->arith);
    o.all_intervals = args->all_intervals;
    o.planes = !args->no_planes;
    // Each pair-frame's solve gets --time-limit (floating: at most the default 30 s); beyond it the pair-frame is
    // undecided.
    const double limit = run_budget().time_limit_s;
    o.solve.time_limit_s =
        o.solve.arith.floating() ? (limit > 0 ? std::min(limit, kDefaultFloatingSeconds) : 0) : limit;
    if (args->threads < 1 || args->threads > 256)
      throw std::invalid_argument("--jobs " + std::to_string(args->threads) + ": expected 1 to 256");
    o.threads = args->threads;
    if (!args->shard.empty()) parse_frame_block(args->shard, o);
    if (!args->out.empty()) {
      check_output_path("--out", args->out);
      check_output_file("--out", args->out, args->force, {args->path});
    }
    if (args->poses) {  // options first (exit 2), before the file is read
      if (args->all_intervals)
        throw std::invalid_argument("--poses with --all-intervals: a pose has a status, not intervals");
      if (!args->shard.empty()) throw std::invalid_argument("--poses with --frame-block: poses run in one block");
      if (o.solve.arith.kind == Arithmetic::Mpfr)
        throw std::invalid_argument("--poses with --arith " + args->arith + ": expected double, exact or certified");
    }
    const Animation anim = read_animation(args->path);
    const auto start = std::chrono::steady_clock::now();
    std::optional<ProgressCadence> cadence;  // redrawn on a terminal, a line per 5 % in a log (app/time_left.hpp)
    o.progress = [&](std::size_t done, std::size_t total) {
      if (quiet()) return;
      if (!cadence) cadence.emplace(isatty(2) != 0, long(total));
      const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!cadence->due(long(done), el)) return;
      std::optional<double> left;
      if (done > 0) left = el / double(done) * double(total - done);  // the measured rate per pair-frame
      std::cerr << cadence->begin() << "eccd animate: pair-frames " << done << "/" << total
                << " past the bounding volumes, " << fixed(el, 1) << " s, "
                << (done == total ? std::string("done") : time_left_text(left)) << cadence->end(done == total);
    };
    if (args->poses) {
      PosesResult pr;
      try {
        pr = animate_poses(anim, o);
      } catch (const std::invalid_argument& e) {
        throw ExitError(3, "animate: " + args->path + ": " + cli_message(e));
      }
      std::string text;
      if (args->json) {
        nlohmann::ordered_json j = poses_result_to_json(pr);
        stamp_format(j, kAnimationAnswerFormat);
        text = j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
      } else {
        text = poses_summary_text(pr);
      }
      if (!args->out.empty())
        write_text_atomically(args->out, text);
      else
        std::cout << text;
      return 0;
    }
    AnimationResult r;
    try {
      r = animate(anim, o);
    } catch (const std::invalid_argument& e) {  // valid options, valid file: the pipeline refuses the request
      throw ExitError(3, "animate: " + args->path + ": " + cli_message(e));
    }
    std::string text;
    if (args->json) {
      nlohmann::ordered_json j = animation_result_to_json(r);
      stamp_format(j, kAnimationAnswerFormat);
      text = j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    } else {
      text = summary_text(r);
    }
    if (!args->out.empty())
      write_text_atomically(args->out, text);
    else
      std::cout << text;
    return 0;
  };
  return c;
}

}  // namespace eccd

// `eccd plot SCENE`: one scene as a PNG, the pictures papers 002 and 003 print.
//
// Left: the two objects at a few instants along their paths (2D: the
// ellipses; 3D: the outlines of the ellipsoids' projections onto the
// xy-plane), their centres' paths, and the contact points. Right: 2D, the
// discriminant Δ(t) of f(λ;t) = det(λA(t) - B(t)) (003 eq. (2)); 3D, the zero
// set of F(u,t) = det((u-1)A(t) - uB(t)) in the (u,t) square (001 section 4,
// 002 section III), with the critical instants, collision intervals and
// contacts that `eccd solve` reports in the chosen arithmetic. Independent
// motions ("parameters": "independent", 001 section 4): one panel,
// where A(s) meets B(t) on a grid of the (s, t) square (add_st_grid below),
// whose boundary is the zero set of F(u, s, t) projected on (s, t), with the
// answer's s- and t-intervals drawn along the axes (exact by default, double
// where exact refuses the pair).
//
// app/plot_data.cpp computes the data; compare/plots/scene_figure.py draws it. The
// data goes through a temporary JSON file ("eccd-plot-data/1", the --data
// file), the script writes OUT's temporary sibling, and OUT is replaced by a
// rename only when the script succeeded: no half-written PNG.
//
// What is computed how:
//   - the answer (critical instants, intervals, contacts, 2D contact points):
//     eccd::solve (api/solve.hpp) in --arith;
//   - the curve: Δ (2D) or the Bernstein coefficients in u of F (3D) are built
//     exactly from the prepared scene with the kernel templates
//     (characteristic_coefficients, cubic_discriminant, ellipsoid_function) and
//     evaluated exactly at rational grid instants; only the normalised values
//     (divided by the largest one, exactly) are rounded to double. F(u, t_k) is
//     then evaluated in u from those rounded coefficients by de Casteljau. So
//     the curve is the same whatever --arith says: a double answer is drawn
//     against the exact curve;
//   - outlines: the object's centre x0 and "dual" shape Σ (the solid is
//     (x - x0)ᵀ Σ⁻¹ (x - x0) ≤ 1; Σ is the normalised dual quadric's block) are
//     computed exactly from Q, then moved by M(t) in double: x0 ↦ L x0 + v,
//     Σ ↦ L Σ Lᵀ with M = [[w L, w v], [0, w]]. The outline of the projection
//     onto the xy-plane is the ellipse of Σ's upper-left 2x2 block (projecting
//     a quadric's dual is taking that block of the dual), in 2D the ellipse itself;
//   - 3D u-window: F is drawn on [0, 1] in u, or zoomed to where F > 0 when
//     that is less than half of it (the relative scale of A and B, which the
//     pipelines keep as prepared, decides where in u the negative roots land);
//   - 3D contact points (display only): u0 = argmax F(., t0) on (0, 1), the
//     double root λ0 = (u0 - 1)/u0 of f, and the null vector of λ0 A - B
//     (largest column of its adjugate), A and B as the pipelines build them.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/option_names.hpp"
#include "app/plot_data.hpp"
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "kernel/budget.hpp"
#include "kernel/motion.hpp"
#include "io/scene_reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace eccd {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

struct PlotOptions {
  std::string scene, out, arith = "exact", data;
  int instants = 5;
  CLI::Option* arith_opt = nullptr;  // null: --arith not given (draw_scene_picture)
  bool announce = true;              // the "wrote ..." line on stdout
};

std::string quote(const std::string& s) {
  std::string r = "'";
  for (char c : s) r += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

int shell(const std::string& cmd) {
  int st = std::system(cmd.c_str());
  if (st == -1) return -1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// An interpreter with numpy and matplotlib: $ECCD_PYTHON if set, else python3 on PATH, else /usr/bin/python3.
std::string find_python(std::string& tried) {
  std::vector<std::string> cands;
  if (const char* e = std::getenv("ECCD_PYTHON"); e && *e)
    cands.push_back(e);
  else
    cands = {"python3", "/usr/bin/python3"};
  for (const auto& c : cands) {
    tried += (tried.empty() ? "" : ", ") + c;
    if (shell(quote(c) + " -c 'import numpy, matplotlib' >/dev/null 2>&1") == 0) return c;
  }
  return "";
}

std::string answer_words(const Solution& rep) {
  if (rep.answer.independent)
    return !rep.answer.collides ? "free (the swept volumes do not meet)"
                                : "collides, " + std::to_string(rep.answer.s_intervals.size()) + " s-interval(s), " +
                                      std::to_string(rep.answer.t_intervals.size()) + " t-interval(s)";
  std::ostringstream o;
  if (!rep.answer.collides) return "free";
  o << "collides";
  o << ", " << rep.answer.intervals.size() << " interval(s)";
  if (rep.answer.first_contact) o << ", first contact t = " << rep.answer.first_contact->approx;
  return o.str();
}

// --out and --data: new files in existing folders, or regular files that are not the scene.
void check_plot_outputs(const PlotOptions& o) {
  for (const auto& [opt_name, f] : {std::pair<std::string, std::string>{"--out", o.out}, {"--data", o.data}}) {
    if (f.empty()) continue;
    check_output_path(opt_name, f);
    fs::path dir = fs::path(f).parent_path();
    std::error_code ec;
    if (!dir.empty() && !fs::is_directory(dir, ec))
      throw OutputError(f + ": folder " + dir.string() + " does not exist");
    if (fs::is_directory(f, ec)) throw OutputError(f + ": cannot write the file: it is a directory");
    // an existing regular file is replaced (a drawing is made again by design); anything else, or the scene, never
    if (std::string why = not_a_plain_output(f); !why.empty())
      throw OutputError(opt_name + " " + f + ": refusing to write there: " + why);
    check_output_file(opt_name, f, true, {o.scene});
  }
}

// The data into its file, the script draws OUT's temporary sibling, and OUT
// (and --data) replaced by a rename only when the script succeeded: no
// half-written PNG. 0 written; 1 the script failed (nothing written).
int write_picture(const PlotOptions& o, const json& data, const fs::path& out, const std::string& python,
                  const fs::path& script) {
  const std::string tag = "." + std::to_string(::getpid()) + ".tmp";
  const fs::path tmp_png = fs::path(out.string() + tag + ".png");
  fs::path tmp_data;
  if (!o.data.empty())
    tmp_data = fs::path(o.data + tag + ".json");
  else
    tmp_data = fs::temp_directory_path() / ("eccd-plot-" + std::to_string(::getpid()) + ".json");
  auto cleanup = [&] {
    std::error_code ec;
    fs::remove(tmp_png, ec);
    fs::remove(tmp_data, ec);
  };
  {
    std::ofstream f(tmp_data);
    f << data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    if (!f) {
      int e = errno;
      cleanup();
      throw OutputError(tmp_data.string() + ": cannot write the file: " + errno_text(e));
    }
  }
  const std::string cmd = quote(python) + " " + quote(script.string()) + " " + quote(tmp_data.string()) + " " +
                          quote(tmp_png.string()) + " 1>&2";
  const int rc = shell(cmd);
  std::error_code ec;
  if (rc != 0 || !fs::is_regular_file(tmp_png) || fs::file_size(tmp_png, ec) == 0) {
    cleanup();
    std::cerr << "eccd: plot: the drawing script " << script.string() << " failed (exit status " << rc
              << "); its messages are above; nothing was written\n";
    return 1;
  }
  if (std::rename(tmp_png.c_str(), out.c_str()) != 0) {
    int e = errno;
    cleanup();
    throw OutputError(out.string() + ": cannot write the file: " + errno_text(e));
  }
  if (!o.data.empty() && std::rename(tmp_data.c_str(), o.data.c_str()) != 0) {
    int e = errno;
    cleanup();
    throw OutputError(o.data + ": cannot write the file: " + errno_text(e));
  } else
    fs::remove(tmp_data, ec);
  return 0;
}

int run_plot(const PlotOptions& o) {
  const SceneSource src = read_scene_source(o.scene);  // "-": standard input
  Scene s = parse_scene(src.text, src.label);          // SceneError -> exit 2
  check_plot_outputs(o);
  bool cyclo =
      std::holds_alternative<CycloidalMotion>(s.a.motion) || std::holds_alternative<CycloidalMotion>(s.b.motion);
  std::string arith_text = o.arith, arith_note;
  if (cyclo && (!o.arith_opt || o.arith_opt->count() == 0)) {
    arith_text = "double";
    arith_note =
        "cycloidal motion: not rational, so double arithmetic (exact cannot represent it; certified also solves it)";
    warn("plot", src.label + ": " + arith_note);
  }
  SolveOptions opt;
  opt.arith = parse_arithmetic(arith_text);  // std::invalid_argument -> exit 2
  Solution rep;
  try {
    ScopedDeadline deadline(run_budget().time_limit_s);
    if (s.independent &&
        (!o.arith_opt || o.arith_opt->count() == 0)) {  // exact where it answers (two balls), else double
      try {
        rep = solve(s, opt);
      } catch (const std::invalid_argument& e) {
        opt.arith = Arithmetic::double_precision();
        arith_note = "exact arithmetic refuses this pair, so double";
        warn("plot", src.label + ": independent motions: " + e.what() + "; drawing the double answer");
        rep = solve(s, opt);
      }
    } else {
      rep = solve(s, opt);
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "eccd: plot: " << src.label << ": " << cli_message(e) << "\n";
    return 3;
  }

  const fs::path script = fs::path(plots_dir()) / "scene_figure.py";
  if (!fs::is_regular_file(script)) {
    std::cerr << "eccd: plot: drawing script " << script.string()
              << " not found (set ECCD_PLOTS_DIR to the folder compare/plots)\n";
    return 1;
  }
  std::string tried;
  const std::string python = find_python(tried);
  if (python.empty()) {
    std::cerr << "eccd: plot: needs python3 with numpy and matplotlib, and none was found (tried " << tried
              << "): install them with `apt-get install python3-matplotlib` (it brings numpy), "
                 "or set ECCD_PYTHON to an interpreter that has them\n";
    return 1;
  }

  json data;
  stamp_format(data, "eccd-plot-data/1");  // format and version, as every JSON object eccd writes
  data["scene"] = s.name;
  data["file"] = s.path;
  data["dim"] = s.dim;
  data["arith"] = opt.arith.name();
  data["arith_note"] = arith_note;
  data["solve"] = solution_to_json(rep);
  plot_data::add_scene_data(data, s, rep, o.instants);

  // Default PNG: the scene file's name; for a scene read from standard input, the scene's "name" (or "scene").
  const std::string stem = o.scene != "-" ? fs::path(o.scene).stem().string()
                           : !s.name.empty() && s.name.find('/') == std::string::npos ? s.name
                                                                                      : "scene";
  const fs::path out = o.out.empty() ? fs::path(stem + ".png") : fs::path(o.out);
  if (const int rc = write_picture(o, data, out, python, script); rc != 0) return rc;
  if (!o.announce) return 0;
  std::cout << "wrote " << out.string() << ": scene " << s.name << " (" << s.dim << "D), " << answer_words(rep) << " ["
            << opt.arith.name() << (rep.certified ? ", certified" : ", not certified") << "]";
  if (!o.data.empty()) std::cout << "; data " << o.data;
  std::cout << "\n";
  return 0;
}

}  // namespace

Command add_plot_command(CLI::App& app) {
  auto o = std::make_shared<PlotOptions>();
  Command c;
  c.sub = app.add_subcommand(
      "plot",
      "Draw one scene as a PNG. Left: the two objects at a few instants along their paths (3D: outlines of their "
      "projections onto the xy-plane), their centres' paths and the contact points. Right: 2D, the discriminant "
      "Delta(t) of f(lambda;t) = det(lambda A - B) on a symmetric log scale; 3D, the zero set of "
      "F(u,t) = det((u-1)A - uB) in the (u,t) square (zoomed in u when F > 0 only in a narrow band), F > 0 filled "
      "(separate at t iff F(u,t) > 0 for some u). Critical instants, collision intervals and contacts come from "
      "`eccd solve` in --arith; the curve (Delta, or F's Bernstein coefficients in u) is built exactly and evaluated "
      "exactly at the sample instants, whatever --arith says. Needs python3 with numpy and matplotlib "
      "(apt-get install python3-matplotlib; ECCD_PYTHON picks the interpreter, ECCD_PLOTS_DIR the script folder). "
      "Exit status: 0 written; 1 python/matplotlib missing or drawing failed (nothing written); 2 bad scene or "
      "option; 3 a request the pipeline refuses.");
  c.sub->add_option("SCENE", o->scene, "Scene file (format ellipse-ccd-scene/1); - reads it from standard input")
      ->required();
  add_old_spelling(c.sub, "-o,--output", "-o/--output", "--out", o->out);
  c.sub->add_option("--out", o->out,
                    "PNG to write (default: the scene file's name with .png, in the current directory; for -, the "
                    "scene's name); "
                    "an existing regular file is replaced, only when drawing succeeded (a directory, device, FIFO, "
                    "socket, symbolic link or the scene: exit 2)");
  c.sub
      ->add_option("--instants", o->instants,
                   "Number of evenly spaced instants drawn on the left, 0 to 50 (1 = t = 0 only); every contact "
                   "instant and the first contact are drawn too")
      ->check(CLI::Range(0, 50))
      ->capture_default_str();
  o->arith_opt =
      c.sub
          ->add_option("--arith", o->arith,
                       "Arithmetic of the critical instants, collision intervals and contacts: exact "
                       "(certified), double or mpfr:BITS. A scene with a cycloidal motion defaults to "
                       "double (Delta(t) drawn from MPFI enclosures; --arith certified or mpfr:BITS also solve it)")
          ->capture_default_str();
  c.sub->add_option(
      "--data", o->data,
      "Also write the data the drawing script read (JSON, eccd-plot-data/1: the solve report, samples, outlines) to "
      "this file "
      "(an existing regular file is replaced; a directory, device, FIFO, socket, symbolic link or the scene: exit 2)");
  c.run = [o] { return run_plot(*o); };
  return c;
}

}  // namespace eccd

namespace eccd {
int draw_scene_picture(const std::string& scene, const std::string& png) {
  PlotOptions o;
  o.scene = scene;
  o.out = png;
  o.announce = false;
  return run_plot(o);
}

std::string plots_dir() {
  if (const char* e = std::getenv("ECCD_PLOTS_DIR")) return e;
  return ECCD_PLOTS_DIR;
}
}  // namespace eccd

// The comparison harness (see compare/harness.hpp).
#include "compare/harness.hpp"

#include "compare/csv.hpp"
#include "compare/harness_families.hpp"
#include "compare/scene_generator.hpp"
#include "io/solution_json.hpp"
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/motion.hpp"
#include "kernel/budget.hpp"
#include "kernel/prepared_scene.hpp"

#include <tuple>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cerrno>
#include <csignal>
#include <poll.h>
#include <cstring>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <sstream>

namespace eccd {

namespace {

template <int N>
int motion_degree(const Motion& m) {
  if (std::holds_alternative<CycloidalMotion>(m)) return -1;
  auto M = motion_matrix<Rational, N>(m, [](const Rational& x) { return x; });
  int d = 0;
  for (auto& row : M)
    for (auto& e : row) d = std::max(d, e.degree());
  return d;
}

// Exact reference coefficients of one scene.
struct Reference2 {
  PreparedPair2 p;
  std::vector<Poly<Rational>> g;       // power form
  std::vector<Bern<Rational>> g_bern;  // each g_k in Bernstein form of its degree
  Bern<Rational> delta_bern;           // Δ in Bernstein form of its degree
};
struct Reference3 {
  PreparedPair3 p;
  std::vector<Poly<Rational>> g;  // power form (the projection pipeline's setup)
  std::vector<Bern<Rational>> g_bern;
  BiBern<Rational> F;
};

template <class T>
void coefficients_2d(const Reference2& ref, Basis basis, int bits, const T& like, ResultRow& row) {
  auto m = to_arithmetic<T, H_2D>(ref.p, like);
  std::vector<Poly<T>> g = characteristic_of(m);
  FloatingPolicy<T> pol(basis, bits, like);
  if (basis == Basis::power) {
    row.coef_err = coefficient_error(g, ref.g);
    row.coef_err_common = coefficient_error_common(g, ref.g_bern);
  } else {
    row.coef_err = coefficient_error(to_bernstein_all(g, like), ref.g_bern);
    row.coef_err_common = row.coef_err;  // already held in the common basis
  }
  row.delta_err = coefficient_error(discriminant_of(g, pol), ref.delta_bern);
}

template <class T>
void coefficients_3d(const Reference3& ref, const PipelineSpec& ps, const T& like, ResultRow& row) {
  if (ps.method == "projection") {
    auto g = characteristic_of(to_arithmetic<T, H_3D>(ref.p, like));
    row.coef_err = coefficient_error(g, ref.g);
    row.coef_err_common = coefficient_error_common(g, ref.g_bern);
    return;
  }
  bool power = ps.basis == "power";
  std::vector<Bern<T>> g = characteristic_bernstein<T, H_3D>(ref.p, power, like);
  row.coef_err = coefficient_error(g, ref.g_bern);
  row.coef_err_common =
      row.coef_err;  // Bernstein coefficients (also for bezier-power: f set up in power form, held in Bernstein form)
  row.delta_err = coefficient_error(ellipsoid_function(g, like), ref.F);
}

// Free text in one CSV field (quoted by csv_line as needed): line breaks become spaces, so that a
// reason stays on one line; at most 200 characters.
std::string csv_text(std::string t) {
  for (char& c : t)
    if (c == '\n' || c == '\r') c = ' ';
  if (t.size() > 200) t = t.substr(0, 197) + "...";
  return t;
}

std::string fmt(double x, const char* f = "%.6g") {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace

int scene_degree(const Scene& s) {
  if (s.dim == 2) return std::max(motion_degree<H_2D>(s.a.motion), motion_degree<H_2D>(s.b.motion));
  return std::max(motion_degree<H_3D>(s.a.motion), motion_degree<H_3D>(s.b.motion));
}

SceneInfo scene_info(const Scene& s, const std::string& source) {
  SceneInfo i;
  i.name = s.name;
  i.source = source;
  i.dim = s.dim;
  if (auto sp = spec_from_note(s.note)) {
    i.family = sp->family;
    i.motion = sp->motion;
    i.degree = sp->degree;
    i.d_exponent = sp->family == "near-miss" || sp->family == "overlap" ? sp->d_exponent : 0;
    i.digits = sp->digits;
    i.seed = sp->seed;
  } else {
    i.degree = scene_degree(s);
  }
  return i;
}

namespace {
template <class O>
constexpr bool has_input_member = requires(O o) {
  o.input;
};

template <class O>
void set_input(O& o, const std::string& mode) {
  if constexpr (has_input_member<O>) {
    using M = decltype(o.input);
    o.input = mode == "prepared" ? M::prepared : M::rounded;
  }
}
}  // namespace

bool solver_has_input_modes() { return has_input_member<SolveOptions>; }

std::vector<std::string> default_input_modes() {
  if (solver_has_input_modes()) return {"rounded", "prepared"};
  return {"prepared"};
}

void apply_input_mode(SolveOptions& opt, const std::string& mode) {
  if (mode != "rounded" && mode != "prepared")
    throw std::invalid_argument("input mode '" + mode + "': expected rounded or prepared");
  set_input(opt, mode);
}

std::vector<PipelineSpec> harness_pipelines(int dim, const HarnessOptions& o) {
  std::vector<PipelineSpec> v;
  std::vector<std::string> modes;
  for (const auto& m : o.inputs) {
    if (m != "rounded" && m != "prepared")
      throw std::invalid_argument("input mode '" + m + "': expected rounded or prepared");
    if (!solver_has_input_modes() && m == "rounded") continue;  // this solver always starts from the prepared scene
    if (std::find(modes.begin(), modes.end(), m) == modes.end()) modes.push_back(m);
  }
  if (modes.empty()) modes.push_back("prepared");
  const bool both = modes.size() > 1;
  auto add = [&](const std::string& arith, const std::string& basis, const std::string& method,
                 const std::string& variant) {
    for (const auto& mode : modes) {
      if (arith == "exact" && mode != modes.front()) continue;
      PipelineSpec p;
      p.opt.arith = parse_arithmetic(arith);
      p.opt.basis = parse_basis(basis);
      if (method != "cd-disc") std::tie(p.opt.method, p.opt.grid) = parse_method(method);  // 2D: one method
      p.basis = arith == "exact" ? "exact" : basis;
      p.method = arith == "exact" ? (dim == 2 ? "cd-disc" : "projection") : method;
      p.label = arith == "exact" ? "exact" : arith + "/" + variant;
      p.input = arith == "exact" ? "prepared" : mode;
      p.arith = p.opt.arith.kind == Arithmetic::Exact  ? "exact"
                : p.opt.arith.kind == Arithmetic::Mpfr ? "mpfr"
                                                       : "double";
      p.bits = p.opt.arith.precision_bits();
      if (arith == "exact") {
        v.push_back(p);
        continue;
      }
      apply_input_mode(p.opt, mode);
      for (PipelineSpec& f : in_faces(p, o.guards)) {
        if (both && mode == "prepared") f.label += "@prepared";
        v.push_back(f);
      }
    }
  };
  add("exact", "bernstein", "bezier", "");
  if (dim == 2) {
    add("double", "power", "cd-disc", "power");
    add("double", "bernstein", "cd-disc", "bernstein");
    add("double", "scaled-bernstein", "cd-disc", "scaled-bernstein");
    for (int b : o.mpfr_bits) {
      std::string a = "mpfr:" + std::to_string(b);
      add(a, "power", "cd-disc", "power");
      add(a, "bernstein", "cd-disc", "bernstein");
    }
  } else {
    std::string n = std::to_string(o.grid);
    add("double", "bernstein", "bezier", "bezier");
    add("double", "power", "bezier", "bezier-power");
    add("double", "bernstein", "sampling:" + n, "sampling:" + n);
    add("double", "bernstein", "marching:" + n, "marching:" + n);
    for (int b : o.mpfr_bits) {
      std::string a = "mpfr:" + std::to_string(b);
      add(a, "bernstein", "bezier", "bezier");
      if (o.mpfr_power_3d) add(a, "power", "bezier", "bezier-power");
    }
  }
  if (o.certified) {
    PipelineSpec p;
    p.opt.arith = Arithmetic::certified();
    p.label = p.arith = "certified";
    p.basis = "none";
    p.method = "ladder";
    p.input = "prepared";
    v.push_back(p);
  }
  if (o.fcl && fcl_availability().available) {
    for (int n : o.fcl_samples)
      if (n < 2) throw std::invalid_argument("FCL sample count " + std::to_string(n) + ": expected N >= 2");
    for (auto engine : {PipelineSpec::Engine::fcl_sample, PipelineSpec::Engine::fcl_ccd})
      for (int n : o.fcl_samples) {
        PipelineSpec p;
        p.engine = engine;
        p.fcl_n = n;
        p.method = (engine == PipelineSpec::Engine::fcl_sample ? "sample:" : "ccd:") + std::to_string(n);
        p.label = "fcl/" + p.method;
        p.arith = "fcl";
        p.bits = 53;
        p.basis = "none";
        p.input = "rounded";
        v.push_back(p);
      }
  }
  return v;
}

std::vector<PipelineSpec> in_faces(const PipelineSpec& p, const std::vector<std::string>& guards) {
  std::vector<PipelineSpec> v;
  for (const auto& g : guards) {
    PipelineSpec f = p;
    f.opt.guard = parse_guard(g);
    f.guard = g;
    if (f.opt.guard == Guard::none) {
      const std::size_t at = f.label.find('@');
      f.label.insert(at == std::string::npos ? f.label.size() : at, kPublishedSuffix);
    }
    if (std::none_of(v.begin(), v.end(), [&](const PipelineSpec& x) { return x.label == f.label; })) v.push_back(f);
  }
  return v;
}

std::vector<std::pair<std::string, int>> fcl_skipped(const std::vector<std::string>& labels,
                                                     const std::vector<std::string>& csv_rows) {
  // the fields scene (0) and pipeline (8) of results_csv_header()
  std::vector<std::string> scenes;
  std::vector<std::pair<std::string, std::string>> have;  // (pipeline, scene)
  for (const auto& line : csv_rows) {
    std::vector<std::string> f = csv_split(line, "results.csv row");
    if (f.size() < 9) continue;
    if (f[8] == "exact")
      scenes.push_back(f[0]);
    else if (f[8].rfind("fcl/ccd:", 0) == 0)
      have.emplace_back(f[8], f[0]);
  }
  std::sort(have.begin(), have.end());
  std::vector<std::pair<std::string, int>> out;
  for (const auto& l : labels) {
    if (l.rfind("fcl/ccd:", 0) != 0) continue;
    int n = 0;
    for (const auto& sc : scenes) n += !std::binary_search(have.begin(), have.end(), std::make_pair(l, sc));
    out.emplace_back(l, n);
  }
  return out;
}

namespace {
// Processor time (user + system) a running child has used so far, from
// /proc/PID/stat (clock ticks); 0 if it cannot be read.
double child_cpu_seconds(pid_t pid) {
  std::FILE* f = std::fopen(("/proc/" + std::to_string(pid) + "/stat").c_str(), "r");
  if (!f) return 0;
  char buf[1024];
  std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  buf[n] = 0;
  const char* p = std::strrchr(buf, ')');  // the command name may hold spaces
  if (!p) return 0;
  unsigned long long ut = 0, st = 0;
  // fields after the name: state ppid pgrp session tty_nr tpgid flags minflt cminflt majflt cmajflt utime stime
  if (std::sscanf(p + 1, " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &ut, &st) != 2) return 0;
  return double(ut + st) / double(sysconf(_SC_CLK_TCK));
}
// The child's side of an isolated run: its result as one JSON line on fd,
// then _exit (the parent's destructors are not run in the child).
[[noreturn]] void report_to_parent(const BoundedRun& c, int fd) {
  nlohmann::json msg = {{"got", c.got ? solution_to_json(*c.got) : nlohmann::json(nullptr)},
                        {"timed_out", c.timed_out},
                        {"error", c.error},
                        {"reason", c.reason}};
  std::string text = msg.dump();
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    ssize_t w = write(fd, p, left);
    if (w <= 0) break;
    p += w;
    left -= std::size_t(w);
  }
  close(fd);
  _exit(0);
}

// The parent's side: the child's JSON line into r (an error when there is none).
void read_child_report(BoundedRun& r, const std::string& text, int status) {
  try {
    nlohmann::json msg = nlohmann::json::parse(text);
    if (!msg["got"].is_null()) r.got = solution_from_json(msg["got"], "the run's process");
    r.timed_out = msg["timed_out"].get<bool>();
    r.error = msg["error"].get<std::string>();
    r.reason = msg["reason"].get<std::string>();
  } catch (const std::exception&) {
    r.error = "the run's process ended without an answer (status " + std::to_string(status) + ")";
    r.got.reset();
  }
}
}  // namespace

// A run in a fresh child that answers faster than this (and than a quarter of its budget, so that both runs stay
// well inside it) runs again for its time (harness.hpp, run_bounded).
constexpr double kRepeatBelowMs = 50;
BoundedRun run_bounded(const Scene& s, const SolveOptions& opt, double budget_s, bool isolate) {
  BoundedRun r;
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const double cpu_start = thread_cpu_seconds();
  auto in_process = [&](BoundedRun& out) {
    try {
      ScopedDeadline budget(budget_s, DeadlineClock::thread_cpu);
      out.got = solve(s, opt);
    } catch (const BudgetExhausted& e) {
      out.timed_out = true;
      out.reason = std::string("time budget: ") + e.what();
    } catch (const std::exception& e) {
      out.error = e.what();
      out.got.reset();
    }
  };
  int fds[2];
  if (!isolate || budget_s <= 0 || pipe(fds) != 0) {
    in_process(r);
    r.cpu_s = thread_cpu_seconds() - cpu_start;
  } else {
    std::fflush(nullptr);
    pid_t pid = fork();
    if (pid == 0) {  // the child: run, write one JSON line, leave without running the parent's destructors
      close(fds[0]);
      BoundedRun c;
      in_process(c);
      if (c.got && c.got->time_ms < std::min(kRepeatBelowMs, budget_s * 1e3 / 4)) {  // timed again (the header)
        BoundedRun again;
        in_process(again);
        if (again.got) c.got->time_ms = again.got->time_ms;
      }
      report_to_parent(c, fds[1]);
    }
    close(fds[1]);
    if (pid < 0) {
      close(fds[0]);
      in_process(r);
      r.cpu_s = thread_cpu_seconds() - cpu_start;
    } else {
      std::string text;
      const double hard = 2 * budget_s + 1;     // processor seconds of the child
      const double backstop = 10 * hard + 120;  // wall seconds: a child that neither works nor ends
      bool killed = false;
      char buf[65536];
      while (true) {
        if (child_cpu_seconds(pid) > hard || elapsed() > backstop) {
          kill(pid, SIGKILL);
          killed = true;
          break;
        }
        pollfd pf{fds[0], POLLIN, 0};
        int pr = poll(&pf, 1, 50);
        if (pr < 0 && errno == EINTR) continue;
        if (pr <= 0) continue;
        ssize_t n = read(fds[0], buf, sizeof buf);
        if (n <= 0) break;  // end of the child's message
        text.append(buf, std::size_t(n));
      }
      close(fds[0]);
      int status = 0;
      rusage ru{};
      while (wait4(pid, &status, 0, &ru) < 0 && errno == EINTR) {}
      r.cpu_s =
          double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
      if (killed) {
        r.timed_out = true;
        r.killed = true;
        r.reason = "time budget: " + fmt(budget_s, "%g") +
                   " s of processor time; the run did not stop and was killed after " + fmt(r.cpu_s, "%.3g") +
                   " s of processor time (" + fmt(elapsed(), "%.3g") + " s)";
      } else {
        read_child_report(r, text, status);
      }
    }
  }
  r.wall_s = elapsed();
  if (!r.timed_out && r.error.empty() && budget_s > 0 && r.cpu_s > budget_s) {  // came back, but later than its budget
    r.timed_out = true;
    r.reason = "time budget: " + fmt(budget_s, "%g") + " s of processor time exceeded (the answer after " +
               fmt(r.cpu_s, "%.3g") + " s is not used)";
  }
  if (!r.error.empty()) r.reason = r.error;
  return r;
}

ResultRow pipeline_row(const SceneInfo& info, const PipelineSpec& ps) {
  ResultRow row;
  row.scene = info;
  row.pipeline = ps.label;
  row.arith = ps.arith;
  row.bits = ps.bits;
  row.basis = ps.basis;
  row.method = ps.method;
  row.input = ps.input;
  row.guard = ps.guard;
  return row;
}

namespace {

// The row of an external engine on one scene (compare/external_answers.hpp), if it answered the scene: its
// answer against the exact one by the same metrics as every pipeline; an unreadable file is an error row.
void rows_from_external(const ExternalEngine& e, const SceneInfo& info, const Answer& exact,
                        std::vector<ResultRow>& rows) {
  std::optional<ExternalAnswer> ext = read_external_answer(e, info.name);
  if (!ext) return;  // no answer file for this scene: no row (meta.json counts the missing ones)
  ResultRow row;
  row.scene = info;
  row.pipeline = "ext:" + e.name;
  row.arith = "external";
  row.basis = "none";
  row.method = "external";
  row.input = "rounded";  // the engine's own input: whatever it made of the scene's numbers
  row.m = answer_metrics(ext->answer ? &*ext->answer : nullptr, exact);
  row.time_us = ext->time_us >= 0 ? ext->time_us : std::numeric_limits<double>::quiet_NaN();  // NaN: not measured
  if (!ext->answer) {
    row.error = row.reason = ext->error;
  } else if (row.m.outcome == "undecided") {
    for (const auto& u : ext->answer->undecided)
      row.reason += (row.reason.empty() ? "" : "; ") + ("undecided near t = " + u.approx);
  }
  rows.push_back(row);
}

}  // namespace

void fill_row_from_run(ResultRow& row, BoundedRun&& br, const Answer& truth) {
  std::optional<Solution> got = std::move(br.got);
  row.error = br.error;
  row.reason = br.reason;
  if (br.timed_out) {
    row.m = answer_metrics(nullptr, truth);
    row.m.outcome = "undecided";
    row.time_us = br.wall_s * 1e6;
    return;
  }
  row.m = answer_metrics(got ? &got->answer : nullptr, truth);
  if (got) {
    row.time_us = got->time_ms * 1e3;
    row.input = to_string(got->input);
    if (row.guard == "bound") {
      row.second_look = 0;
      for (const auto& [key, n] : got->work)
        if (key == "second_look") row.second_look = int(n);
    }
  }
  if (row.m.outcome == "undecided") {
    // the pipeline's own reasons, else where
    std::string why;
    for (const auto& w : got->undecided_reasons)
      if (!w.empty() && why.find(w) == std::string::npos) why += (why.empty() ? "" : "; ") + w;
    if (why.empty())
      for (const auto& u : got->answer.undecided) why += (why.empty() ? "" : "; ") + ("undecided near t = " + u.approx);
    row.reason = why.empty() ? "undecided" : why;
  }
}

std::vector<ResultRow> run_scene(const Scene& s, const SceneInfo& info, const HarnessOptions& opt) {
  if (motion_family_scene(s))
    return run_motion_family_scene(s, info, opt);  // cycloidal, independent (harness_families.hpp)
  std::vector<ResultRow> rows;
  auto pipes = harness_pipelines(s.dim, opt);
  Solution exact;
  {
    ScopedDeadline budget(opt.exact_budget_s);  // BudgetExhausted: no ground truth, the scene fails
    exact = solve(s, pipes[0].opt);             // throws for a scene the exact pipeline refuses
  }
  Reference2 r2;
  Reference3 r3;
  if (s.dim == 2) {
    r2.p = prepare_pair<H_2D>(s);
    r2.g = characteristic_of(to_arithmetic<Rational, H_2D>(r2.p, Rational(1)));
    r2.g_bern = to_bernstein_all(r2.g, Rational(1));
    r2.delta_bern = to_bernstein(cubic_discriminant(r2.g[3], r2.g[2], r2.g[1], r2.g[0]));
  } else {
    r3.p = prepare_pair<H_3D>(s);
    r3.g = characteristic_of(to_arithmetic<Rational, H_3D>(r3.p, Rational(1)));
    r3.g_bern = to_bernstein_all(r3.g, Rational(1));
    r3.F = ellipsoid_function(r3.g_bern, Rational(1));
  }
  for (const auto& ps : pipes) {
    ResultRow row = pipeline_row(info, ps);
    if (ps.engine != PipelineSpec::Engine::solve) {  // FCL, in this process (see the header)
      const bool ccd = ps.engine == PipelineSpec::Engine::fcl_ccd;
      if (ccd && !fcl_ccd_inexpressible(s).empty()) continue;  // no row: counted by fcl_skipped
      std::optional<Answer> got;
      auto start = std::chrono::steady_clock::now();
      try {
        got = ccd ? fcl_ccd(s, ps.fcl_n) : fcl_sample(s, ps.fcl_n);
      } catch (const std::exception& e) {
        row.error = row.reason = e.what();
      }
      row.time_us = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e6;
      const Answer reference = ccd ? first_contact_view(exact.answer) : exact.answer;
      row.m = answer_metrics(got ? &*got : nullptr, reference);
      if (ccd) {  // no intervals claimed: no end error; structure = collides and the first contact agree
        row.m.endpoint_err.reset();
        if (got) row.m.structure_ok = row.m.outcome == "correct" && answer_difference(*got, reference).agrees;
      }
      rows.push_back(row);
      continue;
    }
    BoundedRun br;
    if (ps.label == "exact")
      br.got = exact;
    else
      br = run_bounded(s, ps.opt, opt.budget_s, opt.isolate);
    fill_row_from_run(row, std::move(br), exact.answer);
    // Coefficient errors are recomputed from the prepared scene, i.e. for the prepared input mode only (a rounded
    // row leaves them empty rather than show another mode's numbers).
    if ((ps.arith == "double" || ps.arith == "mpfr") && ps.input == "prepared") {
      Basis basis = ps.opt.basis;
      if (ps.opt.arith.kind == Arithmetic::Double) {
        if (s.dim == 2)
          coefficients_2d<double>(r2, basis, 53, 1.0, row);
        else
          coefficients_3d<double>(r3, ps, 1.0, row);
      } else {
        Mpfr like(mpq_class(1), ps.opt.arith.precision_bits());
        if (s.dim == 2)
          coefficients_2d<Mpfr>(r2, basis, ps.opt.arith.precision_bits(), like, row);
        else
          coefficients_3d<Mpfr>(r3, ps, like, row);
      }
    }
    rows.push_back(row);
  }
  for (const auto& e : opt.externals) rows_from_external(e, info, exact.answer, rows);
  return rows;
}

std::string results_csv_header() {
  return "scene,source,dim,degree,family,motion,d,seed,pipeline,arith,bits,basis,method,coef_err,delta_err,outcome,"
         "collides,exact_collides,intervals,exact_intervals,missed_contacts,false_contacts,first_contact_err,"
         "endpoint_err,time_us,structure_ok,input,digits,reason,coef_err_common,guard,exact_touch,second_look";
}

std::string results_csv_line(const ResultRow& r) {
  const SceneInfo& s = r.scene;
  auto opt = [](const std::optional<double>& x) { return x ? fmt(*x) : std::string(); };
  // In the order of results_csv_header(); csv_line quotes a field with a comma, quote or line break (RFC 4180).
  return csv_line({s.name,
                   s.source,
                   std::to_string(s.dim),
                   std::to_string(s.degree),
                   s.family,
                   s.motion,
                   s.family == "near-miss" || s.family == "overlap" ? separation_label(s.d_exponent) : "",
                   s.seed ? std::to_string(*s.seed) : "",
                   r.pipeline,
                   r.arith,
                   std::to_string(r.bits),
                   r.basis,
                   r.method,
                   opt(r.coef_err),
                   opt(r.delta_err),
                   r.m.outcome,
                   r.m.collides ? (*r.m.collides ? "1" : "0") : "",
                   r.m.outcome == kNoGroundTruthOutcome ? ""
                   : r.m.exact_collides                 ? "1"
                                                        : "0",
                   std::to_string(r.m.intervals),
                   r.m.outcome == kNoGroundTruthOutcome ? "" : std::to_string(r.m.exact_intervals),
                   std::to_string(r.m.missed_contacts),
                   std::to_string(r.m.false_contacts),
                   opt(r.m.first_contact_err),
                   opt(r.m.endpoint_err),
                   fmt(r.time_us, "%.1f"),
                   r.m.structure_ok ? "1" : "0",
                   r.input,
                   s.digits ? std::to_string(s.digits) : "",
                   csv_text(r.reason),
                   opt(r.coef_err_common),
                   r.guard,
                   r.m.outcome == kNoGroundTruthOutcome ? ""
                   : r.m.exact_touch                    ? "1"
                                                        : "0",
                   r.second_look ? std::to_string(*r.second_look) : ""});
}

}  // namespace eccd

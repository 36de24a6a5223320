// The harness on cycloidal and independent scenes (compare/harness_families.hpp).
#include "compare/harness_families.hpp"

#include "compare/csv.hpp"
#include "kernel/budget.hpp"
#include "kernel/cycloidal_motion.hpp"

#include <stdexcept>

namespace eccd {

namespace {

bool cycloidal_scene(const Scene& s) { return s.dim == 2 && !s.independent && has_cycloidal_motion(s); }

PipelineSpec spec(const std::string& arith, const std::string& variant, const std::string& basis,
                  const std::string& method, const std::string& input) {
  PipelineSpec p;
  p.opt.arith = parse_arithmetic(arith);
  p.label = arith == "exact" || arith == "certified" ? arith : arith + "/" + variant;
  p.arith = p.opt.arith.kind == Arithmetic::Exact       ? "exact"
            : p.opt.arith.kind == Arithmetic::Certified ? "certified"
            : p.opt.arith.kind == Arithmetic::Mpfr      ? "mpfr"
                                                        : "double";
  p.bits = p.opt.arith.floating() ? p.opt.arith.precision_bits() : 0;
  p.basis = basis;
  p.method = method;
  p.input = input;
  if (p.opt.arith.floating()) apply_input_mode(p.opt, input);
  return p;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& x : v)
    if (!x.empty() && out.find(x) == std::string::npos) out += (out.empty() ? "" : "; ") + x;
  return out;
}

}  // namespace

bool motion_family_scene(const Scene& s) { return s.independent || cycloidal_scene(s); }

std::vector<PipelineSpec> motion_family_pipelines(const Scene& s, const HarnessOptions& o) {
  std::vector<PipelineSpec> v;
  // Each floating pipeline in the faces asked for; a cycloidal one in the guarded face only (api/solve.cpp).
  auto add = [&](const PipelineSpec& p, bool guarded_only) {
    std::vector<std::string> faces = o.guards;
    if (guarded_only) faces = {"bound"};
    for (const PipelineSpec& f : in_faces(p, faces)) v.push_back(f);
  };
  if (cycloidal_scene(s)) {
    v.push_back(spec("certified", "", "none", "ladder", "prepared"));
    add(spec("double", "cycloidal", "pointwise", "cd-disc-cycloidal", "rounded"), true);
    for (int b : o.mpfr_bits)
      add(spec("mpfr:" + std::to_string(b), "cycloidal", "pointwise", "cd-disc-cycloidal", "rounded"), true);
  } else {
    v.push_back(spec("exact", "", "exact", "balls-exact", "prepared"));
    add(spec("double", "independent", "bernstein", "bezier-independent", "prepared"), false);
    for (int b : o.mpfr_bits)
      add(spec("mpfr:" + std::to_string(b), "independent", "bernstein", "bezier-independent", "prepared"), false);
  }
  return v;
}

std::vector<ResultRow> run_motion_family_scene(const Scene& s, const SceneInfo& info0, const HarnessOptions& opt) {
  SceneInfo info = info0;
  if (info.degree < 1) info.degree = 1;  // a cycloidal case: linear translation, transcendental rotation (as generated)
  const std::vector<PipelineSpec> pipes = motion_family_pipelines(s, opt);
  // The ground truth: certified (cycloidal) or exact (independent); none when it is refused or leaves something
  // undecided.
  std::optional<Solution> truth;
  std::string no_truth;
  {
    ScopedDeadline budget(opt.exact_budget_s);  // BudgetExhausted: no ground truth, the scene fails (as in run_scene)
    try {
      truth = solve(s, pipes[0].opt);
    } catch (const std::invalid_argument& e) {
      no_truth = std::string(kNoGroundTruthReason) + pipes[0].label + " refuses the scene: " + e.what();
    }
  }
  if (truth && !truth->answer.undecided.empty()) {
    no_truth = std::string(kNoGroundTruthReason) + "the " + pipes[0].label + " answer leaves " +
               std::to_string(truth->answer.undecided.size()) + " instant(s) undecided (" +
               joined(truth->undecided_reasons) + ")";
  }
  std::vector<ResultRow> rows;
  for (std::size_t k = 0; k < pipes.size(); ++k) {
    const PipelineSpec& ps = pipes[k];
    ResultRow row = pipeline_row(info, ps);
    BoundedRun br;
    if (k == 0) {
      if (truth)
        br.got = *truth;
      else
        br.error = no_truth.substr(std::string(kNoGroundTruthReason).size());
    } else {
      // Independent runs stay in this process: their pipeline asks the deadline, and an undecided floating answer
      // (s-intervals found, t-intervals not yet) does not survive the child's JSON round trip (the answer reader
      // refuses collides without t-intervals), which would turn an undecided row into an error.
      br = run_bounded(s, ps.opt, opt.budget_s, opt.isolate && !s.independent);
    }
    if (!no_truth.empty()) {
      // What the pipeline said, with nothing to compare it with: never counted right or wrong.
      fill_row_from_run(row, std::move(br), Answer{});
      row.m.outcome = kNoGroundTruthOutcome;
      row.m.first_contact_err.reset();
      row.m.endpoint_err.reset();
      row.m.structure_ok = false;
      row.m.missed_contacts = row.m.false_contacts = 0;
      row.reason = no_truth + (row.reason.empty() || k == 0 ? "" : "; the run: " + row.reason);
    } else {
      fill_row_from_run(row, std::move(br), truth->answer);
      if (k == 0 && ps.arith == "certified")
        row.reason =
            "ground truth: the certified answer (cycloidal motion: no exact answer exists); compared with itself";
    }
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json no_ground_truth_meta(const std::vector<std::string>& csv_rows) {
  // the fields scene (0), outcome (15) and reason (28) of results_csv_header()
  nlohmann::json list = nlohmann::json::array();
  std::string last;
  for (const auto& line : csv_rows) {
    std::vector<std::string> f = csv_split(line, "results.csv row");
    if (f.size() < 29 || f[15] != kNoGroundTruthOutcome || f[0] == last) continue;
    last = f[0];
    list.push_back({{"scene", f[0]}, {"reason", f[28]}});
  }
  return {{"scenes", list.size()}, {"list", list}};
}

}  // namespace eccd

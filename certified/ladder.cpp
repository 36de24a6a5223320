// The certified ladder (certified/ladder.hpp).
#include "certified/ladder.hpp"

#include "certified/certified_policy.hpp"
#include "exact/cd_disc_exact.hpp"
#include "kernel/ccd_projection.hpp"
#include "kernel/cycloidal_cd_disc.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

namespace eccd {

namespace {

// What every run of the ladder is: method "cd-disc" in 2D, "projection" in 3D.
template <int N>
Solution& named(Solution& s, const char* basis, bool certified) {
  s.basis = basis;
  s.method = N == 4 ? "projection" : "cd-disc";
  s.certified = certified;
  return s;
}

// One rung: the pipeline in interval type T (Interval or MpfiInterval) with
// subdivision down to 2^-max_depth. A Solution if it decided everything;
// otherwise nothing, with `reason` set and `multiple_root` if it met one.
template <class T, int N>
std::optional<Solution> try_certified_rung(const PreparedPair<N>& p, Variant variant, bool first_contact, const T& like,
                                           int max_depth, std::string& reason, bool& multiple_root) {
  try {
    CertifiedPolicy<T> pol(like);
    pol.max_depth = max_depth;
    PipelineResult<T> r = projection_pipeline(to_arithmetic<T, N>(p, like), pol, variant, first_contact);
    if (r.answer.undecided.empty()) {
      Solution s = solution_of(r, N - 1);
      s.work.emplace_back("interval_pieces", pol.pieces);
      return named<N>(s, "bernstein", true);
    }
    reason = std::to_string(r.answer.undecided.size()) + " instant(s) undecided";
  } catch (const Escalate& e) {
    reason = e.what();
    multiple_root = e.kind == Escalate::multiple_root;
  }
  return std::nullopt;
}

}  // namespace

template <int N>
Solution run_exact(const PreparedPair<N>& p, Variant variant, bool first_contact) {
  ExactPolicy pol;
  Solution s = solution_of(projection_pipeline(to_arithmetic<Rational, N>(p, Rational(1)), pol, variant, first_contact), N - 1);
  return named<N>(s, "exact", true);
}

template <int N>
Solution run_certified(const PreparedPair<N>& p, const std::vector<int>& mpfi_rungs, Variant variant, bool first_contact) {
  auto start = std::chrono::steady_clock::now();
  std::vector<Escalation> escalations;
  auto finish = [&](Solution s, const std::string& rung) {
    s.escalations = escalations;
    s.decided_in = rung;
    s.certified = true;
    s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
    return s;
  };
  std::string reason;
  bool multiple_root = false;
  if (auto s = try_certified_rung<Interval, N>(p, variant, first_contact, Interval(0), 48, reason, multiple_root))
    return finish(*s, "interval");
  escalations.push_back({"interval", reason});
  for (int bits : mpfi_rungs) {
    if (multiple_root) {  // no precision separates a multiple root: straight to exact
      escalations.push_back({"mpfi:" + std::to_string(bits), "skipped: the rung below met a multiple root"});
      break;
    }
    // Deeper subdivision at higher precision (roots closer than 2^-48 can be
    // told apart when the coefficients are known to `bits` bits), but not so
    // deep that a true multiple root (every touch scene) costs much before
    // the exact rung: 2^-64 at the default 256 bits.
    int depth = std::clamp(bits / 4, 48, 256);
    std::string rung = "mpfi:" + std::to_string(bits);
    if (auto s = try_certified_rung<MpfiInterval, N>(p, variant, first_contact, MpfiInterval(Rational(0), bits), depth,
                                                     reason, multiple_root))
      return finish(*s, rung);
    escalations.push_back({rung, reason});
  }
  return finish(run_exact<N>(p, variant, first_contact), "exact");
}

Solution run_certified_cycloidal(const Scene& scene, const std::vector<int>& mpfi_rungs, Variant variant) {
  auto start = std::chrono::steady_clock::now();
  std::vector<int> rungs = mpfi_rungs.empty() ? std::vector<int>{128} : mpfi_rungs;
  std::vector<Escalation> escalations;
  Solution s;
  std::string rung;
  for (std::size_t i = 0; i < rungs.size(); ++i) {
    const int bits = rungs[i];
    rung = "mpfi:" + std::to_string(bits);
    MpfiInterval like(Rational(0), bits);
    CycloidalOptions co;
    co.certified = true;
    co.max_depth = std::clamp(bits / 2, 24, 200);
    co.refine_bits = 64;  // brackets of width 2^-64 where the signs are proved that far
    s = solution_of(cycloidal_cd_disc(cycloidal_pair<MpfiInterval>(scene, like), like, co, variant), 2);
    if (s.answer.undecided.empty() || i + 1 == rungs.size()) break;
    escalations.push_back({rung, std::to_string(s.answer.undecided.size()) + " instant(s) undecided"});
  }
  s.escalations = escalations;
  s.decided_in = rung;
  // Every bracket and status is proved; an undecided stretch is named as such
  // (never a claimed touch), so the run is certified only if none is left.
  s.certified = s.answer.undecided.empty();
  s.basis = "pointwise";
  s.method = "cd-disc-cycloidal";
  s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  return s;
}

template Solution run_exact<3>(const PreparedPair<3>&, Variant, bool);
template Solution run_exact<4>(const PreparedPair<4>&, Variant, bool);
template Solution run_certified<3>(const PreparedPair<3>&, const std::vector<int>&, Variant, bool);
template Solution run_certified<4>(const PreparedPair<4>&, const std::vector<int>&, Variant, bool);

}  // namespace eccd

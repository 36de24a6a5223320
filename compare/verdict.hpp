#pragma once
// Verdicts: how a floating pipeline's answer differs from the certified one,
// in words a user can act on ("missed contact near t ∈ [lo, hi]", "false
// contact", "end of collision interval 2 off by 1.3e-3", "wrong collides").
//
// Statement. Both answers are in the spec's form (scene-format.md, "The
// answer"). Floating instants are compared through their decimal `approx`
// (they are not certified); the certified answer's instants through their
// approx too, which is within 2^-64 of the instant, far below any tolerance
// used here. An interval of one answer matches an interval of the other when
// they overlap after widening by tol. The verdict is "agrees" when collides is
// the same, every certified interval is matched by exactly one reported
// interval and vice versa, every interval end is within tol, the contacts
// match one to one within tol, the numbers of contact intervals (continuous
// touching) are the same, and nothing is left undecided.
// This is reporting, not deciding: doubles are fine here (design.md).
#include "kernel/answer.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct Verdict {
  std::string pipeline;
  bool agrees = false;
  std::string error;                      // the pipeline failed (exception message)
  std::vector<std::string> differences;   // empty iff agrees (and no error)
  std::optional<double> max_endpoint_error;
  double time_ms = 0;
  // Counters for tables (eccd regress --floating).
  bool wrong_collides = false;
  int missed = 0, spurious = 0, endpoints_off = 0, undecided = 0;

  nlohmann::json to_json() const {
    nlohmann::json j = {{"pipeline", pipeline}, {"agrees", agrees}, {"differences", differences}, {"time_ms", time_ms}};
    j["max_endpoint_error"] = max_endpoint_error ? nlohmann::json(*max_endpoint_error) : nlohmann::json(nullptr);
    if (!error.empty()) j["error"] = error;
    return j;
  }
  // "agrees (endpoints within 8.3e-16)" or "differs: ...; ..."
  std::string text() const {
    if (!error.empty()) return "failed: " + error;
    char buf[64];
    if (agrees) {
      if (!max_endpoint_error) return "agrees";
      std::snprintf(buf, sizeof buf, "agrees (interval ends within %.2g)", *max_endpoint_error);
      return buf;
    }
    std::string s = "differs: ";
    for (std::size_t i = 0; i < differences.size(); ++i) s += (i ? "; " : "") + differences[i];
    return s;
  }
};

namespace verdict_detail {
inline double value(const nlohmann::json& i) { return std::stod(i.at("approx").get<std::string>()); }
inline std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.10g", x);
  return b;
}
inline std::string gnum(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.2g", x);
  return b;
}
// "near t ∈ [lo, hi]" from a certified instant (decimals of its bracket), else "near t ≈ x".
inline std::string near(const nlohmann::json& i) {
  if (i.contains("lo") && i["lo"].is_string() && i["lo"] != i["hi"]) {
    return "near t ∈ [" + decimal_string(mpq_class(i["lo"].get<std::string>()), 12) + ", " +
           decimal_string(mpq_class(i["hi"].get<std::string>()), 12) + "]";
  }
  return "near t ≈ " + num(value(i));
}
struct Span {
  double a, b;
  const nlohmann::json* ja;
  const nlohmann::json* jb;
};
inline std::vector<Span> spans(const nlohmann::json& list) {
  std::vector<Span> v;
  if (list.is_array())
    for (const auto& iv : list) v.push_back({value(iv[0]), value(iv[1]), &iv[0], &iv[1]});
  return v;
}
inline std::string span_text(const Span& s) {
  if (s.a == s.b) return "contact " + near(*s.ja);
  return "collision interval [" + num(s.a) + ", " + num(s.b) + "]";
}
}  // namespace verdict_detail

// got: a pipeline's JSON (eccd solve); certified: the certified answer's JSON.
inline Verdict judge(const std::string& pipeline, const nlohmann::json& got, const nlohmann::json& certified, double tol) {
  using namespace verdict_detail;
  Verdict v;
  v.pipeline = pipeline;
  if (got.contains("time_ms")) v.time_ms = got["time_ms"].get<double>();
  if (got.contains("error")) {
    v.error = got["error"].get<std::string>();
    return v;
  }
  bool gc = got.at("collides").get<bool>(), ec = certified.at("collides").get<bool>();
  if (gc != ec) {
    v.wrong_collides = true;
    v.differences.push_back(std::string("wrong collides: says ") + (gc ? "they collide" : "they never collide"));
  }
  auto G = spans(got["intervals"]), E = spans(certified["intervals"]);
  auto overlap = [tol](const Span& x, const Span& y) { return x.a <= y.b + tol && y.a <= x.b + tol; };
  double worst = 0;
  bool all_matched = true;
  // Instants already reported through an interval (missed, false or end off):
  // a contact there is not reported a second time.
  std::vector<double> flagged_exact, flagged_got;
  for (std::size_t k = 0; k < E.size(); ++k) {
    std::vector<std::size_t> m;
    for (std::size_t i = 0; i < G.size(); ++i)
      if (overlap(G[i], E[k])) m.push_back(i);
    if (m.empty()) {
      all_matched = false;
      ++v.missed;
      v.differences.push_back("missed " + span_text(E[k]));
      flagged_exact.insert(flagged_exact.end(), {E[k].a, E[k].b});
      continue;
    }
    if (m.size() > 1) {
      all_matched = false;
      v.differences.push_back("splits " + span_text(E[k]) + " into " + std::to_string(m.size()) + " intervals");
      continue;
    }
    const Span& g = G[m[0]];
    double ds = std::abs(g.a - E[k].a), de = std::abs(g.b - E[k].b);
    worst = std::max({worst, ds, de});
    std::string which = "collision interval " + std::to_string(k + 1);
    if (ds > tol) {
      ++v.endpoints_off;
      v.differences.push_back("start of " + which + " off by " + gnum(ds) + " (" + num(g.a) + " vs " + num(E[k].a) + ")");
      flagged_exact.push_back(E[k].a);
      flagged_got.push_back(g.a);
    }
    if (de > tol) {
      ++v.endpoints_off;
      v.differences.push_back("end of " + which + " off by " + gnum(de) + " (" + num(g.b) + " vs " + num(E[k].b) + ")");
      flagged_exact.push_back(E[k].b);
      flagged_got.push_back(g.b);
    }
  }
  for (std::size_t i = 0; i < G.size(); ++i) {
    int n = 0;
    for (const auto& e : E) n += overlap(G[i], e);
    if (n == 0) {
      ++v.spurious;
      all_matched = false;
      v.differences.push_back("false " + (G[i].a == G[i].b ? "contact near t ≈ " + num(G[i].a) : span_text(G[i])));
      flagged_got.insert(flagged_got.end(), {G[i].a, G[i].b});
    } else if (n > 1) {
      all_matched = false;
      v.differences.push_back("merges " + std::to_string(n) + " collision intervals into [" + num(G[i].a) + ", " + num(G[i].b) + "]");
    }
  }
  auto in = [](const std::vector<double>& v, double x) { return std::find(v.begin(), v.end(), x) != v.end(); };
  // External contacts, matched one to one within tol.
  std::vector<double> gcs, ecs;
  if (got["contacts"].is_array()) for (const auto& c : got["contacts"]) gcs.push_back(value(c));
  std::vector<bool> used(gcs.size(), false);
  if (certified["contacts"].is_array())
    for (const auto& c : certified["contacts"]) {
      double x = value(c);
      int best = -1;
      for (std::size_t i = 0; i < gcs.size(); ++i)
        if (!used[i] && std::abs(gcs[i] - x) <= tol && (best < 0 || std::abs(gcs[i] - x) < std::abs(gcs[best] - x))) best = int(i);
      if (best >= 0) used[best] = true;
      else if (!in(flagged_exact, x)) { ++v.missed; v.differences.push_back("missed contact " + near(c)); }
    }
  for (std::size_t i = 0; i < gcs.size(); ++i)
    if (!used[i] && !in(flagged_got, gcs[i])) { ++v.spurious; v.differences.push_back("false contact near t ≈ " + num(gcs[i])); }
  // Continuous touching (docs/answer-format.md): the count must match, else a
  // continuous touch was reported as an overlap (or the reverse).
  auto ncontact_intervals = [](const nlohmann::json& a) {
    return a.contains("contact_intervals") && a["contact_intervals"].is_array() ? a["contact_intervals"].size() : std::size_t(0);
  };
  if (std::size_t e = ncontact_intervals(certified), g = ncontact_intervals(got); e != g) {
    if (e > g) v.missed += int(e - g);
    else v.spurious += int(g - e);
    v.differences.push_back("reports " + std::to_string(g) + " interval(s) of continuous touching, the certified answer " + std::to_string(e));
  }
  if (got.contains("undecided") && got["undecided"].is_array())
    for (const auto& u : got["undecided"]) { ++v.undecided; v.differences.push_back("undecided near t ≈ " + num(value(u))); }
  if (all_matched && !E.empty()) v.max_endpoint_error = worst;
  v.agrees = v.differences.empty();
  return v;
}

}  // namespace eccd

// The one comparison of two answers: api/answer_difference.hpp.
#include "api/answer_difference.hpp"

#include "io/scene_reader.hpp"  // parse_rational: a decimal read exactly

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace eccd {

namespace {

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.10g", x);
  return b;
}
std::string gnum(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.2g", x);
  return b;
}

// The exact value of an instant's decimal (its text if it parses, else its double).
std::optional<Rational> decimal_value(const Instant& i) {
  try {
    return parse_rational(i.approx);
  } catch (const std::invalid_argument&) {}
  if (std::isfinite(i.value)) return Rational(i.value);
  return std::nullopt;
}

// "t ∈ [lo, hi]" for a certified instant with a proper bracket, the exact value
// for a rational one, else "t ≈ x".
std::string where(const Instant& i) {
  if (i.certified()) {
    if (*i.lo == *i.hi) return "t = " + i.lo->get_str();
    return "t ∈ [" + decimal_string(*i.lo, 12) + ", " + decimal_string(*i.hi, 12) + "]";
  }
  return "t ≈ " + num(i.value);
}

struct Span {
  const Instant* a;
  const Instant* b;
  double lo() const { return a->certified() ? a->lo->get_d() : a->value; }  // reporting only
  double hi() const { return b->certified() ? b->hi->get_d() : b->value; }
  bool point() const { return a->approx == b->approx && a->lo == b->lo && a->hi == b->hi; }
};

std::string span_text(const Span& s, const std::string& noun = "collision interval") {
  if (s.point()) return (noun == "collision interval" ? "contact near " : noun + " (a point) near ") + where(*s.a);
  return noun + " [" + num(s.a->value) + ", " + num(s.b->value) + "]";
}

std::vector<Span> spans(const std::vector<std::pair<Instant, Instant>>& list) {
  std::vector<Span> v;
  for (const auto& [a, b] : list) v.push_back({&a, &b});
  return v;
}

}  // namespace

bool instants_match(const Instant& a, const Instant& b, double tol) {
  if (a.certified() && b.certified()) return !(*a.hi < *b.lo) && !(*b.hi < *a.lo);
  if (a.certified() || b.certified()) {
    const Instant& c = a.certified() ? a : b;
    const Instant& d = a.certified() ? b : a;
    std::optional<Rational> x = decimal_value(d);
    if (!x) return false;
    Rational slack(std::isfinite(tol) && tol > 0 ? tol : 0.0);
    return !(*x < Rational(*c.lo - slack)) && !(Rational(*c.hi + slack) < *x);
  }
  return std::isfinite(a.value) && std::isfinite(b.value) && std::abs(a.value - b.value) <= tol;
}

namespace {

// Instants reported through an interval already (of the reference, of the answer).
struct Flagged {
  std::vector<const Instant*> ref, got;
};

bool reported(const std::vector<const Instant*>& list, const Instant& x, double tol) {
  return std::any_of(list.begin(), list.end(), [&](const Instant* f) { return instants_match(*f, x, tol); });
}

std::string yes(bool b) { return std::string(b ? "true" : "false"); }

// The ends of a one-to-one pair of intervals (answer g, reference e, the k-th); returns the larger end's distance.
double compare_ends(AnswerDifference& d, const DifferenceOptions& opt, const Span& g, const Span& e, std::size_t k,
                    const std::string& noun, Flagged& flagged) {
  const std::string which = noun + " " + std::to_string(k + 1);
  double worst = 0;
  for (int end = 0; end < 2; ++end) {
    const Instant& x = end ? *g.b : *g.a;
    const Instant& y = end ? *e.b : *e.a;
    const double off = std::abs(x.value - y.value);
    if (std::isfinite(off)) worst = std::max(worst, off);
    if (!instants_match(x, y, opt.tol)) {
      ++d.endpoints_off;
      d.differences.push_back(which + (end ? " end" : " start") + " off by " + gnum(off) + " (" + opt.reference_name +
                              " " + num(y.value) + ", " + opt.answer_name + " " + num(x.value) + ")");
      flagged.ref.push_back(&y);
      flagged.got.push_back(&x);
    }
  }
  return worst;
}

// The matching of interval lists (collision intervals; for independent motions the s- and t-intervals, each matched
// the same way). noun names them. Intervals: correspondence by overlap, then the ends of one-to-one pairs.
void match_intervals(AnswerDifference& d, const DifferenceOptions& opt,
                     const std::vector<std::pair<Instant, Instant>>& got_list,
                     const std::vector<std::pair<Instant, Instant>>& ref_list, const std::string& noun,
                     Flagged& flagged) {
  const double tol = opt.tol;
  auto G = spans(got_list), E = spans(ref_list);
  auto overlap = [tol](const Span& x, const Span& y) { return x.lo() <= y.hi() + tol && y.lo() <= x.hi() + tol; };
  double worst = 0;
  bool one_to_one = true;
  for (std::size_t k = 0; k < E.size(); ++k) {
    std::vector<std::size_t> m;
    for (std::size_t i = 0; i < G.size(); ++i)
      if (overlap(G[i], E[k])) m.push_back(i);
    if (m.empty()) {
      one_to_one = false;
      ++d.missed;
      d.differences.push_back("missed " + span_text(E[k], noun));
      flagged.ref.insert(flagged.ref.end(), {E[k].a, E[k].b});
      continue;
    }
    if (m.size() > 1) {
      one_to_one = false;
      ++d.split;
      d.differences.push_back("splits " + span_text(E[k], noun) + " into " + std::to_string(m.size()) + " intervals");
      flagged.ref.insert(flagged.ref.end(), {E[k].a, E[k].b});
      continue;
    }
    worst = std::max(worst, compare_ends(d, opt, G[m[0]], E[k], k, noun, flagged));
  }
  for (std::size_t i = 0; i < G.size(); ++i) {
    int n = 0;
    for (const auto& e : E) n += overlap(G[i], e);
    if (n == 0) {
      one_to_one = false;
      ++d.spurious;
      d.differences.push_back("false " + span_text(G[i], noun));
      flagged.got.insert(flagged.got.end(), {G[i].a, G[i].b});
    } else if (n > 1) {
      one_to_one = false;
      ++d.merged;
      d.differences.push_back("merges " + std::to_string(n) + " " + noun + "s into [" + num(G[i].a->value) + ", " +
                              num(G[i].b->value) + "]");
      flagged.got.insert(flagged.got.end(), {G[i].a, G[i].b});
    }
  }
  if (one_to_one && !E.empty()) d.max_endpoint_error = std::max(d.max_endpoint_error.value_or(0.0), worst);
}

void compare_first_contact(AnswerDifference& d, const DifferenceOptions& opt, const Answer& got, const Answer& ref,
                           const Flagged& flagged) {
  const std::string& A = opt.answer_name;
  const std::string& R = opt.reference_name;
  if (got.first_contact && ref.first_contact) {
    d.first_contact_error = std::abs(got.first_contact->value - ref.first_contact->value);
    if (!instants_match(*got.first_contact, *ref.first_contact, opt.tol) &&
        !reported(flagged.ref, *ref.first_contact, opt.tol))
      d.differences.push_back("first contact off by " + gnum(*d.first_contact_error) + " (" + R + " " +
                              num(ref.first_contact->value) + ", " + A + " " + num(got.first_contact->value) + ")");
  } else if (got.first_contact.has_value() != ref.first_contact.has_value()) {
    d.differences.push_back("first contact: " + R + " " + (ref.first_contact ? where(*ref.first_contact) : "none") +
                            ", " + A + " " + (got.first_contact ? where(*got.first_contact) : "none"));
  }
}

// External contacts, one to one, nearest first.
void compare_contacts(AnswerDifference& d, const DifferenceOptions& opt, const Answer& got, const Answer& ref,
                      const Flagged& flagged) {
  const double tol = opt.tol;
  std::vector<bool> used(got.contacts.size(), false);
  for (const auto& c : ref.contacts) {
    int best = -1;
    for (std::size_t i = 0; i < got.contacts.size(); ++i)
      if (!used[i] && instants_match(got.contacts[i], c, tol) &&
          (best < 0 || std::abs(got.contacts[i].value - c.value) < std::abs(got.contacts[best].value - c.value)))
        best = int(i);
    if (best >= 0) {
      used[best] = true;
      continue;
    }
    ++d.missed_contacts;
    if (!reported(flagged.ref, c, tol)) {
      ++d.missed;
      d.differences.push_back("missed contact near " + where(c));
    }
  }
  for (std::size_t i = 0; i < got.contacts.size(); ++i) {
    if (used[i]) continue;
    ++d.false_contacts;
    if (!reported(flagged.got, got.contacts[i], tol)) {
      ++d.spurious;
      d.differences.push_back("false contact near " + where(got.contacts[i]));
    }
  }
}

// Continuous touching.
void compare_contact_intervals(AnswerDifference& d, const DifferenceOptions& opt, const Answer& got,
                               const Answer& ref) {
  const std::string& A = opt.answer_name;
  const std::string& R = opt.reference_name;
  if (got.contact_intervals.size() != ref.contact_intervals.size()) {
    d.contact_intervals_differ = 1;
    const std::size_t e = ref.contact_intervals.size(), g = got.contact_intervals.size();
    if (e > g)
      d.missed += int(e - g);
    else
      d.spurious += int(g - e);
    d.differences.push_back("contact_intervals: " + R + " " + std::to_string(e) + ", " + A + " " + std::to_string(g) +
                            " (intervals of continuous touching)");
    return;
  }
  for (std::size_t i = 0; i < got.contact_intervals.size(); ++i) {
    const auto &s = ref.contact_intervals[i], &g = got.contact_intervals[i];
    if (instants_match(s.first, g.first, opt.tol) && instants_match(s.second, g.second, opt.tol)) continue;
    ++d.contact_intervals_differ;
    d.differences.push_back("contact interval " + std::to_string(i + 1) + ": " + R + " [" + num(s.first.value) + ", " +
                            num(s.second.value) + "], " + A + " [" + num(g.first.value) + ", " + num(g.second.value) +
                            "]");
  }
}

}  // namespace

AnswerDifference answer_difference(const Answer& got, const Answer& ref, const DifferenceOptions& opt) {
  AnswerDifference d;
  const std::string& A = opt.answer_name;
  const std::string& R = opt.reference_name;
  d.intervals = int(got.intervals.size());
  d.reference_intervals = int(ref.intervals.size());

  // What each answer claims (kernel/answer.hpp collides_claim): an answer with undecided stretches that proves no
  // collision claims nothing, and is undecided there, not wrong.
  const std::optional<bool> got_claim = collides_claim(got), ref_claim = collides_claim(ref);
  if (got_claim && ref_claim && *got_claim != *ref_claim) {
    d.collides_differs = true;
    d.differences.push_back("collides: " + R + " " + yes(*ref_claim) + ", " + A + " " + yes(*got_claim));
  }
  if (got.independent != ref.independent) {
    d.differences.push_back(std::string("kind: ") + R + " is an answer of " +
                            (ref.independent ? "independent" : "shared-parameter") + " motions, " + A + " of " +
                            (got.independent ? "independent" : "shared-parameter") + " motions");
    d.agrees = false;
    return d;
  }

  Flagged flagged;
  if (got.independent) {
    d.intervals = int(got.s_intervals.size() + got.t_intervals.size());
    d.reference_intervals = int(ref.s_intervals.size() + ref.t_intervals.size());
    match_intervals(d, opt, got.s_intervals, ref.s_intervals, "s-interval", flagged);
    match_intervals(d, opt, got.t_intervals, ref.t_intervals, "t-interval", flagged);
    for (const auto& u : got.undecided) {
      ++d.undecided;
      d.differences.push_back("undecided near " + num(u.value));
    }
    d.agrees = d.differences.empty();
    return d;
  }
  match_intervals(d, opt, got.intervals, ref.intervals, "collision interval", flagged);
  compare_first_contact(d, opt, got, ref, flagged);
  compare_contacts(d, opt, got, ref, flagged);
  compare_contact_intervals(d, opt, got, ref);
  for (const auto& u : got.undecided) {
    ++d.undecided;
    d.differences.push_back("undecided near t ≈ " + num(u.value));
  }
  d.agrees = d.differences.empty();
  return d;
}

}  // namespace eccd

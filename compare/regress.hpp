#pragma once
// Regression against stored exact answers (eccd regress, and the CI test).
//
// Statement (issue 5): a stored answer and a recomputed exact answer agree when
// they have the same `collides`, the same number of collision intervals, of
// external contacts and of contact intervals (continuous touching; a stored
// answer without the key has none), and each recomputed bracket overlaps the
// stored one (intervals' starts and ends, first contact, contacts, contact
// intervals' ends). Two certified
// brackets that overlap may still hold different instants in principle; but a
// bracket of the recomputed answer holds exactly one root of the projection,
// so a stored bracket that overlaps it and is itself certified cannot be off
// by more than the two widths (2^-64 each by default). A stored instant
// without a bracket is compared by its decimal: the recomputed bracket,
// widened by 1e-12, must contain it.
// Decisions use exact rationals (brackets); the decimal fallback is a report.
#include "kernel/answer.hpp"
#include "io/scene_reader.hpp"

#include <string>
#include <vector>

namespace eccd {

namespace regress_detail {
inline bool matches(const Instant& stored, const Instant& got) {
  if (!got.certified()) return false;
  if (stored.certified()) return !(*stored.hi < *got.lo) && !(*got.hi < *stored.lo);
  Rational x;
  try {
    x = parse_rational(stored.approx);
  } catch (const std::invalid_argument&) {
    return false;
  }
  Rational slack(mpz_class(1), mpz_class("1000000000000"));  // 1e-12
  slack.canonicalize();
  return !(x < Rational(*got.lo - slack)) && !(Rational(*got.hi + slack) < x);
}
inline std::string show(const Instant& i) {
  if (!i.certified()) return i.approx;
  if (*i.lo == *i.hi) return i.lo->get_str();
  return i.approx + " in [" + i.lo->get_str() + ", " + i.hi->get_str() + "]";
}
}  // namespace regress_detail

// The differences, in words; empty when the answers agree.
inline std::vector<std::string> answer_differences(const Answer& stored, const Answer& got) {
  using regress_detail::matches;
  using regress_detail::show;
  std::vector<std::string> d;
  if (stored.collides != got.collides)
    d.push_back(std::string("collides: stored ") + (stored.collides ? "true" : "false") + ", recomputed " + (got.collides ? "true" : "false"));
  if (stored.intervals.size() != got.intervals.size()) {
    d.push_back("intervals: stored " + std::to_string(stored.intervals.size()) + ", recomputed " + std::to_string(got.intervals.size()));
  } else {
    for (std::size_t i = 0; i < got.intervals.size(); ++i) {
      if (!matches(stored.intervals[i].first, got.intervals[i].first))
        d.push_back("interval " + std::to_string(i + 1) + " start: stored " + show(stored.intervals[i].first) + ", recomputed " + show(got.intervals[i].first));
      if (!matches(stored.intervals[i].second, got.intervals[i].second))
        d.push_back("interval " + std::to_string(i + 1) + " end: stored " + show(stored.intervals[i].second) + ", recomputed " + show(got.intervals[i].second));
    }
  }
  if (stored.first_contact.has_value() != got.first_contact.has_value())
    d.push_back(std::string("first_contact: stored ") + (stored.first_contact ? show(*stored.first_contact) : "null") + ", recomputed " +
                (got.first_contact ? show(*got.first_contact) : "null"));
  else if (got.first_contact && !matches(*stored.first_contact, *got.first_contact))
    d.push_back("first_contact: stored " + show(*stored.first_contact) + ", recomputed " + show(*got.first_contact));
  if (stored.contacts.size() != got.contacts.size()) {
    d.push_back("contacts: stored " + std::to_string(stored.contacts.size()) + ", recomputed " + std::to_string(got.contacts.size()));
  } else {
    for (std::size_t i = 0; i < got.contacts.size(); ++i)
      if (!matches(stored.contacts[i], got.contacts[i]))
        d.push_back("contact " + std::to_string(i + 1) + ": stored " + show(stored.contacts[i]) + ", recomputed " + show(got.contacts[i]));
  }
  // Continuous touching (a stored answer without the key has none).
  if (stored.contact_intervals.size() != got.contact_intervals.size()) {
    d.push_back("contact_intervals: stored " + std::to_string(stored.contact_intervals.size()) + ", recomputed " +
                std::to_string(got.contact_intervals.size()));
  } else {
    for (std::size_t i = 0; i < got.contact_intervals.size(); ++i) {
      const auto &s = stored.contact_intervals[i], &g = got.contact_intervals[i];
      if (!matches(s.first, g.first) || !matches(s.second, g.second))
        d.push_back("contact interval " + std::to_string(i + 1) + ": stored [" + show(s.first) + ", " + show(s.second) + "], recomputed [" +
                    show(g.first) + ", " + show(g.second) + "]");
    }
  }
  return d;
}

}  // namespace eccd

#pragma once
// From a decided timeline over [0, 1] to the scene answer.
//
// Statement (scene-format.md, "The answer"; 003 section VI, 002 section III,
// 001 section 4). Every CCD method of the workbench ends the same way: the
// critical instants 0 = c_0 < c_1 < ... < c_m = 1 (roots of the projection
// polynomial, or contact instants found by Bézier shooting) split [0, 1] into
// open cells on which the status is constant. The timeline is the sequence
//   instant c_0, cell (c_0, c_1), instant c_1, ..., cell, instant c_m,
// each node with its status. The collision set C is the union of the nodes in
// collision (touching or overlapping); its maximal intervals are the maximal
// runs of such nodes. A run always starts and ends at an instant (a cell in C
// has its end instants in C, since C is closed); a run that starts or ends on
// a cell because of rounding is widened to the neighbouring instant.
// `contacts` are the touching instants; `undecided` the uncertain nodes.
// A touching cell (continuous touching, 3D e.g. two balls rolling on each
// other) gives a `contact_interval` over the cell's closure, runs merged; the
// touching instants inside it are not listed in `contacts`
// (docs/answer-format.md).
// Requirements: none on the arithmetic (statuses and display instants only).
#include "kernel/answer.hpp"
#include "kernel/contact_status.hpp"

#include <stdexcept>
#include <vector>

namespace eccd {

struct TimelineNode {
  Instant t;  // the instant, or for a cell its sample instant
  Status status;
  bool is_cell;
};

// An instant that is neither touching nor next to an overlapping cell
// contradicts the theory (the status can only change through a touch, and
// overlap is open in t). Exact arithmetic: an internal error. Rounded: the
// node becomes uncertain.
inline void check_isolated_instants(std::vector<TimelineNode>& seq, bool exact) {
  for (std::size_t k = 2; k + 2 < seq.size(); k += 2) {
    TimelineNode& n = seq[k];
    if (n.status == Status::overlapping && seq[k - 1].status == Status::separate &&
        seq[k + 1].status == Status::separate) {
      if (exact) throw std::logic_error("internal error: an isolated overlapping instant between separate cells");
      n.status = Status::uncertain;
    }
  }
}

// Fills ans (collides, intervals, first_contact, contacts, contact_intervals, undecided).
// on_contact(k) is called for each touching instant node k, in order.
template <class OnContact>
void assemble_answer(const std::vector<TimelineNode>& seq, Answer& ans, OnContact on_contact) {
  // Continuous touching (docs/answer-format.md): a touching cell makes a
  // contact interval from its left to its right instant (runs merged); the
  // instants inside such an interval are not isolated contacts.
  auto touching_cell = [&](std::size_t k) {
    return k < seq.size() && seq[k].is_cell && seq[k].status == Status::touching;
  };
  auto contact = [&](std::size_t k) {
    if (touching_cell(k + 1) || (k > 0 && touching_cell(k - 1))) return;
    ans.contacts.push_back(seq[k].t);
    on_contact(k);
  };
  for (std::size_t k = 0; k < seq.size(); ++k) {
    if (!touching_cell(k)) continue;
    std::size_t e = k;
    while (touching_cell(e + 2) && seq[e + 1].status == Status::touching) e += 2;
    ans.contact_intervals.push_back({k > 0 ? seq[k - 1].t : seq[k].t, e + 1 < seq.size() ? seq[e + 1].t : seq[e].t});
    k = e;
  }
  for (std::size_t k = 0; k < seq.size(); ++k) {
    const TimelineNode& n = seq[k];
    if (n.status == Status::uncertain) {
      ans.undecided.push_back(n.t);
      continue;
    }
    if (!n.is_cell && n.status == Status::touching) contact(k);
    if (!in_collision(n.status)) continue;
    std::size_t e = k;
    while (e + 1 < seq.size() && in_collision(seq[e + 1].status)) {
      ++e;
      if (!seq[e].is_cell && seq[e].status == Status::touching) contact(e);
    }
    const Instant& first = seq[k].is_cell ? seq[k - 1].t : seq[k].t;
    const Instant& last = seq[e].is_cell ? seq[e + 1].t : seq[e].t;
    ans.intervals.push_back({first, last});
    k = e;
  }
  ans.collides = !ans.intervals.empty();
  if (ans.collides) ans.first_contact = ans.intervals.front().first;
}

}  // namespace eccd

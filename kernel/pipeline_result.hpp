#pragma once
// PipelineResult<T>: what every pipeline run returns, in 2D and in 3D.
//
// Statement. CD-DISC (2D, 003; kernel/cd_disc.hpp), the projection CCD (3D,
// 002; kernel/ccd_projection.hpp), the Bézier zero-set method (3D, 001
// section 4; floating/bezier_ccd.hpp) and the sampled 3D baselines (002 IV;
// floating/ccd3_baselines.hpp) all return this one type, in every arithmetic
// T: the Answer (kernel/answer.hpp) that the harness compares, and the
// diagnostics of the run (f's coefficients g_k, the degree of the polynomial
// whose roots were the critical instants, the critical instants and cells
// with their status, the timeline, work counters, reasons for undecided
// parts, time). `projection_degree` is the degree of Δ in 2D, of the
// discriminant or psc_k in 3D (projection_index), and of the Bézier method's
// f in t; it is as built in the run's arithmetic and basis.
// Requirements on T: those of Poly<T> (kernel/polynomial.hpp).
#include "kernel/answer.hpp"
#include "kernel/bernstein.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/polynomial.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eccd {

// 003 section VI-C: 1 = collides?, 2 = first contact, 3 = all external
// contacts with contact points; 0 (default) = the scene answer.
enum class Variant { answer = 0, collides = 1, first_contact = 2, all_contacts = 3 };

template <class T>
struct PipelineResult {
  Answer answer;
  Variant variant = Variant::answer;
  std::vector<Poly<T>> g;      // g_0 .. g_N (g_3 in 2D, g_4 in 3D), power form
  int projection_degree = -1;  // degree of the projection (see above) as built in this arithmetic and basis
  bool projection_identically_zero = false;
  int projection_index = 0;  // 3D: 0 = discriminant, k = psc_k (kernel/ccd_projection.hpp)
  Status status_at_0 = Status::uncertain;
  struct Critical {
    Instant t;
    Status status;
    int multiplicity = 0;
  };
  std::vector<Critical> critical;  // roots of the projection in [0, 1] with their status
  struct Cell {
    Instant sample;
    Status status;
  };
  std::vector<Cell> cells;
  std::vector<TimelineNode> timeline;                  // instant, cell, ..., instant (kernel/collision_timeline.hpp)
  std::vector<std::pair<std::string, long>> counters;  // work done (method-specific)
  std::vector<std::string> undecided_reasons;          // floating: why the undecided instants are undecided
  double seconds = 0;
};

// Nothing can be decided (a non-finite value): the whole of [0, 1] is
// undecided, with the reason; never a confident answer.
template <class T>
void undecided_everywhere(PipelineResult<T>& res, const Instant& i0, const Instant& i1, const std::string& reason) {
  res.answer = Answer{};
  res.answer.collides = false;
  res.answer.undecided = {i0, i1};
  res.status_at_0 = Status::uncertain;
  res.timeline = {{i0, Status::uncertain, false}, {i0, Status::uncertain, true}, {i1, Status::uncertain, false}};
  res.cells = {{i0, Status::uncertain}};
  res.undecided_reasons.push_back(reason);
}

// The start of a 3D result from g_0..g_4 in Bernstein form: variant, and g in power form for reporting.
template <class T>
PipelineResult<T> result_from_bernstein(const std::vector<Bern<T>>& g, bool first_contact_only) {
  PipelineResult<T> res;
  res.variant = first_contact_only ? Variant::first_contact : Variant::answer;
  for (const auto& gi : g) res.g.push_back(to_power(gi));
  return res;
}

}  // namespace eccd

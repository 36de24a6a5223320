#pragma once
// Time left of a run of tasks of several kinds (`eccd report`'s progress line;
// issue 19, point 5).
//
// A report's tasks differ in cost by two orders of magnitude (a 3D scene of
// motion degree 6 takes about 20 s, a failure-map cell about 0.4 s), so the
// plain average "elapsed / done x left" is wrong whenever the mix of the tasks
// done differs from the mix of those left: with the expensive tasks first it
// overestimates by the ratio of the costs, with the cheap ones first it
// underestimates. Here each task has a kind (e.g. "3D deg 6", "case 2D",
// "map cell") and the work left is the sum over the tasks not finished of the
// mean measured cost of their kind. A kind with no finished task yet gets its
// prior (a rough relative cost, any unit) scaled by the ratio measured / prior
// over all finished tasks, so one measured kind calibrates the others.
// A running task counts with its expected cost minus the time it has run
// (not below zero), and it bounds its kind's cost from below while that kind
// has no finished task (a task that has run 5 s costs at least 5 s; early in
// a run, when one cheap kind calibrates the priors, this keeps the estimate of
// the expensive kinds from collapsing). The wall time left is the work left divided by the
// workers that still have something to do, and never less than the longest
// running task's expected rest.
//
// Pure: no clock, no I/O (tests/app/test_cli_report.cpp checks it on a
// synthetic sequence of costs). No paper section.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace eccd {

class TimeLeft {
 public:
  // prior[k] > 0: the rough relative cost of a task of kind k.
  explicit TimeLeft(std::vector<double> prior) : prior_(std::move(prior)), sum_(prior_.size(), 0), n_(prior_.size(), 0) {}

  // A finished task of kind k took `seconds`.
  void add(std::size_t kind, double seconds) {
    sum_[kind] += seconds;
    ++n_[kind];
    measured_s_ += seconds;
    measured_prior_ += prior_[kind];
  }

  bool measured() const { return measured_prior_ > 0; }

  // Expected cost in seconds of one task of kind k (needs measured()).
  double cost(std::size_t kind) const {
    if (n_[kind] > 0) return sum_[kind] / double(n_[kind]);
    return prior_[kind] * (measured_s_ / measured_prior_);
  }

  // Wall seconds left: `queued[k]` tasks of kind k not started, `running` the
  // (kind, seconds run so far) of the tasks in progress, `workers` processes.
  // nullopt before any task has finished (nothing to scale the priors by).
  std::optional<double> wall(const std::vector<long>& queued, const std::vector<std::pair<std::size_t, double>>& running,
                             int workers) const {
    if (!measured()) return std::nullopt;
    std::vector<double> c(prior_.size());
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = cost(k);
    for (const auto& [kind, ran] : running)
      if (n_[kind] == 0) c[kind] = std::max(c[kind], ran);
    double work = 0, longest = 0;
    long tasks = long(running.size());
    for (std::size_t k = 0; k < queued.size(); ++k) {
      work += double(queued[k]) * c[k];
      tasks += queued[k];
    }
    for (const auto& [kind, ran] : running) {
      double rest = std::max(0.0, c[kind] - ran);
      work += rest;
      longest = std::max(longest, rest);
    }
    if (tasks == 0) return 0.0;
    long busy = std::max(1L, std::min<long>(workers, tasks));
    return std::max(work / double(busy), longest);
  }

 private:
  std::vector<double> prior_, sum_;
  std::vector<long> n_;
  double measured_s_ = 0, measured_prior_ = 0;
};

}  // namespace eccd

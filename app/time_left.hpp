#pragma once
// Time left of a run of tasks of several kinds (`eccd report`'s progress
// line).
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
// synthetic sequence of costs; tests/app/test_progress.cpp the rate and the
// cadence below). No paper section.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eccd {

class TimeLeft {
 public:
  // prior[k] > 0: the rough relative cost of a task of kind k.
  explicit TimeLeft(std::vector<double> prior)
      : prior_(std::move(prior)), sum_(prior_.size(), 0), n_(prior_.size(), 0) {}

  // A finished task of kind k took `seconds`.
  void add(std::size_t kind, double seconds) {
    sum_[kind] += seconds;
    ++n_[kind];
    measured_s_ += seconds;
    measured_prior_ += prior_[kind];
  }

  bool measured() const { return measured_prior_ > 0; }

  // Wall seconds left from the measured rate of the whole run: the prior
  // units finished per wall second so far (`elapsed_s` since the start)
  // against the prior units not finished (queued, and half of each running
  // task). nullopt before any task has finished. A check on wall(): when
  // the tasks measured so far are cheap kinds that calibrate the priors too
  // low, the run's own rate still says how fast work gets done.
  std::optional<double> wall_by_rate(const std::vector<long>& queued, const std::vector<std::size_t>& running_kinds,
                                     double elapsed_s) const {
    if (!measured() || elapsed_s <= 0) return std::nullopt;
    double rest = 0;
    for (std::size_t k = 0; k < queued.size(); ++k) rest += double(queued[k]) * prior_[k];
    for (std::size_t kind : running_kinds) rest += 0.5 * prior_[kind];
    return rest / (measured_prior_ / elapsed_s);
  }

  // Expected cost in seconds of one task of kind k (needs measured()).
  double cost(std::size_t kind) const {
    if (n_[kind] > 0) return sum_[kind] / double(n_[kind]);
    return prior_[kind] * (measured_s_ / measured_prior_);
  }

  // Wall seconds left: `queued[k]` tasks of kind k not started, `running` the
  // (kind, seconds run so far) of the tasks in progress, `workers` processes.
  // nullopt before any task has finished (nothing to scale the priors by).
  std::optional<double> wall(const std::vector<long>& queued,
                             const std::vector<std::pair<std::size_t, double>>& running, int workers) const {
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

// "about 3 min 5 s left", or "time left unknown" while there is no measured rate.
inline std::string time_left_text(std::optional<double> seconds) {
  if (!seconds) return "time left unknown";
  const long s = std::lround(std::max(0.0, *seconds));
  std::string t;
  if (s >= 3600)
    t = std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
  else if (s >= 60)
    t = std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  else
    t = std::to_string(s) + " s";
  return "about " + t + " left";
}

// When a long command prints its progress line on stderr. On a terminal the
// line is redrawn in place ('\r', at most every `min_gap_s` seconds). In a log
// file (not a terminal) there is no redrawing: a new line each time the share
// done passes the next multiple of `step_percent`, or after `heartbeat_s`
// seconds without a line, and one at the end. Pure: the caller passes the
// clock and whether stderr is a terminal (isatty(2)).
class ProgressCadence {
 public:
  ProgressCadence(bool tty, long total, double step_percent = 5, double min_gap_s = 0.5, double heartbeat_s = 120)
      : tty_(tty), total_(std::max(1L, total)), step_(step_percent), gap_(min_gap_s), heartbeat_(heartbeat_s) {}

  // true: print a line now (and remember that it was printed).
  bool due(long done, double elapsed_s) {
    bool print;
    if (done >= total_)
      print = !ended_;
    else if (tty_)
      print = elapsed_s - last_s_ >= gap_;
    else
      print = std::floor(100.0 * double(done) / double(total_) / step_) >
                  std::floor(100.0 * double(last_done_) / double(total_) / step_) ||
              elapsed_s - last_s_ >= heartbeat_ || last_s_ < 0;
    if (print) {
      last_s_ = elapsed_s;
      last_done_ = done;
      ended_ = done >= total_;
    }
    return print;
  }
  // What goes before a line ('\r' redraws on a terminal) and after it ("\n" in a log; on a
  // terminal the rest of the old line is cleared and the cursor stays for the next redraw).
  const char* begin() const { return tty_ ? "\r" : ""; }
  const char* end(bool last) const { return last || !tty_ ? (tty_ ? "\x1b[K\n" : "\n") : "\x1b[K"; }
  bool tty() const { return tty_; }

 private:
  bool tty_;
  long total_;
  double step_, gap_, heartbeat_;
  double last_s_ = -1;
  long last_done_ = 0;
  bool ended_ = false;
};

}  // namespace eccd

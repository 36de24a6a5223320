// The certified static test (api/static_status.hpp): the
// filtered predicate (double with its error bound, exact only where that is
// uncertain) next to the double test, on the same batches of random pairs as
// static2d / static3d. Baseline: the double test through the API.
#include "bench/groups.hpp"

namespace eccd_bench::groups {

void register_static_certified() {
  for (int dim : {2, 3}) {
    std::string grp = "static-certified-" + std::to_string(dim) + "d";
    group(grp, std::string("certified static test from two poses, ") + (dim == 2 ? "2D" : "3D") + " (per pair)",
          "The batch of 1024 random pairs of the static" + std::to_string(dim) +
              "d group, one pair per iteration: "
              "eccd::static_status(a, b) from the semi-axes and poses in double (Bounded<double>, uncertain where the "
              "error "
              "bound cannot decide; the baseline) and certified (the same double test, then the exact test — world "
              "quadrics "
              "and exact signs — only where the double one is uncertain). The result column counts the statuses and "
              "how many "
              "pairs went to the exact test.",
          "the certified static test's cost target: at most 1.5x the double static test on random pairs");
    for (const char* arith : {"double", "certified"}) {
      std::string label = std::string(arith) + " static_status (API, two poses)";
      Arithmetic a = std::string(arith) == "double" ? Arithmetic::double_precision() : Arithmetic::certified();
      row(grp, label, std::string(arith) == "double", Cost::fast,
          std::string("eccd::static_status(a, b, ") + arith + ")", [grp, label, a, dim](benchmark::State& st) {
            auto status_of = [&](int k) {
              return dim == 2 ? static_status(static2d.get().pa[k], static2d.get().pb[k], a)
                              : static_status(static3d.get().pa[k], static3d.get().pb[k], a);
            };
            int i = 0;
            auto f = [&] {
              i = (i + 1) & (kBatch - 1);
              return status_of(i);
            };
            timed(st, grp + "/" + label, f, [&](Status) {
              std::vector<Status> v;
              int to_exact = 0;
              for (int k = 0; k < kBatch; ++k) {
                v.push_back(status_of(k));
                Status d = dim == 2 ? static_status(static2d.get().pa[k], static2d.get().pb[k])
                                    : static_status(static3d.get().pa[k], static3d.get().pb[k]);
                to_exact += d == Status::uncertain;
              }
              json j = status_counts(v);
              if (a.kind == Arithmetic::Certified) j["went_to_exact"] = to_exact;
              return j;
            });
          });
    }
  }
}

}  // namespace eccd_bench::groups

// Static tests: batches of random pairs in double.
#include "bench/groups.hpp"

namespace eccd_bench::groups {

// static3d: the target rows (the API, one pair and batched) and plain double with the status.
void register_static3d() {
  group(
      "static3d", "3D static separation test in double (per pair)",
      "A batch of 1024 random ellipsoid pairs, A in standard position (diag(1/a², 1/b², 1/c², -1)), B rotated and "
      "translated into A's frame; one pair per iteration. The target row 'Appendix A + Sturm' times the API, "
      "eccd::static_status from the two ellipsoids' semi-axes and poses (api/static_status.hpp: both shapes as unit "
      "balls "
      "under their axis-scaled poses, the relative pose by the adjugate and 001 Appendix A in plain double with static "
      "error bounds, Descartes and the discriminant's sign, kernel/static_filter3d.hpp; the running-bound Sturm test "
      "only where that is uncertain). Row "
      "'static_status_batch' is the batched API, 64 pairs per iteration. The other rows "
      "split plain double on B given in A's frame: coefficients of f(λ) = det(λA - B) by the generic "
      "determinant expansion (2^4 column choices, kernel/characteristic_polynomial.hpp) or by 001 Appendix A "
      "(kernel/fast_quartic.hpp, 40 multiplications + det B by cofactors); status from the Sturm count of the "
      "negative roots (kernel/quartic_status.hpp). Rows 'coefficients only' and 'status only' split the time.",
      "001: the whole static procedure (motion matrices of degree 4 included) in under 1 µs on a 3 GHz Pentium IV; "
      "speed target: at most 40 ns per pair (batched: 15 ns per pair)");
  auto all3 = [](auto status_of) {
    (void)static3d.get();  // the pairs are built before the first status call
    std::vector<Status> v;
    for (int i = 0; i < kBatch; ++i) v.push_back(status_of(i));
    return status_counts(v);
  };
  row("static3d", "generic det + Sturm", true, Cost::fast,
      "characteristic_coefficients_in<double,4> + quartic_contact_status", [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return quartic_contact_status(characteristic_coefficients_in<double, 4>(s.a[i], s.b[i], 0.0));
        };
        timed(st, "static3d/generic det + Sturm", f, [&](Status) {
          return all3([&](int k) {
            return quartic_contact_status(characteristic_coefficients_in<double, 4>(s.a[k], s.b[k], 0.0));
          });
        });
      });
  // The target row: what a user's program runs, eccd::static_status (api/static_status.hpp) from the two
  // ellipsoids' semi-axes and poses: B's pose relative to A's, 001 Appendix A and the Sturm count, in
  // Bounded<double> (uncertain where double's error bound is not decisive).
  row("static3d", "Appendix A + Sturm", false, Cost::fast,
      "eccd::static_status(a, b) from two poses (the API: relative pose, Appendix A, Sturm, with error bound; the "
      "target row)",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return static_status(s.pa[i], s.pb[i]);
        };
        timed(st, "static3d/Appendix A + Sturm", f,
              [&](Status) { return all3([&](int k) { return static_status(s.pa[k], s.pb[k]); }); });
      });
  // The batched API, 64 pairs per iteration (the figure per pair is the median / 64; target 15 ns per pair).
  row("static3d", "static_status_batch (API, 64 pairs per iteration)", false, Cost::fast,
      "eccd::static_status_batch over 64 pairs from two poses (blocks of 8 lanes in structure of arrays through the "
      "static "
      "filter compiled for AVX-512 where the CPU has it, api/static_filter_simd.hpp; pair by pair otherwise); divide "
      "by 64 "
      "for the time per pair",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        std::size_t i = 0;
        std::array<Status, 64> out;
        auto f = [&] {
          i = (i + 64) & (kBatch - 1);
          static_status_batch(std::span<const Ellipsoid>(s.pa).subspan(i, 64),
                              std::span<const Ellipsoid>(s.pb).subspan(i, 64), std::span<Status>(out));
          return out[0];
        };
        timed(st, "static3d/static_status_batch (API, 64 pairs per iteration)", f, [&](Status) {
          std::vector<Status> v(kBatch);
          static_status_batch(std::span<const Ellipsoid>(s.pa), std::span<const Ellipsoid>(s.pb), std::span<Status>(v));
          return status_counts(v);
        });
      });
  row("static3d", "Appendix A + Sturm, plain double, B given in A's frame", false, Cost::fast,
      "appendix_a_coefficients + quartic_contact_status in plain double on precomputed B (no pose, no error bound)",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return quartic_contact_status(appendix_a_coefficients(s.e[i][0], s.e[i][1], s.e[i][2], s.b[i]));
        };
        timed(st, "static3d/Appendix A + Sturm, plain double, B given in A's frame", f, [&](Status) {
          return all3([&](int k) {
            return quartic_contact_status(appendix_a_coefficients(s.e[k][0], s.e[k][1], s.e[k][2], s.b[k]));
          });
        });
      });
}

// static3d: the coefficients and the status decision timed apart.
void register_static3d_parts() {
  row("static3d", "generic det, coefficients only", false, Cost::fast, "characteristic_coefficients_in<double,4>",
      [](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return characteristic_coefficients_in<double, 4>(s.a[i], s.b[i], 0.0);
        };
        timed(st, "static3d/generic det, coefficients only", f, [](const std::vector<double>&) { return json(); });
      });
  row("static3d", "Appendix A, coefficients only", false, Cost::fast, "appendix_a_coefficients (001 Appendix A)",
      [](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return appendix_a_coefficients(s.e[i][0], s.e[i][1], s.e[i][2], s.b[i]);
        };
        timed(st, "static3d/Appendix A, coefficients only", f, [](const std::array<double, 5>&) { return json(); });
      });
  row("static3d", "Sturm status only", false, Cost::fast, "quartic_contact_status on precomputed coefficients",
      [](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return quartic_contact_status(s.coeffs[i]);
        };
        timed(st, "static3d/Sturm status only", f, [](Status) { return json(); });
      });
}

void register_static2d() {
  group(
      "static2d", "2D static separation test in double (per pair)",
      "A batch of 1024 random pairs of ellipses, A axis-aligned at the origin, B rotated and translated; one pair per "
      "iteration. Coefficients g0..g3 of the cubic f(λ) = det(λA - B) by the generic determinant expansion "
      "(2^3 column choices), status by 003 Theorem 6 from signs only (discriminant, Descartes; "
      "kernel/contact_status.hpp). Row 'static_status (API, two poses)' is what a user's program runs: "
      "eccd::static_status from the semi-axes and poses (api/static_status.hpp: B relative to A, the 3x3 analogue "
      "of 001 Appendix A, with double's error bound).",
      "003 gives no static timing; 000: about 8 µs per static 3D test with root solving (for scale)");
  auto all2 = [](auto status_of) {
    std::vector<Status> v;
    for (int i = 0; i < kBatch; ++i) v.push_back(status_of(i));
    return status_counts(v);
  };
  row("static2d", "generic det + cubic rule", true, Cost::fast,
      "characteristic_coefficients_in<double,3> + cubic_contact_status", [all2](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto st_of = [&](int k) {
          std::vector<double> g = characteristic_coefficients_in<double, 3>(s.a[k], s.b[k], 0.0);
          return cubic_contact_status(g[3], g[2], g[1], g[0]);
        };
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return st_of(i);
        };
        timed(st, "static2d/generic det + cubic rule", f, [&](Status) { return all2(st_of); });
      });
  row("static2d", "static_status (API, two poses)", false, Cost::fast,
      "eccd::static_status(a, b) from two poses (the API: relative pose, closed-form cubic, 003 Theorem 6 rule, with "
      "error bound)",
      [all2](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto st_of = [&](int k) { return static_status(s.pa[k], s.pb[k]); };
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return st_of(i);
        };
        timed(st, "static2d/static_status (API, two poses)", f, [&](Status) { return all2(st_of); });
      });
  row("static2d", "static_status_batch (API, 64 pairs per iteration)", false, Cost::fast,
      "eccd::static_status_batch over 64 pairs from two poses; divide by 64 for the time per pair",
      [](benchmark::State& st) {
        const Static2D& s = static2d.get();
        std::size_t i = 0;
        std::array<Status, 64> out;
        auto f = [&] {
          i = (i + 64) & (kBatch - 1);
          static_status_batch(std::span<const Ellipse>(s.pa).subspan(i, 64),
                              std::span<const Ellipse>(s.pb).subspan(i, 64), std::span<Status>(out));
          return out[0];
        };
        timed(st, "static2d/static_status_batch (API, 64 pairs per iteration)", f, [&](Status) {
          std::vector<Status> v(kBatch);
          static_status_batch(std::span<const Ellipse>(s.pa), std::span<const Ellipse>(s.pb), std::span<Status>(v));
          return status_counts(v);
        });
      });
  row("static2d", "generic det, coefficients only", false, Cost::fast, "characteristic_coefficients_in<double,3>",
      [](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return characteristic_coefficients_in<double, 3>(s.a[i], s.b[i], 0.0);
        };
        timed(st, "static2d/generic det, coefficients only", f, [](const std::vector<double>&) { return json(); });
      });
  row("static2d", "cubic rule only", false, Cost::fast, "cubic_contact_status on precomputed coefficients",
      [](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          const auto& g = s.coeffs[i];
          return cubic_contact_status(g[3], g[2], g[1], g[0]);
        };
        timed(st, "static2d/cubic rule only", f, [](Status) { return json(); });
      });
}

void register_static() {
  register_static3d();
  register_static3d_parts();
  register_static2d();
}

}  // namespace eccd_bench::groups

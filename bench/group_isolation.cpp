// Exact real root isolation.
#include "bench/groups.hpp"

namespace eccd_bench::groups {

struct IsoPoly {
  std::string id, what;
  Poly<Rational> p;
  std::vector<mpz_class> z;  // primitive integer coefficients
};

IsoPoly iso_from(const std::string& id, const std::string& what, const Poly<Rational>& p) {
  IsoPoly ip{id, what, p, {}};
  for (const auto& s : integer_coefficients(p)) ip.z.emplace_back(s);
  return ip;
}

Lazy<IsoPoly> iso_deg2([] {
  return iso_from("2d-deg2", "Δ(t) of the 2D degree-2 scene", certificate_algebra(s2d_deg2.get().scene).projection);
});
Lazy<IsoPoly> iso_deg4([] {
  return iso_from("2d-deg4", "Δ(t) of the 2D degree-4 scene", certificate_algebra(s2d_deg4.get().scene).projection);
});
Lazy<IsoPoly> iso_deg6([] {
  return iso_from("2d-deg6", "Δ(t) of the 2D degree-6 scene", certificate_algebra(s2d_deg6.get().scene).projection);
});
Lazy<IsoPoly> iso_3d_deg2([] {
  return iso_from("3d-deg2", "projection of the 3D degree-2 affine scene",
                  certificate_algebra(s3d_deg2.get().scene).projection);
});
Lazy<IsoPoly> iso_paper002([] {
  return iso_from("paper002", "projection (discriminant) of paper 002's example",
                  certificate_algebra(s3d_paper002.get().scene).projection);
});
Lazy<IsoPoly> iso_random200([] {
  std::mt19937_64 rng(200);
  std::uniform_int_distribution<long> c(-1000, 1000);
  Poly<Rational> p;
  for (int i = 0; i <= 200; ++i) p.c.push_back(Rational(c(rng)));
  if (p.c.back() == 0) p.c.back() = 1;
  return iso_from("random200",
                  "random integer polynomial of degree 200, coefficients uniform in [-1000, 1000] (seed 200)", p);
});

json iso_info(const IsoPoly& ip) {
  std::size_t bits = 0;
  for (const auto& z : ip.z) bits = std::max(bits, mpz_sizeinbase(z.get_mpz_t(), 2));
  return {{"what", ip.what}, {"degree", ip.p.degree()}, {"max_coefficient_bits", bits}};
}

void register_isolation() {
  struct P {
    Lazy<IsoPoly>* poly;
    const char* id;
  };
  for (P pp : {P{&iso_deg2, "isolation-2d-deg2"}, P{&iso_deg4, "isolation-2d-deg4"}, P{&iso_deg6, "isolation-2d-deg6"},
               P{&iso_3d_deg2, "isolation-3d-deg2"}, P{&iso_paper002, "isolation-paper002"},
               P{&iso_random200, "isolation-random200"}}) {
    std::string grp = pp.id;
    group(grp, std::string("Exact real root isolation: ") + (grp.substr(10)),
          "The same integer polynomial isolated by the workbench (eccd::real_roots on [0, 1], brackets of width "
          "2^-64: CGAL Algebraic_kernel_d_1 over CORE::BigInt isolates, the workbench refines the roots in [0, 1] "
          "by quadratic interval refinement), by CGAL's kernel over GMP + MPFI (all real roots), by CGAL's kernel over "
          "CORE::BigInt called directly (all real roots) and by MPSolve (isolating discs for all complex "
          "roots). Process CPU time (all threads).",
          grp == "isolation-random200"
              ? "anchor: CGAL with CORE about 7 ms on a random degree-200 integer polynomial (this machine)"
              : "the workbench's own isolation (baseline)");
    Lazy<IsoPoly>* poly = pp.poly;
    row(
        grp, "workbench real_roots (CGAL CORE + own refinement)", true, Cost::slow,
        "eccd::real_roots(p, 0, 1, 64): conversion, solve_1, brackets to 2^-64, restriction to [0, 1]",
        [poly, grp](benchmark::State& st) {
          const IsoPoly& ip = poly->get();
          timed(
              st, grp + "/workbench real_roots (CGAL CORE + own refinement)",
              [&] { return real_roots(ip.p, Rational(0), Rational(1), 64); },
              [&](const std::vector<AlgebraicRoot>& r) {
                json j = iso_info(ip);
                j["in_unit"] = r.size();
                return j;
              });
        },
        true);
    struct L {
      const char* label;
      std::unique_ptr<eccd_bench::PreparedIsolation> (*prep)(const std::vector<mpz_class>&);
      const char* note;
    };
    for (L l :
         {L{"CGAL GMP+MPFI solve_1", eccd_bench::prepare_cgal_gmp_mpfi,
            "Algebraic_kernel_d_1<Gmpz>, CGAL_USE_MPFI, fresh kernel"},
          L{"CGAL CORE solve_1", eccd_bench::prepare_cgal_core, "Algebraic_kernel_d_1<CORE::BigInt>, fresh kernel"},
          L{"MPSolve isolate", eccd_bench::prepare_mpsolve,
            "mps_mpsolve, goal isolate, secular GA, all complex roots"}}) {
      std::string label = l.label;
      row(
          grp, label, false, Cost::slow, l.note,
          [poly, grp, label, l](benchmark::State& st) {
            const IsoPoly& ip = poly->get();
            auto prepared = l.prep(ip.z);
            timed(
                st, grp + "/" + label, [&] { return prepared->run(); },
                [&](const eccd_bench::IsolationOutcome& o) {
                  json j = iso_info(ip);
                  j["roots"] = o.roots;
                  j["in_unit"] = o.in_unit;
                  return j;
                });
          },
          true);
    }
  }
}

}  // namespace eccd_bench::groups

#pragma once
// The polynomials a certificate speaks about, recomputed from the scene in
// exact rational arithmetic: what the certificate writer and the checker both
// derive from the scene file alone.
//
// Statement. From the scene (kernel/prepared_scene.hpp: exact, primitive
// integer Q and N(t)), f(λ;t) = det(λA(t) - B(t)) = Σ g_k(t) λ^k
// (kernel/characteristic_polynomial.hpp), and the projection polynomial whose
// real roots in [0, 1] are the only instants where the status can change:
//   2D: Δ(t), the discriminant of the cubic f (003 section III eq. (2));
//       Δ ≡ 0 means the disks are never separate (003 Corollary 7);
//   3D: Disc_λ f, or when it vanishes identically the first principal
//       subresultant coefficient psc_k(f, ∂f/∂λ) that does not (002 section
//       III; kernel/subresultants.hpp).
// Evidence polynomials, whose signs at a root decide its status:
//   2D: "P" = 9 g3 g0 - g2 g1 and "D" = g2² - 3 g3 g1 (kernel/discriminant.hpp,
//       kernel/contact_status.hpp);
//   3D: "s(j,i)" and "disc(S_2)" (kernel/quartic_touch_rule.hpp).
// The static status at a rational instant is the exact static test (003
// Theorem 6 / 002 Theorem 1). Nothing here isolates roots or runs a CCD
// method: this is the part of the workbench a certificate checker trusts.
// Requirements: a scene with rational motions (cycloidal motions are refused
// by prepare_pair).
#include "exact/integer_polynomial.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quartic_status.hpp"
#include "kernel/quartic_touch_rule.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

struct CertificateAlgebra {
  int dim = 2;
  std::vector<Poly<Rational>> g;        // g_0 .. g_{dim+1}
  Poly<Rational> projection;            // zero only for a 2D Δ ≡ 0
  std::string projection_name;          // "discriminant", "psc_1", ...
  int projection_index = 0;             // 3D: k of psc_k (0 = discriminant)
  std::vector<std::string> vanishing;   // the candidates before it, each ≡ 0

  // An evidence polynomial by its certificate name; throws std::invalid_argument for an unknown name.
  Poly<Rational> evidence(const std::string& name) const {
    if (dim == 2) {
      if (name == "P") return double_root_numerator(g[3], g[2], g[1], g[0]);
      if (name == "D") return double_root_denominator(g[3], g[2], g[1]);
    } else {
      if (name == "disc(S_2)") return subresultant_evidence(g, 2, -1);
      int j = -1, i = -1;
      char tail = 0;
      if (std::sscanf(name.c_str(), "s(%d,%d%c", &j, &i, &tail) == 3 && tail == ')' && i >= 0 && i <= j && j <= 3 &&
          subresultant_evidence_name(j, i) == name)
        return subresultant_evidence(g, j, i);
    }
    throw std::invalid_argument("unknown evidence polynomial \"" + name + "\" for a " + std::to_string(dim) + "D scene");
  }

  // The exact static test at a rational instant.
  Status status_at(const Rational& t) const {
    if (dim == 2) return cubic_contact_status(g[3](t), g[2](t), g[1](t), g[0](t));
    return quartic_status_at(g, t);
  }
};

inline CertificateAlgebra certificate_algebra(const Scene& s) {
  CertificateAlgebra a;
  a.dim = s.dim;
  if (s.dim == 2) {
    a.g = characteristic_of(to_arithmetic<Rational, 3>(prepare_pair<3>(s), Rational(1)));
    a.projection = cubic_discriminant(a.g[3], a.g[2], a.g[1], a.g[0]);
    a.projection_name = "discriminant";
    return a;
  }
  a.g = characteristic_of(to_arithmetic<Rational, 4>(prepare_pair<4>(s), Rational(1)));
  a.projection = quartic_discriminant(a.g[4], a.g[3], a.g[2], a.g[1], a.g[0]);
  a.projection_name = "discriminant";
  for (int k = 1; a.projection.is_zero() && k <= 3; ++k) {
    a.vanishing.push_back(a.projection_name);
    a.projection = subresultant_evidence(a.g, k, k);
    a.projection_name = "psc_" + std::to_string(k);
    a.projection_index = k;
  }
  if (a.projection.is_zero()) throw std::logic_error("internal error: psc_3 of the characteristic quartic vanishes");
  return a;
}

// Primitive integer coefficients (lowest degree first) of a positive multiple
// of p, as decimal strings: how a certificate writes a polynomial.
inline std::vector<std::string> integer_coefficients(const Poly<Rational>& p) {
  std::vector<std::string> out;
  for (const auto& x : primitive_integer_multiple(p)) out.push_back(x.get_str());
  return out;
}

}  // namespace eccd

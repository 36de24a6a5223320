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

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

struct CertificateAlgebra {
  int dim = 2;
  std::vector<Poly<Rational>> g;       // g_0 .. g_{dim+1}
  Poly<Rational> projection;           // zero only for a 2D Δ ≡ 0
  std::string projection_name;         // "discriminant", "psc_1", ...
  int projection_index = 0;            // 3D: k of psc_k (0 = discriminant)
  std::vector<std::string> vanishing;  // the candidates before it, each ≡ 0

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
    throw std::invalid_argument("unknown evidence polynomial \"" + name + "\" for a " + std::to_string(dim) +
                                "D scene");
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
    a.g = characteristic_of(to_arithmetic<Rational, H_2D>(prepare_pair<H_2D>(s), Rational(1)));
    a.projection = cubic_discriminant(a.g[3], a.g[2], a.g[1], a.g[0]);
    a.projection_name = "discriminant";
    return a;
  }
  a.g = characteristic_of(to_arithmetic<Rational, H_3D>(prepare_pair<H_3D>(s), Rational(1)));
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

// The largest bit size of the numerators and denominators of p's coefficients.
inline std::size_t coefficient_bits(const Poly<Rational>& p) {
  std::size_t b = 0;
  for (const auto& x : p.c)
    b = std::max({b, mpz_sizeinbase(x.get_num_mpz_t(), 2), mpz_sizeinbase(x.get_den_mpz_t(), 2)});
  return b;
}

// τ: the largest bit size of p's primitive integer coefficients.
inline std::size_t integer_coefficient_bits(const Poly<Rational>& p) {
  std::size_t tau = 0;
  for (const auto& x : primitive_integer_multiple(p)) tau = std::max(tau, mpz_sizeinbase(x.get_mpz_t(), 2));
  return tau;
}

// How a certificate writes an instant's `approx` (and how the checker reads
// it back): a plain decimal "[-]digits[.digits][e[-]digits]". For a bracket
// lo < hi it is the midpoint rounded to the fewest decimal places that keep
// it inside [lo, hi]; for a point [r, r] it is r exactly when r has at most 40
// decimal places, else r rounded to 40 places. So approx lies in its bracket,
// and a point's approx is r correctly rounded to its own last digit.
inline std::string decimal_with_places(const Rational& x, int k) {  // round(x 10^k) / 10^k, half up
  mpz_class p10;
  mpz_ui_pow_ui(p10.get_mpz_t(), 10, unsigned(k));
  Rational y = x * Rational(p10) + Rational(1, 2);
  mpz_class m;
  mpz_fdiv_q(m.get_mpz_t(), y.get_num_mpz_t(), y.get_den_mpz_t());
  const bool neg = sgn(m) < 0;
  std::string d = mpz_class(abs(m)).get_str();
  if (k > 0) {
    if (d.size() <= std::size_t(k)) d = std::string(std::size_t(k) + 1 - d.size(), '0') + d;
    const std::size_t head = d.size() - std::size_t(k);
    std::string r = d.substr(0, head);  // appended, not inserted (GCC 12's false -Wrestrict)
    d = r.append(".").append(d, head);
  }
  std::string r = neg ? "-" : "";  // appended, not inserted: GCC 12's false -Wrestrict (bug 105329)
  return r.append(d);
}
inline Rational decimal_value(const Rational& x, int k) {
  mpz_class p10;
  mpz_ui_pow_ui(p10.get_mpz_t(), 10, unsigned(k));
  Rational y = x * Rational(p10) + Rational(1, 2);
  mpz_class m;
  mpz_fdiv_q(m.get_mpz_t(), y.get_num_mpz_t(), y.get_den_mpz_t());
  Rational v(m, p10);
  v.canonicalize();
  return v;
}
inline std::string approx_in_bracket(const Rational& lo, const Rational& hi) {
  if (lo == hi) {
    for (int k = 0; k < 40; ++k)
      if (decimal_value(lo, k) == lo) return decimal_with_places(lo, k);
    return decimal_with_places(lo, 40);
  }
  const Rational mid = (lo + hi) / 2;
  for (int k = 0;; ++k) {
    Rational v = decimal_value(mid, k);
    if (lo <= v && v <= hi) return decimal_with_places(mid, k);
  }
}

// An approx read back: its exact value and the unit of its last written digit;
// nullopt when it is not a plain decimal of at most max_chars characters (or
// its exponent is beyond ±100000).
struct ApproxValue {
  Rational value, unit;
};
inline std::optional<ApproxValue> read_approx(const std::string& s, std::size_t max_chars) {
  if (s.empty() || s.size() > max_chars) return std::nullopt;
  std::size_t i = 0;
  bool neg = false;
  if (s[i] == '-' || s[i] == '+') neg = s[i++] == '-';
  std::string digits;
  long places = 0;
  bool dot = false;
  for (; i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || (s[i] == '.' && !dot)); ++i) {
    if (s[i] == '.') {
      dot = true;
      continue;
    }
    digits += s[i];
    if (dot) ++places;
  }
  if (digits.empty()) return std::nullopt;
  long ex = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) eneg = s[i++] == '-';
    std::size_t start = i;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
      if (ex < 1000000) ex = ex * 10 + (s[i] - '0');
    if (i == start || ex > 100000) return std::nullopt;
    if (eneg) ex = -ex;
  }
  if (i != s.size()) return std::nullopt;
  const long e = ex - places;  // value = digits · 10^e
  mpz_class p10;
  mpz_ui_pow_ui(p10.get_mpz_t(), 10, unsigned(e < 0 ? -e : e));
  ApproxValue a;
  mpz_class m(digits, 10);
  if (neg) m = -m;
  a.value = e < 0 ? Rational(m, p10) : Rational(m * p10);
  a.unit = e < 0 ? Rational(mpz_class(1), p10) : Rational(p10);
  a.value.canonicalize();
  a.unit.canonicalize();
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

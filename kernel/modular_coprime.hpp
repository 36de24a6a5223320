#pragma once
// coprime_mod_p: a proof, from one gcd modulo a prime, that two polynomials
// with rational coefficients have no common factor of positive degree (a
// filter in front of the exact Euclid gcd of kernel/polynomial.hpp, which
// over Q suffers coefficient growth; the exact preparation of a scene,
// kernel/prepared_scene.hpp, calls it to skip the gcd when the content of
// N(t) is constant, which it almost always is).
//
// Statement (the classical modular gcd bound, e.g. von zur Gathen & Gerhard,
// Modern Computer Algebra, 3rd ed., Lemma 6.33). Let a, b in Q[t] be non-zero,
// p a prime that divides no denominator of a or b and not the numerator of
// either leading coefficient, and ā, b̄ their images in F_p[t] (num·den^-1 mod
// p). Scaled by the lcm L of its denominators (p ∤ L) and divided by its
// integer content, a becomes a primitive integer polynomial a' with
// a' ≡ u·ā (mod p) for a unit u, and p ∤ lc(a') (lc(a') divides L·lc(a),
// whose numerator p does not divide). The monic gcd g of a and b over Q is,
// up to a rational factor, a primitive integer polynomial g' dividing a' and
// b' in Z[t] (Gauss's lemma). lc(g') divides lc(a'), so p ∤ lc(g'): its image
// ḡ has the degree of g, and it divides ā and b̄, hence gcd(ā, b̄) in F_p[t].
// So deg g <= deg gcd(ā, b̄): when the gcd modulo p is a non-zero constant,
// a and b are coprime over Q. The converse does not hold (an unlucky prime
// may leave a spurious common factor): false means "not proved", and the
// caller runs the exact gcd. p = 2^61 - 1; products of two residues are
// formed in 128 bits, so every step is exact.
// Requirements: Poly<Rational> (mpq_class), canonical (gmp keeps them so).
#include "kernel/polynomial.hpp"
#include "number/rational_traits.hpp"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace eccd {

namespace modp {

inline constexpr std::uint64_t kPrime = (std::uint64_t(1) << 61) - 1;

// The 128-bit product of two residues. __int128 is a GCC/Clang extension, which -Wpedantic reports;
// __extension__ says it is meant (every compiler eccd builds with has it).
__extension__ typedef unsigned __int128 u128;

inline std::uint64_t mul(std::uint64_t a, std::uint64_t b) {
  u128 x = static_cast<u128>(a) * b;                                          // < 2^122
  std::uint64_t lo = std::uint64_t(x & kPrime), hi = std::uint64_t(x >> 61);  // x = hi·2^61 + lo, 2^61 ≡ 1
  std::uint64_t r = lo + hi;                                                  // < 2^62
  r = (r & kPrime) + (r >> 61);
  return r >= kPrime ? r - kPrime : r;
}
inline std::uint64_t sub(std::uint64_t a, std::uint64_t b) { return a >= b ? a - b : a + kPrime - b; }
inline std::uint64_t power(std::uint64_t a, std::uint64_t e) {
  std::uint64_t r = 1;
  for (; e; e >>= 1, a = mul(a, a))
    if (e & 1) r = mul(r, a);
  return r;
}
inline std::uint64_t inverse(std::uint64_t a) { return power(a, kPrime - 2); }  // a != 0 (Fermat)

// The residue of an integer (0 <= result < p).
inline std::uint64_t residue(const mpz_class& z) {
  static_assert(sizeof(unsigned long) >= 8, "mpz_fdiv_ui needs a 64-bit unsigned long for p = 2^61 - 1");
  return mpz_fdiv_ui(z.get_mpz_t(), static_cast<unsigned long>(kPrime));
}

// ā with low-to-high coefficients, or nothing if p divides a denominator or
// the numerator of the leading coefficient (the lemma's conditions).
inline std::optional<std::vector<std::uint64_t>> image(const Poly<Rational>& a) {
  std::vector<std::uint64_t> r(a.c.size());
  std::uint64_t last_d = 1, last_inv = 1;  // denominators repeat (scenes write few): one inversion each
  for (std::size_t i = 0; i < a.c.size(); ++i) {
    std::uint64_t d = residue(a.c[i].get_den());
    if (d == 0) return std::nullopt;
    if (d != last_d) {
      last_d = d;
      last_inv = inverse(d);
    }
    r[i] = mul(residue(a.c[i].get_num()), last_inv);
  }
  if (r.empty() || r.back() == 0) return std::nullopt;
  return r;
}

// The degree of gcd(a, b) in F_p[t] (Euclid); both non-zero with non-zero leading coefficients.
inline int gcd_degree(std::vector<std::uint64_t> a, std::vector<std::uint64_t> b) {
  auto trim = [](std::vector<std::uint64_t>& v) {
    while (!v.empty() && v.back() == 0) v.pop_back();
  };
  if (a.size() < b.size()) std::swap(a, b);
  while (!b.empty()) {
    const std::uint64_t inv = inverse(b.back());
    while (a.size() >= b.size()) {  // a <- a mod b
      const std::uint64_t f = mul(a.back(), inv);
      const std::size_t shift = a.size() - b.size();
      for (std::size_t i = 0; i < b.size(); ++i) a[shift + i] = sub(a[shift + i], mul(f, b[i]));
      trim(a);  // the leading coefficient is now 0
      if (a.empty()) break;
    }
    std::swap(a, b);
  }
  return int(a.size()) - 1;
}

}  // namespace modp

// True only if a and b (non-zero) provably have no common factor of positive
// degree over Q (see the statement); false: not proved.
inline bool coprime_mod_p(const Poly<Rational>& a, const Poly<Rational>& b) {
  if (a.is_zero() || b.is_zero()) return false;
  if (a.degree() == 0 || b.degree() == 0) return true;  // a non-zero constant divides nothing of positive degree
  auto x = modp::image(a), y = modp::image(b);
  if (!x || !y) return false;
  return modp::gcd_degree(std::move(*x), std::move(*y)) == 0;
}

// True only if the gcd of the non-zero entries of a matrix of polynomials
// (rows of Poly<Rational>) is provably a constant: some entry is coprime to
// the first non-zero one (then so is their gcd with every other entry).
template <class Rows>
bool content_is_constant(const Rows& m) {
  const Poly<Rational>* first = nullptr;
  for (const auto& row : m)
    for (const Poly<Rational>& e : row) {
      if (e.is_zero()) continue;
      if (!first)
        first = &e;
      else if (coprime_mod_p(*first, e))
        return true;
    }
  return first && first->degree() == 0;
}

}  // namespace eccd

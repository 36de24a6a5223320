#pragma once
// The enclosures the cycloidal certificate's claims rest on
// (certificate/write/cycloidal_certificate.hpp), shared by its writer and its checker: MPFI
// at a fixed precision, Δ, Δ', g_k and the static test of
// kernel/cycloidal_motion.hpp / kernel/contact_status.hpp at a rational
// instant or over a rational interval.
//
// Statement. Each function returns a proved fact or Sign::uncertain /
// Status::uncertain: MPFI rounds outward, so an enclosure that excludes 0
// proves the sign of the exact value at every t of the argument.
//   delta_sign_at(t)         sign of Δ(t);
//   delta_sign_over(a, b)    sign of Δ on [a, b]: the natural enclosure, else
//                            the mean-value form Δ(m) + Δ'([a, b])([a, b] - m);
//   derivative_sign_over     sign of Δ' on [a, b] (forward mode, Dual);
//   root_free(a, b)          Δ has no root in [a, b]: delta_sign_over proves a
//                            sign, or Δ' has a proved sign and Δ(a), Δ(b) the
//                            same proved non-zero sign (monotone);
//   simple_root(a, b)        exactly one root in (a, b), simple: Δ(a), Δ(b)
//                            proved of opposite signs and Δ' proved non-zero;
//   status_at(t)             the static test (003 Theorem 6) at t;
//   status_at_root(a, b)     touching / overlapping at the root in [a, b]
//                            from the signs of P and D proved over [a, b];
//   magnitude_upper(a, b)    an upper bound (a rational) of |Δ| on [a, b].
// Requirements: a pair from cycloidal_pair<MpfiInterval> (kernel/cycloidal_motion.hpp).
#include "kernel/contact_status.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "number/dual.hpp"
#include "number/enclosure.hpp"
#include "number/mpfi_interval.hpp"

namespace eccd {

class CycloidalEnclosures {
 public:
  CycloidalEnclosures(const Scene& s, int bits)
      : like_(mpq_class(0), bits), pair_(cycloidal_pair<MpfiInterval>(s, like_)) {}

  Sign delta_sign_at(const mpq_class& t) const { return sign(cycloidal_delta<MpfiInterval>(pair_, point(t))); }
  Sign derivative_sign_over(const mpq_class& a, const mpq_class& b) const { return sign(derivative(a, b)); }
  Sign delta_sign_over(const mpq_class& a, const mpq_class& b) const {
    Sign s = sign(cycloidal_delta<MpfiInterval>(pair_, range(a, b)));
    if (s == Sign::positive || s == Sign::negative) return s;
    return sign(mean_value(a, b));
  }
  bool root_free(const mpq_class& a, const mpq_class& b) const {
    Sign s = delta_sign_over(a, b);
    if (s == Sign::positive || s == Sign::negative) return true;
    if (!proved_nonzero(derivative_sign_over(a, b))) return false;
    Sign sa = delta_sign_at(a), sb = delta_sign_at(b);
    return proved_nonzero(sa) && sa == sb;
  }
  // The proof of root_free(a, b) a cycloidal certificate names (format 2's gap_proofs): "natural",
  // "mean_value" or "monotone", or nullptr when none holds.
  const char* root_free_by(const mpq_class& a, const mpq_class& b) const {
    Sign s = sign(cycloidal_delta<MpfiInterval>(pair_, range(a, b)));
    if (proved_nonzero(s)) return "natural";
    if (proved_nonzero(sign(mean_value(a, b)))) return "mean_value";
    if (!proved_nonzero(derivative_sign_over(a, b))) return nullptr;
    Sign sa = delta_sign_at(a), sb = delta_sign_at(b);
    return proved_nonzero(sa) && sa == sb ? "monotone" : nullptr;
  }
  bool simple_root(const mpq_class& a, const mpq_class& b) const {
    Sign sa = delta_sign_at(a), sb = delta_sign_at(b);
    return proved_nonzero(sa) && proved_nonzero(sb) && sa != sb && proved_nonzero(derivative_sign_over(a, b));
  }
  Status status_at(const mpq_class& t) const {
    auto g = cycloidal_g<MpfiInterval>(pair_, point(t));
    return cubic_contact_status(g[3], g[2], g[1], g[0]);
  }
  Status status_at_root(const mpq_class& a, const mpq_class& b) const {
    auto g = cycloidal_g<MpfiInterval>(pair_, range(a, b));
    return status_at_multiple_root(sign(double_root_numerator(g[3], g[2], g[1], g[0])),
                                   sign(double_root_denominator(g[3], g[2], g[1])));
  }
  // max |Δ| over [a, b] from below by nothing: an upper bound, exact as a rational (an MPFR end point is dyadic).
  mpq_class magnitude_upper(const mpq_class& a, const mpq_class& b) const {
    MpfiInterval nat = cycloidal_delta<MpfiInterval>(pair_, range(a, b)), mv = mean_value(a, b);
    mpq_class x = bound(nat), y = bound(mv);
    return x < y ? x : y;
  }
  static bool proved_nonzero(Sign s) { return s == Sign::positive || s == Sign::negative; }

 private:
  MpfiInterval point(const mpq_class& t) const { return MpfiInterval(t, like_.precision()); }
  MpfiInterval range(const mpq_class& a, const mpq_class& b) const { return MpfiInterval(a, b, like_.precision()); }
  MpfiInterval derivative(const mpq_class& a, const mpq_class& b) const {
    return cycloidal_delta<Dual<MpfiInterval>>(pair_, Dual<MpfiInterval>(range(a, b), MpfiInterval(1))).d;
  }
  MpfiInterval mean_value(const mpq_class& a, const mpq_class& b) const {
    const mpq_class m = (a + b) / 2;
    return cycloidal_delta<MpfiInterval>(pair_, point(m)) +
           derivative(a, b) * range(mpq_class(a - m), mpq_class(b - m));
  }
  static mpq_class bound(const MpfiInterval& x) {
    mpq_class l, r;
    mpfr_get_q(l.get_mpq_t(), &x.get()->left);
    mpfr_get_q(r.get_mpq_t(), &x.get()->right);
    l = abs(l);
    r = abs(r);
    return l < r ? r : l;
  }

  MpfiInterval like_;
  CycloidalPair<MpfiInterval> pair_;
};

}  // namespace eccd

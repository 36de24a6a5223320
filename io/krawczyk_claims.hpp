#pragma once
// The checks of an end's Krawczyk claims in a certificate, shared by the
// independent-motion checker (io/independent_certificate.cpp) and the Bézier
// checker (io/bezier_certificate.cpp).
//
// Statement. Krawczyk 1969; Moore, Kearfott, Cloud, "Introduction to Interval
// Analysis", 2009, section 8.2 (certified/krawczyk.hpp): a chain X = Y_0, ...,
// Y_k of boxes with K(Y_0) inside the interior of Y_0 proves exactly one zero
// of the system in X; Y_{i+1} containing Y_i ∩ K(Y_i) keeps it in every Y_i.
// The claims re-checked: X's range along the proof's parameter (coordinate
// `param` of the boxes) covers the run [lo, hi]; K(X) inside X's interior;
// the chain's containments; and the bracket [b0, b1] inside [lo, hi] holding
// [lo, hi] ∩ Y_k's parameter range. A failure throws certificate_json::Reject
// naming `claim`.
// Requirements: Nets of F in MPFI built by the checker from the scene itself.
#include "certified/krawczyk.hpp"
#include "io/certificate_json.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace eccd {

inline void check_krawczyk_chain(krawczyk_detail::Nets& nets, const krawczyk_detail::System& sys, const std::vector<krawczyk_detail::Box>& Y,
                                 std::size_t param, const mpq_class& lo, const mpq_class& hi, const std::string& var, const std::string& claim) {
  using certificate_json::reject;
  const std::size_t m = sys.vars.size();
  const krawczyk_detail::Box& X = Y[0];
  if (X.lo[param] > lo || X.hi[param] < hi) reject(claim, "the Krawczyk box's " + var + "-range does not cover the run");
  krawczyk_detail::Box K;
  if (!krawczyk_detail::krawczyk(nets, sys, X, K))
    reject(claim, "Krawczyk's K(X) is not inside the interior of X: the box is not proved to hold one zero");
  for (std::size_t i = 0; i + 1 < Y.size(); ++i) {
    krawczyk_detail::Box K2;
    krawczyk_detail::krawczyk(nets, sys, Y[i], K2);
    if (K2.lo.size() != m) reject(claim, "K(Y_" + std::to_string(i) + ") is not computable");
    for (std::size_t v = 0; v < m; ++v)
      if (Y[i + 1].lo[v] > std::max(Y[i].lo[v], K2.lo[v]) || Y[i + 1].hi[v] < std::min(Y[i].hi[v], K2.hi[v]))
        reject(claim, "chain box " + std::to_string(i + 1) + " does not contain Y_" + std::to_string(i) + " ∩ K(Y_" + std::to_string(i) + ")");
  }
}

inline void check_krawczyk_bracket(const krawczyk_detail::Box& last, std::size_t param, const mpq_class& lo, const mpq_class& hi,
                                   const mpq_class& b0, const mpq_class& b1, const std::string& claim) {
  using certificate_json::reject;
  auto q = [](const mpq_class& x) { mpq_class y = x; y.canonicalize(); return y.get_str(); };
  const mpq_class need_lo = std::max(lo, last.lo[param]), need_hi = std::min(hi, last.hi[param]);
  if (need_lo > need_hi) reject(claim, "the last chain box misses the run");
  if (b0 > need_lo || b1 < need_hi || b0 < lo || b1 > hi)
    reject(claim, "the bracket [" + q(b0) + ", " + q(b1) + "] does not hold [" + q(need_lo) + ", " + q(need_hi) +
                      "] (the run ∩ the last chain box) inside the run");
}

}  // namespace eccd

// Proved 3D answers by the Bézier zero-set analysis in intervals (certified/bezier_proof.hpp).
// Placeholder until the engine lands: proves nothing, so every caller goes on as before.
#include "certified/bezier_proof.hpp"

namespace eccd {

BezierProofResult prove_bezier(const PreparedPair<4>&, const BezierProofOptions&) {
  BezierProofResult r;
  r.reason = "the interval Bézier proof is not built yet";
  return r;
}

}  // namespace eccd

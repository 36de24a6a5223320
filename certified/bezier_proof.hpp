#pragma once
// Proved answers of 3D scenes by 001's Bézier zero-set analysis in interval
// arithmetic: the certified method that decides typical
// 3D scenes without the projection polynomial.
//
// Statement. Paper 001, section 4: with F(u, t) = det((u - 1)A(t) - uB(t))
// (kernel/ellipsoid_function.hpp, u in [0, 1]), the ellipsoids are separate at
// t iff G(t) = max_u F(u, t) > 0; F(0, t) = det A(t) < 0 and F(1, t) = det B(t) < 0
// (the faces u = 0 and u = 1 are checked once), so a maximum equal to 0
// lies inside (0, 1). The proof covers [0, 1] by pieces, in order:
//   - "out" strip [lo, hi]: boxes U_i x T_i, the T_i covering [lo, hi], on
//     each of which every control point of F's net (enclosed in intervals,
//     restricted by de Casteljau) is > 0: G > 0 on the strip (separate);
//   - "in" strip [lo, hi]: boxes U_i x [lo, hi], the U_i covering [0, 1],
//     every control point < 0: F < 0 for every u, G < 0 (overlap);
//   - an "end": a run [lo, hi] between an in and an out strip. Lemma: an end
//     t* of the collision set has F = F_u = 0 at some (u*, t*), u* in (0, 1).
//     Krawczyk's test on (F, F_u) in (u, t) over a box X whose t-range covers
//     [lo, hi] proves exactly one zero in X; the rest of [0, 1] x [lo, hi] is
//     excluded (F or F_u of one sign on each box of a subdivision). G changes
//     sign on [lo, hi] (out at one end, in at the other) and vanishes only at
//     that zero's t, so [lo, hi] holds exactly one end, in the bracket
//     (Krawczyk's t-range, iterated, intersected with [lo, hi]).
// What is not claimed (the ladder goes on to the projection rungs): a run
// between two out strips or two in strips (a touch, a near miss, a collision
// narrower than the strips), an end whose Krawczyk test or exclusion fails.
// Requirements: a prepared 3D pair (exact); intervals of doubles and MPFI.
#include "kernel/answer.hpp"
#include "kernel/prepared_scene.hpp"
#include "number/rational_traits.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eccd {

// ---- Contract between the engine (certified/bezier_proof.cpp) and the
// ---- certificate (certificate/write/bezier_certificate.*): fields may be added, never
// ---- renamed or removed.
struct BezierProofOptions {
  int strip_depth = 16;        // strips of t down to 2^-strip_depth
  int u_depth = 10;            // u-subdivision of one strip, at most this deep
  long max_boxes = 20000;      // work cap (boxes tested in all)
  int bits = 160;              // MPFI precision of the enclosed net for the ends (Krawczyk)
  bool first_contact = false;  // stop after the first collision interval (its end still proved)
  bool record = false;         // keep the proof in BezierProofResult::pieces (for the certificate)
};

// A box [u_lo, u_hi] x [t_lo, t_hi] of the (u, t) square, rational corners.
struct BezierBox {
  Rational u_lo, u_hi, t_lo, t_hi;
};

// One piece of the proof, in t order; the pieces cover [0, 1] without gaps
// (each piece's lo is the previous one's hi).
struct BezierPiece {
  enum Kind { out, in, end } kind = out;
  Rational lo, hi;
  // out: every control point > 0 on each box; the t-ranges cover [lo, hi].
  // in: every control point < 0 on each box; t-range [lo, hi], the u-ranges cover [0, 1].
  // end: the Krawczyk chain X = Y_0, ..., Y_k on (F, F_u) in (u, t): K(Y_0)
  //      inside the interior of Y_0, Y_{i+1} contains Y_i ∩ K(Y_i); Y_0's
  //      t-range covers [lo, hi].
  std::vector<BezierBox> boxes;
  Rational bracket_lo, bracket_hi;  // end only: the end's bracket, inside [lo, hi]
};

struct BezierProofResult {
  bool decided = false;  // everything on [0, 1] proved (else `reason` says where and why)
  std::string reason;
  Answer answer;                    // intervals, first_contact, contacts (the proved ends), collides; when decided
  std::vector<BezierPiece> pieces;  // when options.record (and decided)
  std::vector<std::pair<std::string, long>> work;  // counters
};

// The proof for a prepared 3D pair (rational motions). Never throws for an
// undecidable scene: decided = false with the reason. Honours the running
// thread's deadline (kernel/budget.hpp: BudgetExhausted).
BezierProofResult prove_bezier(const PreparedPair<4>& p, const BezierProofOptions& options);

}  // namespace eccd

#pragma once
// Regression against stored exact answers (eccd regress, and the CI test).
//
// Statement: a stored answer and a recomputed exact answer agree
// when api/answer_difference.hpp (the one comparison of answers) finds no
// difference between them: the same `collides`, the collision intervals one
// to one with matching ends, the same external contacts and contact
// intervals (continuous touching; a stored answer without the key has none),
// the same first contact. Two certified instants match when their brackets
// overlap: a bracket of the recomputed answer holds exactly one root of the
// projection, so a stored certified bracket that overlaps it cannot be off by
// more than the two widths (2^-64 each by default). A stored instant without
// a bracket is compared by its decimal, read exactly: the recomputed bracket,
// widened by 1e-12, must contain it. Decisions use exact rationals.
#include "api/answer_difference.hpp"

#include <string>
#include <vector>

namespace eccd {

// The differences in words ("collision interval 1 end off by 0.1 (stored 0.9,
// recomputed 1)"); empty when the answers agree.
inline std::vector<std::string> regress_differences(const Answer& stored, const Answer& recomputed) {
  DifferenceOptions o;
  o.tol = 1e-12;
  o.answer_name = "recomputed";
  o.reference_name = "stored";
  return answer_difference(recomputed, stored, o).differences;
}

}  // namespace eccd

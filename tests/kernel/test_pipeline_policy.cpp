// The pipeline policy concept (kernel/pipeline_policy.hpp): the policies the
// solver builds are models of it, other types are not, and the optional hooks
// are where the header says.
#include "certified/certified_policy.hpp"
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "kernel/pipeline_policy.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace eccd;

TEST_CASE("the pipeline policies satisfy the concept, other types do not", "[kernel][policy]") {
  struct NotAPolicy {
    using Rep = Poly<Rational>;
    using Root = int;
  };
  STATIC_REQUIRE(PipelinePolicy<ExactPolicy, Rational>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<double>, double>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Mpfr>, Mpfr>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Bounded<double>>, Bounded<double>>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Bounded<Mpfr>>, Bounded<Mpfr>>);
  STATIC_REQUIRE(PipelinePolicy<CertifiedPolicy<Interval>, Interval>);
  STATIC_REQUIRE(PipelinePolicy<CertifiedPolicy<MpfiInterval>, MpfiInterval>);
  STATIC_REQUIRE_FALSE(PipelinePolicy<NotAPolicy, Rational>);
  STATIC_REQUIRE_FALSE(PipelinePolicy<ExactPolicy, double>);  // an exact policy takes rational instants
  // the optional hooks: rounded policies have them, exact and interval ones do not
  STATIC_REQUIRE(ReportsTrouble<FloatingPolicy<double>>);
  STATIC_REQUIRE(KeepsNotes<FloatingPolicy<double>>);
  STATIC_REQUIRE(NormalisesG<FloatingPolicy<double>, std::vector<Poly<double>>>);
  STATIC_REQUIRE(MayBeUnresolved<FloatRoot<double>>);
  STATIC_REQUIRE(SettlesStatus<CertifiedPolicy<Interval>, Interval>);
  STATIC_REQUIRE_FALSE(ReportsTrouble<ExactPolicy>);
  STATIC_REQUIRE_FALSE(NormalisesG<ExactPolicy, std::vector<Poly<Rational>>>);
  STATIC_REQUIRE_FALSE(MayBeUnresolved<AlgebraicRoot>);
  STATIC_REQUIRE_FALSE(SettlesStatus<FloatingPolicy<double>, double>);
}

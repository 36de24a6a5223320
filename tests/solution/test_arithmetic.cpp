// solution/arithmetic.hpp: the arithmetic names of the command line. Checked
// against the header's grammar ("double", "mpfr:BITS" with 53 <= BITS <=
// 65536, "exact", "certified" = MPFI rung 256, "certified:B1,B2,..."
// increasing, each 54..65536, "certified:none"): every accepted name parses
// to the kind, bits and rungs it says and Arithmetic::name gives it back
// (parse and name inverse); precision_bits is 53 / BITS / 0 as stated; the
// factory functions agree with parsing; every malformed name is refused with
// std::invalid_argument whose message starts "--arith TEXT: ".
#include "solution/arithmetic.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("parse_arithmetic and Arithmetic::name are inverse on every form", "[solution][arithmetic]") {
  struct Want {
    const char* text;
    Arithmetic::Kind kind;
    int bits;
    std::vector<int> rungs;
    int precision;
  };
  const Want cases[] = {
      {"double", Arithmetic::Double, 0, {}, 53},
      {"exact", Arithmetic::Exact, 0, {}, 0},
      {"mpfr:53", Arithmetic::Mpfr, 53, {}, 53},
      {"mpfr:200", Arithmetic::Mpfr, 200, {}, 200},
      {"mpfr:65536", Arithmetic::Mpfr, 65536, {}, 65536},
      {"certified", Arithmetic::Certified, 0, {256}, 53},
      {"certified:none", Arithmetic::Certified, 0, {}, 53},
      {"certified:54", Arithmetic::Certified, 0, {54}, 53},
      {"certified:128,512,4096", Arithmetic::Certified, 0, {128, 512, 4096}, 53},
  };
  for (const Want& w : cases) {
    INFO(w.text);
    const Arithmetic a = parse_arithmetic(w.text);
    CHECK(a.kind == w.kind);
    if (w.kind == Arithmetic::Mpfr) CHECK(a.mpfr_bits == w.bits);
    CHECK(a.mpfi_rungs == w.rungs);
    CHECK(a.precision_bits() == w.precision);
    CHECK(a.name() == w.text);
    CHECK(a.floating() == (w.kind == Arithmetic::Double || w.kind == Arithmetic::Mpfr));
  }
  // "certified:256" is the default ladder: it is named "certified"
  CHECK(parse_arithmetic("certified:256").name() == "certified");
  // the factories
  CHECK(Arithmetic::exact().name() == "exact");
  CHECK(Arithmetic::double_precision().name() == "double");
  CHECK(Arithmetic::mpfr(300).name() == "mpfr:300");
  CHECK(Arithmetic::certified().name() == "certified");
  CHECK(Arithmetic::certified({}).name() == "certified:none");
  CHECK(Arithmetic::certified({100, 200}).mpfi_rungs == std::vector<int>{100, 200});
  CHECK(Arithmetic{}.kind == Arithmetic::Exact);  // the default
}

TEST_CASE("parse_arithmetic refuses malformed names with the text in the message", "[solution][arithmetic]") {
  const char* bad[] = {"",
                       "Double",
                       "mpfr",
                       "mpfr:",
                       "mpfr:52",
                       "mpfr:65537",
                       "mpfr:12x",
                       "mpfr:-64",
                       "mpfr:1234567",
                       "certified:",
                       "certified:53",
                       "certified:65537",
                       "certified:256,128",
                       "certified:256,256",
                       "certified:,256",
                       "certified:256,",
                       "certified:none,256",
                       "interval",
                       "exact "};
  for (const char* b : bad) {
    INFO("'" << b << "'");
    try {
      parse_arithmetic(b);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).rfind(std::string("--arith ") + b + ": ", 0) == 0);
    }
  }
  CHECK_THROWS_AS(Arithmetic::mpfr(20), std::invalid_argument);
  CHECK_THROWS_AS(Arithmetic::certified({300, 200}), std::invalid_argument);
}

}  // namespace ECCD_UNITY_ID

// `eccd generate --families cycloidal,independent` from the command line
// (issue 20): the files are written, read back by the reader, and are of the
// promised motions (compare/motion_families.hpp); the kinds themselves are
// checked against the pipelines in tests/compare/test_motion_families.cpp.
#include "io/scene_reader.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;

TEST_CASE("generate --families cycloidal,independent writes 2D cycloidal and 2D and 3D independent scenes",
          "[cli][cycloidal][independent]") {
  TempDir d;
  Run r = run_eccd("generate --out-dir " + q((d.path / "g").string()) +
                   " --families cycloidal,independent --count 3 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  int cyc = 0, indep2 = 0, indep3 = 0;
  for (const auto& e : std::filesystem::directory_iterator(d.path / "g")) {
    eccd::Scene s = eccd::read_scene_file(e.path().string());
    if (s.independent) {
      ++(s.dim == 2 ? indep2 : indep3);
      CHECK((s.dim == 2 || s.dim == 3));
      CHECK(s.note.find("family=independent") != std::string::npos);
    } else {
      ++cyc;
      CHECK(s.dim == 2);
      CHECK(eccd::has_cycloidal_motion(s));
      CHECK(s.note.find("family=cycloidal") != std::string::npos);
    }
  }
  CHECK(cyc == 3);
  CHECK(indep2 == 3);  // --count 3 per dimension (the default --dims 2,3)
  CHECK(indep3 == 3);
  // a dimension without either family: nothing to generate (exit 2)
  Run none = run_eccd("generate --out-dir " + q((d.path / "h").string()) + " --families cycloidal --dims 3");
  CHECK(none.code == 2);
}

}  // namespace ECCD_UNITY_ID

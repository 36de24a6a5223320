// The compiled part of the Python package eccd (python/eccd/, which
// re-exports it as `eccd`): the typed C++ API (include/eccd/eccd.hpp) for
// Python, with pybind11. Nothing is computed here: every function calls the
// API and converts its types.
//
//   import eccd
//   s = eccd.read_scene("cases/paper003/example2.json")   # or eccd.scene_from_dict(d), eccd.scene_from_text(t)
//   r = eccd.solve(s, arith="exact")                        # "double", "mpfr:128", "exact", "certified", ...
//   r.collides, r.intervals, r.first_contact, r.contacts    # instants: .approx (float), .lo / .hi (Fraction or None)
//   eccd.animate("cases/animations/swarm-2d.json", arith="certified")   # the animation answer, a dict
//   eccd.separate(s, "1/3")                                 # a separating plane at t = 1/3, a dict
//
// Types: an Instant's bracket [lo, hi] is exact (fractions.Fraction, made
// from the rational's text, never through a float); .approx is the
// approximation as a float, for display only. Instants order by their exact
// value where certified (the brackets of one list are disjoint), by .approx
// otherwise. Statuses are members of eccd.Status, a str Enum. Errors: a bad
// scene raises eccd.SceneError (a ValueError) whose message names the file,
// the place and what is wrong (bytes that are not UTF-8 and NUL written as
// \xNN escapes); a missing file FileNotFoundError; a bad keyword value
// ValueError naming the keyword (arith='quad', not --arith quad); a run past
// its time_limit TimeoutError.
//
// The bindings are in python/bind_*.cpp, one file per topic, over the shared
// conversions of python/bindings.hpp.
#include "bindings.hpp"

PYBIND11_MODULE(_eccd, m) {
  m.doc() =
      "eccd's compiled core (import eccd): exact continuous collision detection of moving ellipses and ellipsoids";
  m.attr("__version__") = ECCD_VERSION;

  eccd_python::bind_errors(m);
  eccd_python::bind_status(m);
  eccd_python::bind_answers(m);
  eccd_python::bind_solution(m);
  eccd_python::bind_scenes(m);
  eccd_python::bind_static(m);
  eccd_python::bind_certify(m);
  eccd_python::bind_judge(m);
  eccd_python::bind_animation(m);
  eccd_python::bind_fcl(m);
  eccd_python::bind_animate(m);
  eccd_python::bind_separate(m);
  eccd_python::bind_solve(m);
}

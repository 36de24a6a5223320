// 2D CCD.
#include "bench/groups.hpp"

namespace eccd_bench::groups {

const char* variant_title(int v) {
  switch (v) {
    case 1:
      return "Variant 1 (collides?)";
    case 2:
      return "Variant 2 (first contact)";
    case 3:
      return "Variant 3 (all external contacts)";
    default:
      return "full answer (intervals, first contact, contacts)";
  }
}

void add_2d_rows(const std::string& grp, Lazy<Scene2D>* sc, int v, bool mpfr = true) {
  Variant var = Variant(v);
  auto note = [sc](const std::string& what) { return what; };
  row(grp, "double", true, Cost::slow, note("to_arithmetic<double,3> + cd_disc, FloatingPolicy<double> (Bernstein)"),
      [sc, var, grp](benchmark::State& st) {
        const Scene2D& s = sc->get();
        note_scene(s);
        timed(
            st, grp + "/double", [&] { return run2d_double(s.p, var); },
            [](const auto& r) { return summarise_ccd(r); });
      });
  if (mpfr)
    for (int bits : {128, 256}) {
      std::string label = "mpfr:" + std::to_string(bits);
      row(grp, label, false, Cost::slow, "to_arithmetic<Mpfr,3> + cd_disc, FloatingPolicy<Mpfr> (Bernstein)",
          [sc, var, grp, label, bits](benchmark::State& st) {
            const Scene2D& s = sc->get();
            note_scene(s);
            Mpfr like(mpq_class(1), bits);
            timed(
                st, grp + "/" + label, [&] { return run2d_floating<Mpfr>(s.p, var, Basis::bernstein, bits, like); },
                [](const auto& r) { return summarise_ccd(r); });
          });
    }
  row(grp, "exact", false, Cost::slow, "to_arithmetic<Rational,3> + cd_disc, ExactPolicy (certified)",
      [sc, var, grp](benchmark::State& st) {
        const Scene2D& s = sc->get();
        note_scene(s);
        timed(
            st, grp + "/exact", [&] { return run2d_exact(s.p, var); }, [](const auto& r) { return summarise_ccd(r); });
      });
}

void register_2d() {
  for (int k : {2, 4, 6}) {
    for (int v : {1, 2, 3, 0}) {
      std::string grp = "ccd2d-deg" + std::to_string(k) + "-v" + std::to_string(v);
      std::string anchor = k == 6 ? (v == 1   ? "003 Fig. 8: under 1 ms (degree 6, 2.2 GHz Intel)"
                                     : v == 2 ? "003 Fig. 8: under 5 ms"
                                     : v == 3 ? "003 Fig. 8: under 7 ms; speed target: double at most 50 µs"
                                              : "speed target: exact certified answer at most 5 ms")
                                  : "003 Fig. 8 (curves for degrees 2 and 4 lie below the degree-6 figures)";
      group(grp, "2D CCD, motion degree " + std::to_string(k) + ", " + variant_title(v),
            "CD-DISC on a colliding pair of ellipses under general rational Euclidean motions of degree " +
                std::to_string(k) + " (Δ of degree " + std::to_string(24 * k) +
                ", two or more external contacts); baseline: double.",
            anchor);
      add_2d_rows(grp, scene2d_by_degree(k), v);
    }
  }
  group("ccd2d-deg6-free", "2D CCD, motion degree 6, a collision-free pair",
        "The same pipelines on a pair that never collides (Δ of degree 144 without roots in [0, 1]: 003 Fig. 8(b)).",
        "003 Fig. 8(b): collision-free pairs, degree 6");
  {
    Lazy<Scene2D>* sc = &s2d_deg6_free;
    for (int v : {1, 3}) {
      std::string label = "double v" + std::to_string(v);
      row("ccd2d-deg6-free", label, v == 3, Cost::slow, "to_arithmetic + cd_disc, double, Bernstein",
          [sc, v, label](benchmark::State& st) {
            const Scene2D& s = sc->get();
            note_scene(s);
            timed(
                st, "ccd2d-deg6-free/" + label, [&] { return run2d_double(s.p, Variant(v)); },
                [](const auto& r) { return summarise_ccd(r); });
          });
    }
    row("ccd2d-deg6-free", "exact v0", false, Cost::slow, "to_arithmetic + cd_disc, ExactPolicy",
        [sc](benchmark::State& st) {
          const Scene2D& s = sc->get();
          note_scene(s);
          timed(
              st, "ccd2d-deg6-free/exact v0", [&] { return run2d_exact(s.p, Variant::answer); },
              [](const auto& r) { return summarise_ccd(r); });
        });
  }
  group("ccd2d-deg6-basis", "2D CCD, motion degree 6, Variant 3: how Δ is built (003 VI-C)",
        "Double CD-DISC with g_i and Δ in Bernstein form (the default), in power form (converted for the "
        "subdivision), and in scaled Bernstein form (003's choice for Variant 1); MPFR at 128 bits in power form.",
        "003 Fig. 8 (dashed lines: time to obtain Δ in Bernstein and scaled Bernstein form)");
  {
    Lazy<Scene2D>* sc = &s2d_deg6;
    struct B {
      const char* label;
      Basis basis;
      int bits;
    };
    for (B b : {B{"double bernstein", Basis::bernstein, 53}, B{"double power", Basis::power, 53},
                B{"double scaled-bernstein", Basis::scaled_bernstein, 53}, B{"mpfr:128 power", Basis::power, 128}}) {
      std::string label = b.label;
      row("ccd2d-deg6-basis", label, b.basis == Basis::bernstein, Cost::slow,
          std::string("cd_disc, basis ") + to_string(b.basis), [sc, b, label](benchmark::State& st) {
            const Scene2D& s = sc->get();
            note_scene(s);
            if (b.bits == 53)
              timed(
                  st, "ccd2d-deg6-basis/" + label, [&] { return run2d_double(s.p, Variant::all_contacts, b.basis); },
                  [](const auto& r) { return summarise_ccd(r); });
            else {
              Mpfr like(mpq_class(1), b.bits);
              timed(
                  st, "ccd2d-deg6-basis/" + label,
                  [&] { return run2d_floating<Mpfr>(s.p, Variant::all_contacts, b.basis, b.bits, like); },
                  [](const auto& r) { return summarise_ccd(r); });
            }
          });
    }
  }
  group("ccd2d-paper003", "2D CCD, paper 003's Example 2 (degree 4, Δ of degree 96, touch at t = 1/2)",
        "cases/paper003/example2.json: Variant 3 and the full answer.", "003 section VI-C, Example 2");
  add_2d_rows("ccd2d-paper003", &s2d_paper003, 3, false);
}

}  // namespace eccd_bench::groups

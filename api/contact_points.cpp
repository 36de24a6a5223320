// Contact points and normals of a solved 3D scene (api/contact_points.hpp).
#include "api/contact_points.hpp"

#include "floating/rounded_input.hpp"
#include "kernel/contact_geometry.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "number/mpfr_real.hpp"
#include "number/rational_traits.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

namespace eccd {

namespace {

template <class T>
std::vector<std::string> shown(const EVector<T, 3>& v) {
  std::vector<std::string> out;
  for (int i = 0; i < 3; ++i) {
    if (sign(v(i)) == Sign::zero) {
      out.push_back("0");
      continue;
    }  // not "-0"
    if constexpr (std::is_same_v<T, double>)
      out.push_back(scalar_traits<double>::to_string(v(i)));
    else
      out.push_back(round_decimal(scalar_traits<Mpfr>::to_string(v(i)), 20));
  }
  return out;
}

template <class T>
ContactPoint point_of(const ContactGeometry<T, 4>& g) {
  ContactPoint cp;
  if (!g.ok) return cp;
  cp.x = shown<T>(g.point);
  cp.normal = shown<T>(g.normal);
  return cp;
}

template <class T>
std::optional<MovingPair<T, 4>>& rounded_pair_cache(std::optional<MovingPair<double, 4>>& d,
                                                    std::optional<MovingPair<Mpfr, 4>>& m) {
  if constexpr (std::is_same_v<T, double>)
    return d;
  else
    return m;
}

mpq_class instant_value(const Instant& i) {
  if (i.certified()) return (*i.lo + *i.hi) / 2;
  if (std::isfinite(i.value)) return mpq_class(i.value);
  return mpq_class(-1);
}

}  // namespace

void add_contact_points_3d(const Scene& scene, Solution& s, const PreparedPair<4>* given) {
  if (scene.dim != 3 || scene.independent || s.answer.contacts.empty() ||
      s.answer.contact_points.size() >= s.answer.contacts.size())
    return;
  for (const SceneObject* o : {&scene.a, &scene.b})
    if (std::holds_alternative<CycloidalMotion>(o->motion)) return;
  std::vector<ContactPoint> pts;
  const bool floating = s.arith.kind == Arithmetic::Double || s.arith.kind == Arithmetic::Mpfr;
  std::optional<PreparedPair3> prepared;
  std::optional<MovingPair<double, 4>> double_pair;
  std::optional<MovingPair<Mpfr, 4>> mpfr_pair;
  std::string double_trouble, mpfr_trouble;
  for (const Instant& c : s.answer.contacts) {
    const mpq_class t = instant_value(c);
    if (sgn(t) < 0 || t > 1) {
      pts.push_back({});
      continue;
    }
    if (!floating) {  // exact A(t), B(t) at the rational t, then MPFR at 256 bits
      if (!given && !prepared) prepared = prepare_pair<H_3D>(scene);
      const PreparedPair3& pp = given ? *given : *prepared;
      const Rational rt(t);
      Matrix<Rational, 4> a = quadric_at<Rational, 4>(pp.qa, pp.na, rt);
      Matrix<Rational, 4> b = quadric_at<Rational, 4>(pp.qb, pp.nb, rt);
      Matrix<Mpfr, 4> am, bm;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          am[i][j] = Mpfr(a[i][j], 256);
          bm[i][j] = Mpfr(b[i][j], 256);
        }
      pts.push_back(point_of<Mpfr>(contact_geometry<Mpfr, 4>(am, bm)));
      continue;
    }
    auto run = [&](const auto& like) {
      using T = std::decay_t<decltype(like)>;
      // The rounded pair is made once per scene, not once per contact.
      static_assert(std::is_same_v<T, double> || std::is_same_v<T, Mpfr>);
      std::optional<MovingPair<T, 4>>& cached = rounded_pair_cache<T>(double_pair, mpfr_pair);
      std::string& trouble = std::is_same_v<T, double> ? double_trouble : mpfr_trouble;
      if (!cached) cached = round_pair<T, 4>(scene, like, trouble);
      const MovingPair<T, 4>& m = *cached;
      if (!trouble.empty()) return ContactPoint{};
      const T tt = scalar_traits<T>::from_rational(t, like);
      return point_of<T>(contact_geometry<T, 4>(quadric_at<T, 4>(m.qa, m.na, tt), quadric_at<T, 4>(m.qb, m.nb, tt)));
    };
    pts.push_back(s.arith.kind == Arithmetic::Double ? run(1.0) : run(Mpfr(mpq_class(1), s.arith.mpfr_bits)));
  }
  s.answer.contact_points = pts;
}

}  // namespace eccd

// Scene generators (see compare/scene_generator.hpp for the constructions).
#include "compare/scene_generator.hpp"

#include "compare/scene_building.hpp"

#include "compare/motion_families.hpp"
#include "compare/seeded_rng.hpp"

#include "kernel/bernstein.hpp"
#include "kernel/keyframe_motion.hpp"
#include "kernel/motion.hpp"
#include "kernel/poly_matrix.hpp"
#include "io/scene_reader.hpp"
#include "kernel/sturm.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace eccd {

namespace {

std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  SeededRng r{a ^ (b * 0x2545f4914f6cdd1dULL)};
  return r.next();
}
std::uint64_t hash_string(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace

namespace scene_building {

namespace {

// ---- motions with a prescribed centre path ---------------------------------

// Bernstein control points of a centre path of degree p inside a box.
struct Box {
  Vec lo, hi;
};
std::vector<Vec> control_points(Rng& r, int p, const Box& box) {
  std::vector<Vec> c(p + 1);
  for (auto& pt : c)
    for (std::size_t i = 0; i < box.lo.size(); ++i) {
      Rational span = box.hi[i] - box.lo[i];
      pt.push_back(box.lo[i] + span * r.frac(0, 16, 16));
    }
  return c;
}
std::vector<RPoly> path_polys(const std::vector<Vec>& ctrl) {
  std::vector<RPoly> out;
  for (std::size_t i = 0; i < ctrl[0].size(); ++i) {
    Vec c;
    for (auto& pt : ctrl) c.push_back(pt[i]);
    out.push_back(from_bernstein(c));
  }
  return out;
}

Motion kinematic_motion(Rng& r, int k, const std::vector<RPoly>& centre) {
  while (true) {
    RPoly d2 = random_poly(r, k, -4, 4, 2), d3 = random_poly(r, k, -4, 4, 2);
    if (k == 0 && d2.is_zero() && d3.is_zero()) continue;
    if (badly_scaled(d2 * d2 + d3 * d3)) continue;
    KinematicMotion km;
    km.d[0] = Rational(1, 2) * (centre[0] * d3 + centre[1] * d2);
    km.d[1] = Rational(1, 2) * (centre[1] * d3 - centre[0] * d2);
    km.d[2] = d2;
    km.d[3] = d3;
    return km;
  }
}
Motion euler_motion(Rng& r, int k, const std::vector<RPoly>& centre) {
  while (true) {
    EulerMotion em;
    for (auto& e : em.e) e = random_poly(r, k, -4, 4, 2);
    RPoly E = em.e[0] * em.e[0] + em.e[1] * em.e[1] + em.e[2] * em.e[2] + em.e[3] * em.e[3];
    if (badly_scaled(E)) continue;
    for (int i = 0; i < 3; ++i) em.v[i] = centre[i];
    em.v3 = constant(1);
    return em;
  }
}
Motion affine_motion(Rng& r, int deg, const std::vector<RPoly>& centre) {
  while (true) {
    Vec axis = random_unit(r, 3);
    Vec m = random_unit(r, 3);
    Mat R0 = (dot(axis, m) == -1) ? identity(3) : rotation_taking(r, axis, m);
    MatrixMotion mm;
    mm.m.assign(4, std::vector<RPoly>(4));
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        Vec c;
        for (int q = 0; q <= deg; ++q) c.push_back(R0[i][j] + r.frac(-3, 3, 10));
        mm.m[i][j] = from_bernstein(c);
      }
      mm.m[i][3] = centre[i];
    }
    mm.m[3][3] = constant(1);
    PolyMatrix<Rational, 3> L{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) L[i][j] = mm.m[i][j];
    if (badly_scaled(det<Rational, 3>(L))) continue;
    return mm;
  }
}

// (k, p) with 2k + p = deg: rotation degree k, centre-path degree p.
std::pair<int, int> split_degree(Rng& r, int deg) {
  int k = int(r.uniform(0, deg / 2));
  if (deg >= 2 && k == 0 && r.uniform(0, 1)) k = 1;  // prefer some rotation
  return {k, deg - 2 * k};
}

Motion random_motion(Rng& r, const std::string& kind, int deg, const std::vector<RPoly>& centre, int k) {
  if (kind == "kinematic") return kinematic_motion(r, k, centre);
  if (kind == "euler") return euler_motion(r, k, centre);
  return affine_motion(r, deg, centre);
}

}  // namespace

// colliding / free: independent motions with controlled centre paths.
Built build_random(Rng& r, const GeneratorSpec& s) {
  Built b;
  b.alpha_a = random_axes(r, s.dim);
  b.alpha_b = random_axes(r, s.dim);
  auto [ka, pa] = split_degree(r, s.degree);
  auto [kb, pb] = split_degree(r, s.degree);
  if (s.motion == "affine") pa = pb = s.degree;
  Box box{Vec(s.dim, Rational(-5)), Vec(s.dim, Rational(5))};
  Box box_a = box, box_b = box;
  if (s.family == "free") {
    // bounding radius <= 2 (squared semi-axes <= 4), times 1.9 for affine.
    Rational R = s.motion == "affine" ? Rational(4) : Rational(2);
    Rational gap = r.frac(1, 10, 10);
    box_a.hi[0] = -(R + gap);
    box_a.lo[0] = box_a.hi[0] - 6;
    box_b.lo[0] = R + gap;
    box_b.hi[0] = box_b.lo[0] + 6;
  }
  auto ca = control_points(r, pa, box_a), cb = control_points(r, pb, box_b);
  if (s.family == "colliding") {
    Rational t1 = r.frac(1, 15, 16);
    auto at = [&](const std::vector<Vec>& c, int i) {
      Vec v;
      for (auto& pt : c) v.push_back(pt[i]);
      Bern<Rational> q;
      q.b = v;
      return q(t1);
    };
    for (int i = 0; i < s.dim; ++i) {
      Rational shift = at(ca, i) - at(cb, i);
      for (auto& pt : cb) pt[i] += shift;
    }
  }
  b.ma = random_motion(r, s.motion, s.degree, path_polys(ca), ka);
  b.mb = random_motion(r, s.motion, s.degree, path_polys(cb), kb);
  return b;
}

// touch / near-miss: see the header.
Built build_touch(Rng& r, const GeneratorSpec& s) {
  Built b;
  const int dim = s.dim;
  Rational t0 = r.frac(4, 16, 20);
  b.t0 = t0;
  Rational delta = 0;
  if (s.family == "near-miss") {
    mpz_class ten = 1;
    for (int i = 0; i < s.d_exponent; ++i) ten *= 10;
    delta = Rational(mpz_class(1), ten);
  }
  Vec n = random_unit(r, dim), m;
  do m = random_unit(r, dim);
  while (dot(m, n) == -1);
  Tangency ta = shape_with_normal(r, n), tb = shape_with_normal(r, m);
  b.alpha_a = ta.alpha;
  b.alpha_b = tb.alpha;
  const Vec& p = ta.point;
  Mat RB = rotation_taking(r, m, n);
  Vec cB = mat_vec(RB, tb.point);
  for (int i = 0; i < dim; ++i) cB[i] = p[i] - cB[i];
  HMat PB = hconst(RB, cB);
  // Degrees: s(t) of degree ds in {2, 3}; a 3D twist of degree 2kt; G the rest.
  int ds, kt, g;
  do {
    ds = int(r.uniform(2, 3));
    kt = dim == 3 ? int(r.uniform(0, 1)) : 0;
    g = s.degree - ds - 2 * kt;
  } while (g < 0);
  // s(t) = σ(t) n + a(t) τ.
  RPoly tt(std::vector<Rational>{Rational(-t0), Rational(1)});  // t - t0
  Vec hc;
  for (int i = 0; i <= ds - 2; ++i) hc.push_back(r.frac(2, 12, 4));
  RPoly sigma = constant(delta) + tt * tt * from_bernstein(hc);
  RPoly a = tt * random_poly(r, ds - 1, -4, 4, 2);
  Vec tau = dim == 2 ? Vec{-n[1], n[0]} : orthogonal_to(r, n);
  HMat T = hconst(identity(dim), Vec(dim, Rational(0)));
  for (int i = 0; i < dim; ++i) T[i][dim] = sigma * constant(n[i]) + a * constant(tau[i]);
  HMat motion_b = hmul(T, PB);
  if (kt > 0) {  // twist about the line through p along n (keeps the tangent plane)
    while (true) {
      RPoly c = random_poly(r, kt, -3, 3, 1), sn = random_poly(r, kt, -3, 3, 1);
      Poly<Rational> q[4] = {c, sn * constant(n[0]), sn * constant(n[1]), sn * constant(n[2])};
      RPoly E = c * c + sn * sn;
      if (badly_scaled(E)) continue;
      auto Rq = quaternion_matrix(q);
      HMat tw(4, std::vector<RPoly>(4));
      for (int i = 0; i < 3; ++i) {
        RPoly acc = E * constant(p[i]);
        for (int j = 0; j < 3; ++j) {
          tw[i][j] = Rq[i][j];
          acc -= Rq[i][j] * constant(p[j]);
        }
        tw[i][3] = acc;
      }
      tw[3][3] = E;
      motion_b = hmul(T, hmul(tw, PB));
      break;
    }
  }
  // The common motion G of degree g; A = G, B = G * motion_b.
  std::vector<RPoly> centre = path_polys(control_points(r, 0, Box{Vec(dim, Rational(-3)), Vec(dim, Rational(3))}));
  int k = 0;
  if (s.motion == "affine") {
    centre = path_polys(control_points(r, g, Box{Vec(dim, Rational(-3)), Vec(dim, Rational(3))}));
  } else {
    auto [kg, pg] = split_degree(r, g);
    k = kg;
    centre = path_polys(control_points(r, pg, Box{Vec(dim, Rational(-3)), Vec(dim, Rational(3))}));
  }
  b.ma = random_motion(r, s.motion, g, centre, k);
  HMat G = dim == 2 ? to_hmat<3>(b.ma) : to_hmat<4>(b.ma);
  MatrixMotion mb;
  mb.m = hmul(G, motion_b);
  b.mb = mb;
  return b;
}

}  // namespace scene_building

namespace {
using scene_building::build_decimal;
using scene_building::build_keyframe;
using scene_building::build_linear_overlap;
using scene_building::build_random;
using scene_building::build_touch;
using scene_building::Built;
using scene_building::g_decimal_output;
using scene_building::motion_degree;
using scene_building::motion_json;
using scene_building::pow10;
using scene_building::Rng;
using scene_building::semi_axes_json;
using scene_building::shape_json;
}  // namespace

std::vector<std::string> motions_for(int dim) {
  if (dim == 2) return {"kinematic"};
  return {"euler", "affine"};
}

bool linear_family(const std::string& family) { return family == "overlap" || family == "graze"; }
bool realistic_family(const std::string& family) { return family == "decimal" || family == "keyframe"; }

bool family_applies(const std::string& family, const std::string& motion) {
  if (linear_family(family)) return motion == "translation";
  if (motion == "translation") return false;
  return !((family == "near-miss" || family == "keyframe") && motion == "affine");
}

std::string separation_label(int e) { return "1e-" + std::to_string(e); }

Rational round_significant(const Rational& x, int digits) {
  if (x == 0) return x;
  Rational a = abs(x);
  // e with 10^e <= a < 10^(e+1), from a double guess corrected exactly
  int e = int(std::floor(std::log10(a.get_d())));
  while (pow10(e) > a) --e;
  while (pow10(e + 1) <= a) ++e;
  Rational unit = pow10(e - digits + 1);
  Rational q = a / unit;
  mpz_class n = q.get_num() / q.get_den();        // floor
  if (Rational(n) + Rational(1, 2) <= q) n += 1;  // half away from zero
  Rational out = Rational(n) * unit;
  out.canonicalize();
  return x < 0 ? -out : out;
}

std::string exact_decimal(const Rational& x0) {
  Rational x = x0;
  x.canonicalize();
  mpz_class den = x.get_den();
  int twos = 0, fives = 0;
  while (den % 2 == 0) {
    den /= 2;
    ++twos;
  }
  while (den % 5 == 0) {
    den /= 5;
    ++fives;
  }
  if (den != 1) return x.get_str();
  int k = std::max(twos, fives);
  mpz_class n = x.get_num() * mpz_class(pow10(k).get_num()) / x.get_den();
  bool neg = n < 0;
  std::string digits = mpz_class(abs(n)).get_str();
  if (k > 0) {
    if (int(digits.size()) <= k) digits = std::string(k - digits.size() + 1, '0') + digits;
    digits.insert(digits.size() - std::size_t(k), 1, '.');  // (pos, count, char): GCC 12 -Wrestrict misfires on a char*
    while (digits.back() == '0') digits.pop_back();
    if (digits.back() == '.') digits.pop_back();
  }
  return (neg ? "-" : "") + digits;
}

std::uint64_t scene_seed(std::uint64_t run_seed, const GeneratorSpec& c, int index) {
  std::uint64_t h = mix(run_seed, std::uint64_t(c.dim));
  h = mix(h, std::uint64_t(c.degree));
  h = mix(h, hash_string(c.family));
  h = mix(h, hash_string(c.motion));
  h = mix(h, std::uint64_t(c.d_exponent));
  if (c.digits)
    h = mix(h, std::uint64_t(c.digits) + 0x100);  // only the realistic families: the others keep their seeds
  return mix(h, std::uint64_t(index)) >> 11;      // 53 bits: exact in JSON and in a double
}

GeneratedScene generate_scene(const GeneratorSpec& spec) {
  if (auto g = generate_motion_family(spec)) return *g;  // cycloidal, independent (compare/motion_families.hpp)
  if (spec.dim != 2 && spec.dim != 3) throw std::invalid_argument("dimension must be 2 or 3");
  if (spec.degree < 1 || spec.degree > 8) throw std::invalid_argument("motion degree must be between 1 and 8");
  const bool linear = linear_family(spec.family), realistic = realistic_family(spec.family);
  auto ms = motions_for(spec.dim);
  if (!linear && std::find(ms.begin(), ms.end(), spec.motion) == ms.end())
    throw std::invalid_argument("motion '" + spec.motion + "' is not a " + std::to_string(spec.dim) +
                                "D motion (2D: kinematic; 3D: euler, affine)");
  bool touchy = spec.family == "touch" || spec.family == "near-miss";
  if (!touchy && !linear && !realistic && spec.family != "colliding" && spec.family != "free")
    throw std::invalid_argument("unknown family '" + spec.family +
                                "' (colliding, free, touch, near-miss, overlap, graze, decimal, keyframe)");
  if (linear && (spec.motion != "translation" || spec.degree != 1))
    throw std::invalid_argument(spec.family + " scenes are linear translations: motion 'translation', degree 1");
  if (!family_applies(spec.family, spec.motion))
    throw std::invalid_argument(spec.family + " scenes need a rigid motion (an affine motion does not keep distances)");
  if (touchy && spec.degree < 2) throw std::invalid_argument("touch and near-miss scenes need motion degree >= 2");
  if (spec.family == "near-miss" && (spec.d_exponent < 1 || spec.d_exponent > 300))
    throw std::invalid_argument("near-miss separation must be 10^-e with 1 <= e <= 300");
  if (spec.family == "overlap" && (spec.d_exponent < 1 || spec.d_exponent > 300))
    throw std::invalid_argument("overlap depth must be 10^-e with 1 <= e <= 300");
  if (realistic && (spec.digits < 1 || spec.digits > 30))
    throw std::invalid_argument(spec.family + " scenes need 1 to 30 significant digits");
  if (spec.family == "keyframe" && (spec.degree < 2 || spec.degree > 6))
    throw std::invalid_argument("keyframe scenes have motion degree 2 to 6 (1 to 3 keyframed joints)");

  Rng r{spec.seed};
  for (int attempt = 0; attempt < 1000; ++attempt) {
    Built b;
    g_decimal_output = realistic;  // keyframe motions are written while they are built
    try {
      if (linear)
        b = build_linear_overlap(r, spec);
      else if (spec.family == "decimal")
        b = build_decimal(r, spec);
      else if (spec.family == "keyframe")
        b = build_keyframe(r, spec);
      else
        b = touchy ? build_touch(r, spec) : build_random(r, spec);
    } catch (const std::domain_error&) {
      g_decimal_output = false;
      continue;
    }
    g_decimal_output = false;
    if (std::max(motion_degree(spec.dim, b.ma), motion_degree(spec.dim, b.mb)) != spec.degree) continue;
    GeneratedScene g;
    g.spec = spec;
    g.t0 = b.t0;
    std::ostringstream name;
    name << spec.dim << "d-deg" << spec.degree << "-" << spec.family;
    if (spec.family == "near-miss" || spec.family == "overlap") name << "-" << separation_label(spec.d_exponent);
    if (realistic) name << "-" << spec.digits << "digits";
    name << "-" << spec.motion << "-" << spec.seed;
    g.name = name.str();
    std::ostringstream note;
    note << "generated by eccd generate: family=" << spec.family << " dim=" << spec.dim << " degree=" << spec.degree
         << " motion=" << spec.motion;
    if (spec.family == "near-miss") note << " d=" << separation_label(spec.d_exponent);
    if (spec.family == "overlap") note << " depth=" << separation_label(spec.d_exponent);
    if (realistic) note << " digits=" << spec.digits;
    if (!b.base.empty()) note << " base=" << b.base;
    if (b.t0) note << " t0=" << b.t0->get_str();
    note << " seed=" << spec.seed << ".";
    if (spec.family == "touch") note << " The solids touch at t0 only (constructed).";
    if (spec.family == "near-miss") note << " Minimum separation d at t0, never colliding (constructed).";
    if (spec.family == "colliding") note << " The centres coincide at one instant (constructed).";
    if (spec.family == "free") note << " The plane x = 0 separates the solids throughout (constructed).";
    if (spec.family == "overlap")
      note << " Linear translations; at t0 B is pushed depth into A along the common normal (constructed).";
    if (spec.family == "graze") note << " Linear translations; the solids touch at t0 only (constructed).";
    if (spec.family == "decimal")
      note << " A " << b.base << " scene with every number rounded to that many significant digits.";
    if (spec.family == "keyframe")
      note << " Keyframed rigid motions (animation-format.md: centres linear, orientations by a linear quaternion "
              "curve), "
              "key values with that many significant digits.";
    auto& d = g.doc;
    d = nlohmann::ordered_json();
    d["format"] = "ellipse-ccd-scene/1";
    d["name"] = g.name;
    d["dim"] = spec.dim;
    g_decimal_output = realistic;
    d["a"]["shape"] = b.axes_a.empty() ? shape_json(b.alpha_a) : semi_axes_json(b.axes_a);
    d["a"]["motion"] = b.json_a ? *b.json_a : motion_json(b.ma);
    d["b"]["shape"] = b.axes_b.empty() ? shape_json(b.alpha_b) : semi_axes_json(b.axes_b);
    d["b"]["motion"] = b.json_b ? *b.json_b : motion_json(b.mb);
    g_decimal_output = false;
    d["note"] = note.str();
    if (realistic) {  // rounding may make a weight vanish on [0, 1]: the reader decides, and we pick again
      try {
        parse_scene(d.dump(), g.name);
      } catch (const SceneError&) {
        continue;
      }
    }
    return g;
  }
  throw std::runtime_error("generator: no scene of degree " + std::to_string(spec.degree) + " after 1000 attempts");
}

std::vector<GeneratorSpec> plan_scenes(const GeneratePlan& plan) {
  std::vector<GeneratorSpec> out;
  auto emit = [&](int dim, int deg, const std::string& fam, const std::string& mot) {
    std::vector<int> exps = fam == "near-miss" ? plan.d_exponents
                            : fam == "overlap" ? plan.depth_exponents
                                               : std::vector<int>{0};
    std::vector<int> digs = realistic_family(fam) ? plan.digits : std::vector<int>{0};
    for (int e : exps)
      for (int dg : digs)
        for (int i = 0; i < plan.count; ++i) {
          GeneratorSpec s;
          s.dim = dim;
          s.degree = deg;
          s.family = fam;
          s.motion = mot;
          s.d_exponent = e;
          s.digits = dg;
          s.seed = scene_seed(plan.seed, s, i);
          out.push_back(s);
        }
  };
  for (int dim : plan.dims) {
    for (const auto& fam : plan.families)  // cycloidal (2D), independent (2D, 3D): degree 1, once per dimension
      for (int d : motion_family_dims(fam))
        if (d == dim) emit(dim, 1, fam, motion_family_motion(fam));
    for (int deg : plan.degrees)
      for (const auto& fam : plan.families) {
        if (linear_family(fam) || motion_family(fam)) continue;
        if (fam == "keyframe" && (deg < 2 || deg > 6)) continue;
        for (const auto& mot : motions_for(dim)) {
          if (!plan.motions.empty() && std::find(plan.motions.begin(), plan.motions.end(), mot) == plan.motions.end())
            continue;
          if (!family_applies(fam, mot)) continue;
          emit(dim, deg, fam, mot);
        }
      }
    for (const auto& fam : plan.families)  // degree 1, once per dimension
      if (linear_family(fam)) emit(dim, 1, fam, "translation");
  }
  return out;
}

std::optional<GeneratorSpec> spec_from_note(const std::string& note) {
  if (note.rfind("generated by eccd generate:", 0) != 0) return std::nullopt;
  GeneratorSpec s;
  std::istringstream in(note.substr(27));
  std::string tok;
  bool any = false;
  while (in >> tok) {
    if (!tok.empty() && tok.back() == '.') tok.pop_back();
    auto eq = tok.find('=');
    if (eq == std::string::npos) continue;
    std::string k = tok.substr(0, eq), v = tok.substr(eq + 1);
    try {
      if (k == "family")
        s.family = v, any = true;
      else if (k == "dim")
        s.dim = std::stoi(v);
      else if (k == "degree")
        s.degree = std::stoi(v);
      else if (k == "motion")
        s.motion = v;
      else if ((k == "d" || k == "depth") && v.rfind("1e-", 0) == 0)
        s.d_exponent = std::stoi(v.substr(3));
      else if (k == "digits")
        s.digits = std::stoi(v);
      else if (k == "seed")
        s.seed = std::stoull(v);
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  if (!any) return std::nullopt;
  return s;
}

}  // namespace eccd

// FCL as a peer engine (compare/fcl_engine.hpp).
#include "compare/fcl_engine.hpp"

#include "floating/rounded_input.hpp"
#include "kernel/motion.hpp"
#include "kernel/quadric.hpp"
#include "number/double_traits.hpp"

#include <Eigen/Dense>

#ifdef ECCD_HAVE_FCL
#include <fcl/config.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#ifndef ECCD_FCL_STATUS
#define ECCD_FCL_STATUS "unknown"
#endif

namespace eccd {

namespace {

// One body's world quadric in double at t, decomposed (see the header).
template <int H>
FclPose pose_of(const Matrix<double, H>& q, const PolyMatrix<double, H>& n, double t, const char* which,
                std::vector<std::vector<double>>& out) {
  constexpr int d = H - 1;
  Matrix<double, H> A = quadric_at<double, H>(q, n, t);
  out.assign(H, std::vector<double>(H));
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) out[i][j] = A[i][j];
  Eigen::Matrix<double, d, d> S;
  Eigen::Matrix<double, d, 1> b;
  for (int i = 0; i < d; ++i) {
    for (int j = 0; j < d; ++j) S(i, j) = 0.5 * (A[i][j] + A[j][i]);
    b(i) = A[i][d];
  }
  const double c = A[d][d];
  auto fail = [&](const std::string& what) {
    char tb[32];
    std::snprintf(tb, sizeof tb, "%.17g", t);
    throw std::invalid_argument("FCL pose of object " + std::string(which) + " at t = " + tb + ": " + what);
  };
  if (!S.allFinite() || !b.allFinite() || !std::isfinite(c))
    fail("the quadric has a value that is not finite in double");
  Eigen::LDLT<Eigen::Matrix<double, d, d>> ldlt(S);
  Eigen::Matrix<double, d, 1> x0 = -ldlt.solve(b);
  const double k = x0.dot(S * x0) - c;
  if (!(k > 0) || !x0.allFinite()) fail("the quadric is not an ellipse or ellipsoid in double (empty or unbounded)");
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, d, d>> es(S / k);
  if (es.info() != Eigen::Success) fail("Eigen's eigen-decomposition did not converge");
  Eigen::Matrix<double, d, d> R = es.eigenvectors();
  if (R.determinant() < 0) R.col(0) = -R.col(0);
  FclPose p;
  for (int i = 0; i < d; ++i) {
    const double l = es.eigenvalues()(i);
    if (!(l > 0)) fail("the quadric's shape matrix is not positive definite in double");
    p.radii[i] = 1 / std::sqrt(l);
    p.centre[i] = x0(i);
    for (int j = 0; j < d; ++j) p.rotation[i][j] = R(i, j);
  }
  if (d == 2) p.rotation[2][2] = 1;  // the plane's normal stays z
  return p;
}

template <int H>
MovingPair<double, H> rounded_scene(const Scene& s) {
  std::string trouble;
  MovingPair<double, H> m = round_pair<double, H>(s, 1.0, trouble);
  if (!trouble.empty()) throw std::invalid_argument("FCL pose: " + trouble);
  return m;
}

template <int H>
FclScenePose scene_pose(const MovingPair<double, H>& m, double t) {
  FclScenePose p;
  p.a = pose_of<H>(m.qa, m.na, t, "a", p.qa);
  p.b = pose_of<H>(m.qb, m.nb, t, "b", p.qb);
  if (H == 3) {  // the common third semi-axis (see the header: exact for any h > 0 shared by both)
    const double h = std::max({p.a.radii[0], p.a.radii[1], p.b.radii[0], p.b.radii[1]});
    p.a.radii[2] = p.b.radii[2] = h;
  }
  return p;
}

bool cycloidal(const Scene& s) {
  return std::holds_alternative<CycloidalMotion>(s.a.motion) || std::holds_alternative<CycloidalMotion>(s.b.motion);
}

template <int H>
std::string inexpressible_motion(const Motion& motion, const char* which) {
  constexpr int d = H - 1;
  PolyMatrix<Rational, H> M = motion_matrix<Rational, H>(motion, [](const Rational& x) { return x; });
  const std::string who = std::string("object ") + which + " (" + motion_type_name(motion) + "): ";
  for (int j = 0; j < d; ++j)
    if (!M[d][j].is_zero()) return who + "M(t) is not affine (its last row is not 0 ... 0 w)";
  if (M[d][d].degree() > 0)
    return who + "the denominator w(t) of M(t) is not constant (degree " + std::to_string(M[d][d].degree()) + ")";
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      if (M[i][j].degree() > 0)
        return who + "its orientation or shape changes with t (M[" + std::to_string(i) + "][" + std::to_string(j) +
               "] has degree " + std::to_string(M[i][j].degree()) + ")";
  for (int i = 0; i < d; ++i)
    if (M[i][d].degree() > 1)
      return who + "its translation is not linear in t (M[" + std::to_string(i) + "][" + std::to_string(d) +
             "] has degree " + std::to_string(M[i][d].degree()) + ")";
  return "";
}

// The scene rounded once (the user's program holds its numbers and N(t)), posed at each instant.
struct Poser {
  int dim;
  MovingPair<double, H_2D> m2;
  MovingPair<double, H_3D> m3;
  explicit Poser(const Scene& s) : dim(s.dim) {
    if (cycloidal(s))
      throw std::invalid_argument(
          "the FCL peer does not take cycloidal motions (eccd solves them in double, mpfr:BITS and certified)");
    if (dim == 3)
      m3 = rounded_scene<H_3D>(s);
    else
      m2 = rounded_scene<H_2D>(s);
  }
  FclScenePose at(double t) const { return dim == 3 ? scene_pose<H_3D>(m3, t) : scene_pose<H_2D>(m2, t); }
};

#ifdef ECCD_HAVE_FCL
Instant decimal_instant(long k, long n) {
  Instant i;
  mpq_class q(k, n);
  q.canonicalize();
  i.approx = decimal_string(q, 17);
  i.value = double(k) / double(n);
  return i;
}

fcl::Transform3d transform_of(const FclPose& p) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  fcl::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = p.rotation[i][j];
  tf.linear() = r;
  tf.translation() = fcl::Vector3d(p.centre[0], p.centre[1], p.centre[2]);
  return tf;
}

fcl::CollisionRequestd request_of(const FclOptions& o) {
  fcl::CollisionRequestd request;  // FCL's defaults, as a user calls it
  if (o.gjk_tolerance > 0) request.gjk_tolerance = o.gjk_tolerance;
  return request;
}

bool fcl_collide_posed(const Poser& poser, double t, const FclOptions& o) {
  FclScenePose p = poser.at(t);
  fcl::Ellipsoidd ea(p.a.radii[0], p.a.radii[1], p.a.radii[2]), eb(p.b.radii[0], p.b.radii[1], p.b.radii[2]);
  const fcl::CollisionRequestd request = request_of(o);
  fcl::CollisionResultd result;
  return fcl::collide(&ea, transform_of(p.a), &eb, transform_of(p.b), request, result) > 0;
}
#endif

void check_options(const FclOptions& o) {
  if (!(o.gjk_tolerance >= 0) || !std::isfinite(o.gjk_tolerance))
    throw std::invalid_argument("FCL's gjk_tolerance must be a finite number > 0 (or 0 for FCL's default)");
}

void need_fcl() {
#ifndef ECCD_HAVE_FCL
  throw FclUnavailable("FCL is not built in: " + fcl_availability().reason);
#endif
}

}  // namespace

FclAvailability fcl_availability() {
  FclAvailability a;
#ifdef ECCD_HAVE_FCL
  a.available = true;
  a.version = FCL_VERSION;
#else
  a.reason = ECCD_FCL_STATUS;
#endif
  return a;
}

double fcl_gjk_tolerance(const FclOptions& options) {
  check_options(options);
#ifdef ECCD_HAVE_FCL
  return request_of(options).gjk_tolerance;
#else
  return 0;
#endif
}

std::string fcl_tolerances(const FclOptions& options) {
  check_options(options);
#ifdef ECCD_HAVE_FCL
  const fcl::CollisionRequestd r = request_of(options);
  fcl::detail::GJKSolver_libccd<double> solver;
  fcl::ContinuousCollisionRequestd cr;
  std::ostringstream o;
  o << "fcl::collide with "
    << (options.gjk_tolerance > 0 ? "a CollisionRequest (gjk_tolerance set)" : "the default CollisionRequest")
    << ": GJK solver " << (r.gjk_solver_type == fcl::GST_LIBCCD ? "libccd (GST_LIBCCD)" : "indep (GST_INDEP)")
    << ", gjk_tolerance " << r.gjk_tolerance << ", at most " << solver.max_collision_iterations
    << " GJK iterations; fcl::continuousCollide: CCDC_NAIVE with CCDM_TRANS, num_max_iterations N, toc_err "
    << cr.toc_err << " (so at most " << std::ceil(1 / cr.toc_err) << " samples), each sample an fcl::collide as above";
  return o.str();
#else
  return "";
#endif
}

FclScenePose fcl_pose_at(const Scene& s, double t) { return Poser(s).at(t); }

std::string fcl_ccd_inexpressible(const Scene& s) {
  if (cycloidal(s)) return "a cycloidal motion rotates: FCL's translation motion cannot express it";
  for (auto [o, w] : {std::pair{&s.a, "a"}, std::pair{&s.b, "b"}}) {
    std::string why = s.dim == 3 ? inexpressible_motion<H_3D>(o->motion, w) : inexpressible_motion<H_2D>(o->motion, w);
    if (!why.empty()) return "not expressible by FCL's translation motion (CCDM_TRANS): " + why;
  }
  return "";
}

bool fcl_collides_at(const Scene& s, double t, const FclOptions& o) {
  need_fcl();
  check_options(o);
#ifdef ECCD_HAVE_FCL
  return fcl_collide_posed(Poser(s), t, o);
#else
  (void)s, (void)t;
  return false;
#endif
}

Answer fcl_sample(const Scene& s, int n, const FclOptions& o) {
  need_fcl();
  check_options(o);
  if (n < 1) throw std::invalid_argument("fcl/sample:N needs N >= 1");
  Answer a;
#ifdef ECCD_HAVE_FCL
  const Poser poser(s);
  long start = -1;
  for (long k = 0; k <= n; ++k) {
    const bool hit = fcl_collide_posed(poser, double(k) / double(n), o);
    if (hit && start < 0) start = k;
    if (start >= 0 && (!hit || k == n)) {
      const long end = hit ? k : k - 1;
      a.intervals.emplace_back(decimal_instant(start, n), decimal_instant(end, n));
      start = -1;
    }
  }
  a.collides = !a.intervals.empty();
  if (a.collides) a.first_contact = a.intervals.front().first;
#else
  (void)s;
#endif
  return a;
}

Answer fcl_ccd(const Scene& s, int n, const FclOptions& o) {
  need_fcl();
  check_options(o);
  if (o.gjk_tolerance > 0)
    throw std::invalid_argument(
        "fcl/ccd: FCL's naive continuous collision makes its own default CollisionRequest, so a gjk_tolerance cannot "
        "reach it");
  // FCL's naive solver samples t = i/(N-1): N = 1 would divide by zero.
  if (n < 2) throw std::invalid_argument("fcl/ccd:N needs N >= 2");
  if (std::string why = fcl_ccd_inexpressible(s); !why.empty()) throw std::invalid_argument(why);
  Answer a;
#ifdef ECCD_HAVE_FCL
  const Poser poser(s);
  FclScenePose p0 = poser.at(0), p1 = poser.at(1);
  // The shape and orientation are constant: the start's; only the centre moves (CCDM_TRANS).
  FclPose a1 = p0.a, b1 = p0.b;
  a1.centre = p1.a.centre;
  b1.centre = p1.b.centre;
  fcl::Ellipsoidd ea(p0.a.radii[0], p0.a.radii[1], p0.a.radii[2]), eb(p0.b.radii[0], p0.b.radii[1], p0.b.radii[2]);
  fcl::ContinuousCollisionRequestd request;  // FCL's defaults (toc_err, GJK solver) but for these three
  request.num_max_iterations = std::size_t(n);
  request.ccd_motion_type = fcl::CCDM_TRANS;
  request.ccd_solver_type = fcl::CCDC_NAIVE;
  fcl::ContinuousCollisionResultd result;
  fcl::continuousCollide(&ea, transform_of(p0.a), transform_of(a1), &eb, transform_of(p0.b), transform_of(b1), request,
                         result);
  a.collides = result.is_collide;
  if (a.collides) a.first_contact = rounded_instant(result.time_of_contact);
#endif
  return a;
}

Answer first_contact_view(const Answer& x) {
  Answer a;
  a.collides = x.collides;
  a.first_contact = x.first_contact;
  return a;
}

}  // namespace eccd

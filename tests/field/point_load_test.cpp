// The point-load field against the physics it claims to be: Boussinesq's
// solution is axisymmetric, in equilibrium, traction-free on the surface,
// compressive under a downward load, and its Cartesian form must agree with
// the textbook cylindrical form.

#include "field/sampling/point_load.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace hsb {
namespace {

constexpr double kPi = 3.14159265358979323846;

double rel_error(const Mat3& a, const Mat3& b) { return (a - b).norm() / b.norm(); }

// A random point of the default domain at least `min_distance` from the load
// and at least `min_depth` below the surface.
Vec3 random_point(std::mt19937& rng, const PointLoadField& f, double min_distance,
                  double min_depth) {
  const Box3 b = f.bounds();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    const Vec3 p = b.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(b.size());
    if ((p - f.load_point()).norm() >= min_distance && f.load_point().z() - p.z() >= min_depth)
      return p;
  }
}

Mat3 rotation_about_z(double theta) {
  return Eigen::AngleAxisd(theta, Vec3::UnitZ()).toRotationMatrix();
}

TEST(PointLoad, LoadPointIsTopCentre) {
  PointLoadSpec spec;
  spec.bounds = {Vec3(0, -2, 1), Vec3(4, 2, 3)};
  const PointLoadField f(spec);
  EXPECT_EQ(f.load_point(), Vec3(2, 0, 3));
  EXPECT_NEAR(f.singular_radius(), 1e-3 * spec.bounds.diagonal(), 1e-15);
  spec.singular_radius = 0.05;
  EXPECT_EQ(PointLoadField(spec).singular_radius(), 0.05);
}

TEST(PointLoad, AxisymmetricAboutLoadAxis) {
  const PointLoadField f(PointLoadSpec{});
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p = random_point(rng, f, 0.05, 0.0);
    const Mat3 r = rotation_about_z(angle(rng));
    const Vec3 q = f.load_point() + r * (p - f.load_point());
    const Mat3 expected = r * f.stress(p).matrix() * r.transpose();
    EXPECT_LE(rel_error(f.stress(q).matrix(), expected), 1e-10) << "p = " << p.transpose();
  }
}

// div σ by fourth-order central differences, h = 1e-4 of the domain.
// σ is homogeneous of degree −2 in the distance d to the load, so relative
// to |σ|/d the truncation error is ~(h/d)⁴ (≲ 1e-11 for d ≥ 0.2) and the
// rounding error ~ε·d/h (≲ 1e-12). A tolerance of 1e-8 is far above both,
// while a sign or factor error in any one component leaves a residual of
// order 1 (checked below with σxz's sign flipped).
Vec3 divergence(const std::function<Mat3(const Vec3&)>& sigma, const Vec3& p, double h) {
  Vec3 div = Vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h * Vec3::Unit(j);
    div += (-sigma(p + 2 * e).col(j) + 8 * sigma(p + e).col(j) - 8 * sigma(p - e).col(j) +
            sigma(p - 2 * e).col(j)) /
           (12.0 * h);
  }
  return div;
}

TEST(PointLoad, Equilibrium) {
  const PointLoadField f(PointLoadSpec{});
  const double h = 1e-4 * f.bounds().size().maxCoeff();
  const auto sigma = [&](const Vec3& x) { return f.stress(x).matrix(); };
  const auto wrong_sign = [&](const Vec3& x) {
    Sym3 s = f.stress(x);
    s.xz = -s.xz;
    return s.matrix();
  };
  std::mt19937 rng(2);
  double worst_wrong = 0.0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 p = random_point(rng, f, 0.2, 0.01);  // depth 0.01 ≫ 2h: no surface clamp
    const double d = (p - f.load_point()).norm();
    const double scale = f.stress(p).frobenius_norm() / d;
    EXPECT_LE(divergence(sigma, p, h).norm(), 1e-8 * scale) << "p = " << p.transpose();
    worst_wrong = std::max(worst_wrong, divergence(wrong_sign, p, h).norm() / scale);
  }
  EXPECT_GT(worst_wrong, 0.1);  // the check can fail
}

TEST(PointLoad, SurfaceIsTractionFree) {
  const PointLoadField f(PointLoadSpec{});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p(u(rng), u(rng), f.load_point().z());
    if ((p - f.load_point()).norm() < 0.05) continue;
    const Sym3 s = f.stress(p);
    // Traction on the face with normal z: (σxz, σyz, σzz) = 0.
    EXPECT_NEAR(s.zz, 0.0, 1e-14 * s.frobenius_norm());
    EXPECT_NEAR(s.xz, 0.0, 1e-14 * s.frobenius_norm());
    EXPECT_NEAR(s.yz, 0.0, 1e-14 * s.frobenius_norm());
    EXPECT_GT(s.frobenius_norm(), 0.0);  // but the in-plane stresses are not zero
  }
}

TEST(PointLoad, CompressiveBelowLoad) {
  PointLoadSpec spec;
  spec.load = 2.5;
  const PointLoadField f(spec);
  for (double d : {0.1, 0.5, 1.0, 2.0}) {
    const Vec3 p = f.load_point() - d * Vec3::UnitZ();
    ASSERT_TRUE(f.sample(p).has_value()) << "d = " << d;
    const Sym3 s = *f.sample(p);
    EXPECT_NEAR(s.zz, -3.0 * spec.load / (2.0 * kPi * d * d), 1e-12 * std::abs(s.zz));
    EXPECT_LT(s.zz, 0.0);
    // On the axis nothing shears.
    EXPECT_NEAR(s.xy, 0.0, 1e-15);
    EXPECT_NEAR(s.xz, 0.0, 1e-15);
    EXPECT_NEAR(s.yz, 0.0, 1e-15);
  }
}

// The textbook cylindrical form (Timoshenko & Goodier §138, tension
// positive, z = depth, P the downward load), rotated into world axes: an
// independent derivation of the Cartesian formulas the field uses.
TEST(PointLoad, MatchesCylindricalSolution) {
  PointLoadSpec spec;
  spec.load = 1.7;
  spec.poisson_ratio = 0.27;
  const PointLoadField f(spec);
  const double P = spec.load, n = 1.0 - 2.0 * spec.poisson_ratio;
  std::mt19937 rng(4);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = random_point(rng, f, 0.05, 1e-3);
    const Vec3 rel = p - f.load_point();
    const double r = std::hypot(rel.x(), rel.y());
    if (r < 1e-3) continue;
    const double z = -rel.z();
    const double rho = rel.norm();
    const double rho5 = std::pow(rho, 5);
    const double sr = P / (2 * kPi) * (n / (rho * (rho + z)) - 3 * z * r * r / rho5);
    const double st = P / (2 * kPi) * n * (z / (rho * rho * rho) - 1 / (rho * (rho + z)));
    const double sz = -3 * P * z * z * z / (2 * kPi * rho5);
    const double trz = -3 * P * r * z * z / (2 * kPi * rho5);
    // Orthonormal cylindrical basis in world axes: e_r, e_θ, e_depth = −ẑ.
    const Vec3 er(rel.x() / r, rel.y() / r, 0), ed(0, 0, -1);
    const Vec3 et = ed.cross(er);
    Mat3 basis;
    basis << er, et, ed;
    Mat3 cyl;
    cyl << sr, 0, trz, 0, st, 0, trz, 0, sz;
    const Mat3 expected = basis * cyl * basis.transpose();
    EXPECT_LE(rel_error(f.stress(p).matrix(), expected), 1e-12) << "p = " << p.transpose();
  }
}

TEST(PointLoad, FiniteEverywhereInDomain) {
  const PointLoadField f(PointLoadSpec{});
  const Box3 b = f.bounds();
  const int n = 41;  // odd: the grid contains the load point
  bool saw_load_point = false;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 t(i / (n - 1.0), j / (n - 1.0), k / (n - 1.0));
        const Vec3 p = b.lo + t.cwiseProduct(b.size());
        saw_load_point |= (p - f.load_point()).norm() == 0.0;
        const std::optional<Sym3> s = f.sample(p);
        ASSERT_TRUE(s.has_value()) << p.transpose();
        ASSERT_TRUE(s->is_finite()) << p.transpose();
      }
  EXPECT_TRUE(saw_load_point);
  // At the load point: the value at the singular radius straight down.
  const Sym3 at_load = *f.sample(f.load_point());
  const Sym3 below = f.stress(f.load_point() - f.singular_radius() * Vec3::UnitZ());
  EXPECT_LE((at_load - below).frobenius_norm(), 1e-12 * below.frobenius_norm());
  // Inside the singular ball, the value on its surface in the same direction.
  const Vec3 dir = Vec3(0.3, -0.2, -0.9).normalized();
  const Sym3 inside = f.stress(f.load_point() + 0.25 * f.singular_radius() * dir);
  const Sym3 surface = f.stress(f.load_point() + f.singular_radius() * dir);
  EXPECT_LE((inside - surface).frobenius_norm(), 1e-12 * surface.frobenius_norm());
}

TEST(PointLoad, NothingOutsideDomain) {
  const PointLoadField f(PointLoadSpec{});
  const Box3 b = f.bounds();
  const double eps = 1e-9;
  for (int a = 0; a < 3; ++a) {
    Vec3 below = b.centre(), above = b.centre();
    below(a) = b.lo(a) - eps;
    above(a) = b.hi(a) + eps;
    EXPECT_FALSE(f.sample(below).has_value()) << "axis " << a;
    EXPECT_FALSE(f.sample(above).has_value()) << "axis " << a;
  }
  EXPECT_FALSE(f.sample(Vec3(std::nan(""), 0, 0)).has_value());
  EXPECT_TRUE(f.sample(b.lo).has_value());
  EXPECT_TRUE(f.sample(b.hi).has_value());
}

TEST(PointLoad, PoissonRatioAffectsHorizontalStressOnly) {
  PointLoadSpec a, b;
  a.poisson_ratio = 0.1;
  b.poisson_ratio = 0.45;
  const PointLoadField fa(a), fb(b);
  const Vec3 p(0.4, -0.3, 0.2);
  const Sym3 sa = fa.stress(p), sb = fb.stress(p);
  EXPECT_GT(std::abs(sa.xx - sb.xx), 1e-3 * std::abs(sa.xx));
  EXPECT_GT(std::abs(sa.xy - sb.xy), 1e-3 * std::abs(sa.xy));
  EXPECT_NEAR(sa.zz, sb.zz, 1e-15 * std::abs(sa.zz));
  EXPECT_NEAR(sa.xz, sb.xz, 1e-15 * std::abs(sa.xz));
  EXPECT_NEAR(sa.yz, sb.yz, 1e-15 * std::abs(sa.yz));
}

TEST(PointLoad, LinearInLoad) {
  PointLoadSpec a, b;
  b.load = -3.0;
  const Vec3 p(0.2, 0.5, -0.4);
  const Mat3 ma = PointLoadField(a).stress(p).matrix();
  const Mat3 mb = PointLoadField(b).stress(p).matrix();
  EXPECT_LE((mb + 3.0 * ma).norm(), 1e-14 * ma.norm());
}

TEST(PointLoad, RejectsBadSpecs) {
  PointLoadSpec flat;
  flat.bounds = {Vec3(-1, -1, 0), Vec3(1, 1, 0)};
  EXPECT_THROW(PointLoadField{flat}, std::invalid_argument);
  PointLoadSpec negative_radius;
  negative_radius.singular_radius = -1.0;
  EXPECT_THROW(PointLoadField{negative_radius}, std::invalid_argument);
}

}  // namespace
}  // namespace hsb

// An independent reference: VTK's own vtkPointLoad on the same domain.
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPointLoad.h>
#include <vtkSmartPointer.h>

namespace hsb {
namespace {

TEST(PointLoad, AgreesWithVtkPointLoad) {
  PointLoadSpec spec;
  spec.bounds = Box3{Vec3(-1, -2, -1.5), Vec3(1, 2, 0.5)};
  spec.load = 3.0;
  spec.poisson_ratio = 0.27;
  const PointLoadField field(spec);

  auto vtk = vtkSmartPointer<vtkPointLoad>::New();
  vtk->SetModelBounds(-1, 1, -2, 2, -1.5, 0.5);
  vtk->SetLoadValue(3.0);
  vtk->SetPoissonsRatio(0.27);
  vtk->SetSampleDimensions(9, 10, 11);
  vtk->ComputeEffectiveStressOff();
  vtk->Update();
  vtkImageData* image = vtk->GetOutput();
  vtkDataArray* tensors = image->GetPointData()->GetTensors();
  int compared = 0;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    double p[3], t[9];
    image->GetPoint(i, p);
    const Vec3 x(p[0], p[1], p[2]);
    if ((x - field.load_point()).norm() < 0.1) continue;  // VTK puts FLT_MAX at the load
    tensors->GetTuple(i, t);
    const Sym3 ours = field.stress(x);
    const Sym3 theirs{t[0], t[4], t[8], t[1], t[5], t[2]};
    // VTK stores single precision.
    EXPECT_LT((ours.matrix() - theirs.matrix()).norm(), 1e-5 * (1.0 + ours.frobenius_norm())) << x.transpose();
    ++compared;
  }
  EXPECT_GT(compared, 900);
}

}  // namespace
}  // namespace hsb

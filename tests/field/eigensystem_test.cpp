// Properties every decomposition must have, on random and on degenerate
// tensors (repeated eigenvalues are where solvers usually go wrong).

#include "field/tensor/eigensystem.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace hsb {
namespace {

// A random rotation from a QR of a Gaussian matrix, fixed to det = +1.
Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Mat3 a;
  for (int i = 0; i < 9; ++i) a(i) = g(rng);
  Mat3 q = Eigen::HouseholderQR<Mat3>(a).householderQ();
  if (q.determinant() < 0) q.col(2) *= -1.0;
  return q;
}

Sym3 with_eigenvalues(const Vec3& values, const Mat3& rotation) {
  return Sym3::symmetric_part(rotation * values.asDiagonal() * rotation.transpose());
}

void expect_valid(const Sym3& s, const std::string& label) {
  SCOPED_TRACE(label);
  const Eigensystem es = decompose(s);
  const Mat3& v = es.vectors;
  const Mat3 m = s.matrix();

  const double scale = m.norm();
  const Mat3 rebuilt = v * es.values.asDiagonal() * v.transpose();
  EXPECT_LE((rebuilt - m).norm(), 1e-10 * scale);
  EXPECT_LE((v.transpose() * v - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(v.determinant(), 1.0, 1e-12);
  EXPECT_GE(es.values(0), es.values(1));
  EXPECT_GE(es.values(1), es.values(2));
  // Each column is an eigenvector of its own eigenvalue.
  for (int k = 0; k < 3; ++k)
    EXPECT_LE((m * v.col(k) - es.values(k) * v.col(k)).norm(), 1e-10 * std::max(scale, 1e-300));
}

TEST(Eigensystem, RandomSymmetricTensors) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Sym3 s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    expect_valid(s, "random #" + std::to_string(i));
  }
}

TEST(Eigensystem, RecoversKnownEigenvalues) {
  std::mt19937 rng(7);
  const Vec3 values(2.5, -0.5, -4.0);
  for (int i = 0; i < 50; ++i) {
    const Mat3 r = random_rotation(rng);
    const Eigensystem es = decompose(with_eigenvalues(values, r));
    EXPECT_LE((es.values - values).cwiseAbs().maxCoeff(), 1e-12);
    // Distinct eigenvalues: the eigenvectors are the rotation's columns up to sign.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(es.vectors.col(k).dot(r.col(k))), 1.0, 1e-12);
  }
}

TEST(Eigensystem, DegenerateTensors) {
  std::mt19937 rng(99);
  std::vector<std::pair<std::string, Vec3>> spectra = {
      {"two equal (top)", Vec3(2, 2, -1)},
      {"two equal (bottom)", Vec3(3, -1, -1)},
      {"all equal", Vec3(1.5, 1.5, 1.5)},
      {"rank one", Vec3(4, 0, 0)},
      {"rank one negative", Vec3(0, 0, -4)},
      {"gap 1e-12", Vec3(1.0 + 1e-12, 1.0, 0.5)},
      {"two gaps 1e-12", Vec3(1.0 + 1e-12, 1.0, 1.0 - 1e-12)},
      {"huge", Vec3(3e8, 1e8, -2e8)},
      {"huge degenerate", Vec3(1e8, 1e8, -2e8)},
      {"tiny", Vec3(3e-8, 1e-8, -2e-8)},
      {"tiny degenerate", Vec3(3e-8, -2e-8, -2e-8)},
  };
  for (const auto& [label, values] : spectra) {
    for (int i = 0; i < 20; ++i) expect_valid(with_eigenvalues(values, random_rotation(rng)), label);
    // Axis-aligned as well: already diagonal is a special path in some solvers.
    expect_valid(with_eigenvalues(values, Mat3::Identity()), label + " diagonal");
  }
}

TEST(Eigensystem, ZeroTensor) {
  const Eigensystem es = decompose(Sym3{});
  EXPECT_EQ(es.values, Vec3::Zero());
  EXPECT_EQ(es.vectors, Mat3::Identity());
}

TEST(Eigensystem, EigenvaluesMatchWithinScaleAtRepeatedValues) {
  // All equal: every basis is valid, but the values must be exact-ish.
  const Eigensystem es = decompose(Sym3{2, 2, 2, 0, 0, 0});
  EXPECT_LE((es.values - Vec3::Constant(2)).cwiseAbs().maxCoeff(), 1e-15);
}

// The eigenvalues alone are decompose()'s to the bit: random tensors of
// every scale, repeated eigenvalues, zero.
TEST(Eigensystem, EigenvaluesAloneAreTheDecompositionsBits) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0), e(-12.0, 12.0);
  std::vector<Sym3> tensors{Sym3{}, with_eigenvalues({2.0, 2.0, -1.0}, random_rotation(rng)),
                            with_eigenvalues({3.0, 3.0, 3.0}, random_rotation(rng))};
  for (int i = 0; i < 2000; ++i) {
    const double scale = std::pow(10.0, e(rng));
    tensors.push_back(Sym3{scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng),
                           scale * u(rng)});
  }
  for (const Sym3& s : tensors) {
    const Vec3 alone = eigenvalues(s), decomposed = decompose(s).values;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(alone(k), decomposed(k));
  }
}

TEST(Sym3, SymmetricPartOfGeneralTensor) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int i = 0; i < 100; ++i) {
    Mat3 t;
    for (int k = 0; k < 9; ++k) t(k) = u(rng);
    const Mat3 expected = 0.5 * (t + t.transpose());
    EXPECT_LE((Sym3::symmetric_part(t).matrix() - expected).cwiseAbs().maxCoeff(), 1e-15);
  }
}

TEST(Sym3, ComponentOrderAndArithmetic) {
  const Sym3 a{1, 2, 3, 4, 5, 6};  // xx yy zz xy yz xz
  const Mat3 m = a.matrix();
  EXPECT_EQ(m(0, 1), 4);
  EXPECT_EQ(m(1, 0), 4);
  EXPECT_EQ(m(1, 2), 5);
  EXPECT_EQ(m(2, 1), 5);
  EXPECT_EQ(m(0, 2), 6);
  EXPECT_EQ(m(2, 0), 6);
  EXPECT_NEAR(a.frobenius_norm(), m.norm(), 1e-14);
  const Sym3 b{0.5, -1, 2, 0, 3, -2};
  EXPECT_EQ((a + b).matrix(), a.matrix() + b.matrix());
  EXPECT_EQ((a - b).matrix(), a.matrix() - b.matrix());
  EXPECT_EQ((2.5 * a).matrix(), 2.5 * a.matrix());
  EXPECT_TRUE(a.is_finite());
  EXPECT_FALSE((Sym3{0, 0, 0, 0, std::nan(""), 0}).is_finite());
}

}  // namespace
}  // namespace hsb

// The Bogner-Fox-Schmit element against exact polynomial calculus: it must reproduce every
// bicubic, and its matrices must give the exact integrals of (Lap p)^2 and p^2 for bicubics p.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "assemble.hpp"
#include "bfs_element.hpp"
#include "gauss.hpp"
#include "sampling.hpp"

using namespace plate;

namespace {
// A bivariate polynomial sum a(i, j) x^i y^j with exact calculus, independent of the element code.
struct Poly {
  Eigen::MatrixXd a;  // a(i, j), degree < rows in x, < cols in y
  double operator()(double x, double y) const {
    double s = 0;
    for (int i = 0; i < a.rows(); ++i)
      for (int j = 0; j < a.cols(); ++j) s += a(i, j) * std::pow(x, i) * std::pow(y, j);
    return s;
  }
  Poly dx() const {
    Poly d{Eigen::MatrixXd::Zero(a.rows(), a.cols())};
    for (int i = 1; i < a.rows(); ++i) d.a.row(i - 1) = i * a.row(i);
    return d;
  }
  Poly dy() const {
    Poly d{Eigen::MatrixXd::Zero(a.rows(), a.cols())};
    for (int j = 1; j < a.cols(); ++j) d.a.col(j - 1) = j * a.col(j);
    return d;
  }
  Poly operator+(const Poly& o) const { return Poly{a + o.a}; }
  Poly operator*(const Poly& o) const {
    Poly p{Eigen::MatrixXd::Zero(a.rows() + o.a.rows() - 1, a.cols() + o.a.cols() - 1)};
    for (int i = 0; i < a.rows(); ++i)
      for (int j = 0; j < a.cols(); ++j) p.a.block(i, j, o.a.rows(), o.a.cols()) += a(i, j) * o.a;
    return p;
  }
  // Exact integral over [0, h]^2 from the antiderivative of each monomial.
  double integral(double h) const {
    double s = 0;
    for (int i = 0; i < a.rows(); ++i)
      for (int j = 0; j < a.cols(); ++j) s += a(i, j) * std::pow(h, i + 1) / (i + 1) * std::pow(h, j + 1) / (j + 1);
    return s;
  }
};

// q(x / h, y / h) with q a random bicubic: scaled to the element, so that no part of it (the
// constant and linear parts, which K annihilates) dwarfs the rest and costs digits to cancellation.
Poly random_bicubic(std::mt19937& rng, double h = 1.0) {
  std::uniform_real_distribution<double> u(-1, 1);
  Poly p{Eigen::MatrixXd(4, 4)};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.a(i, j) = u(rng) / std::pow(h, i + j);
  return p;
}

// The element's 16 coefficients of p: (p, p_x, p_y, p_xy) at the corners of [0, h]^2.
Vector16 hermite_data(const Poly& p, double h) {
  const Poly px = p.dx(), py = p.dy(), pxy = px.dy();
  Vector16 c;
  for (int a = 0; a < 4; ++a) {
    const double x = (a & 1) * h, y = (a >> 1) * h;
    c.segment<4>(4 * a) << p(x, y), px(x, y), py(x, y), pxy(x, y);
  }
  return c;
}
}  // namespace

TEST(Gauss, IntegratesPolynomialsUpToDegree2nMinus1Exactly) {
  for (int n = 1; n <= 8; ++n) {
    const Quadrature1D q = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double s = 0;
      for (int i = 0; i < n; ++i) s += q.weights[i] * std::pow(q.points[i], k);
      EXPECT_NEAR(s, 1.0 / (k + 1), 1e-15) << "n = " << n << ", degree " << k;
    }
    double s = 0;  // degree 2n is not integrated exactly: the rule is no better than claimed
    for (int i = 0; i < n; ++i) s += q.weights[i] * std::pow(q.points[i], 2 * n);
    EXPECT_GT(std::abs(s - 1.0 / (2 * n + 1)), 1e-12) << "n = " << n;
  }
}

TEST(BfsElement, ReproducesEveryBicubicAndItsDerivatives) {
  std::mt19937 rng(1);
  const double h = 0.37;
  for (int trial = 0; trial < 5; ++trial) {
    const Poly p = random_bicubic(rng);
    const Poly px = p.dx(), py = p.dy();
    const Vector16 c = hermite_data(p, h);
    for (double t : {0.0, 0.13, 0.5, 0.91, 1.0})
      for (double s : {0.0, 0.27, 0.66, 1.0}) {
        const LocalBasis b = bfs_basis(t, s, h);
        const double x = t * h, y = s * h;
        EXPECT_NEAR(c.dot(b.v), p(x, y), 1e-13);
        EXPECT_NEAR(c.dot(b.dx), px(x, y), 1e-12);
        EXPECT_NEAR(c.dot(b.dy), py(x, y), 1e-12);
        EXPECT_NEAR(c.dot(b.dxx), px.dx()(x, y), 1e-11);
        EXPECT_NEAR(c.dot(b.dxy), px.dy()(x, y), 1e-11);
        EXPECT_NEAR(c.dot(b.dyy), py.dy()(x, y), 1e-11);
      }
  }
}

// The two partial reads of the basis agree with the whole one: bfs_values to the bit, and
// bfs_basis_along (which multiplies by 1 / h where the whole one divides by h) to a few units in
// the last place, on a cell whose side is not a power of two.
TEST(BfsElement, PartialReadsOfTheBasisAreTheWholeOnesNumbers) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0, 1), a(0, 2 * M_PI);
  for (double h : {0.3, 1.0 / 64}) {
    for (int k = 0; k < 50; ++k) {
      const double t = u(gen), s = u(gen), th = a(gen), c = std::cos(th), sn = std::sin(th);
      const LocalBasis b = bfs_basis(t, s, h);
      const Vector16 v = bfs_values(t, s, h);
      double along[48], again[48];
      bfs_basis_along(t, s, h, c, sn, along, along + 16, along + 32);
      bfs_basis_along(t, s, h, c, sn, again, nullptr, again + 32);  // no slopes: the same others
      const double slope_size = b.dx.cwiseAbs().maxCoeff() + b.dy.cwiseAbs().maxCoeff();
      const double lap_size = b.dxx.cwiseAbs().maxCoeff() + b.dyy.cwiseAbs().maxCoeff();
      for (int i = 0; i < 16; ++i) {
        EXPECT_EQ(v[i], b.v[i]);
        EXPECT_NEAR(along[i], b.v[i], 4e-16);
        EXPECT_NEAR(along[16 + i], c * b.dx[i] + sn * b.dy[i], 1e-15 * slope_size);
        EXPECT_NEAR(along[32 + i], b.dxx[i] + b.dyy[i], 1e-15 * lap_size);
        EXPECT_EQ(again[i], along[i]);
        EXPECT_EQ(again[32 + i], along[32 + i]);
      }
    }
  }
}

TEST(BfsElement, MatricesGiveExactEnergyAndMassOfBicubics) {
  std::mt19937 rng(2);
  for (double h : {1.0, 0.25, 0.01}) {
    const Matrix16 K = bfs_stiffness(h), M = bfs_mass(h);
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    for (int trial = 0; trial < 5; ++trial) {
      const Poly p = random_bicubic(rng, h);
      const Poly lap = p.dx().dx() + p.dy().dy();
      const Vector16 c = hermite_data(p, h);
      const double energy = (lap * lap).integral(h), mass = (p * p).integral(h);
      EXPECT_NEAR(c.dot(K * c), energy, 1e-12 * energy) << "h = " << h;
      EXPECT_NEAR(c.dot(M * c), mass, 1e-12 * mass) << "h = " << h;
    }
  }
}

TEST(BfsElement, StiffnessKernelIsExactlyTheHarmonicBicubics) {
  // Lap p = 0 for p in span{1, x, y, xy, x^2 - y^2, x^3 - 3 x y^2, 3 x^2 y - y^3, x^3 y - x y^3}:
  // eight harmonic bicubics, so K has an eight-dimensional kernel and no more.
  Eigen::SelfAdjointEigenSolver<Matrix16> es(bfs_stiffness(0.5));
  const auto ev = es.eigenvalues();
  for (int k = 0; k < 8; ++k) EXPECT_LT(std::abs(ev[k]), 1e-10 * ev[15]) << k;
  EXPECT_GT(ev[8], 1e-6 * ev[15]);
}

TEST(Sampling, GaussGramIsTheConsistentMassMatrix) {
  // (8) with the L2 product: S^T W S over 4 x 4 Gauss points must be the assembled mass matrix.
  const Grid g = make_grid(5, 1.0, 0.8);
  const Sampling s = make_sampling(g, SamplingKind::Gauss);
  const SpMat gram = weighted_gram(s.S, s.weights, g.unknowns());
  const SpMat mass = assemble_matrix(g, bfs_mass(g.h));
  EXPECT_LT(SpMat(gram - mass).norm(), 1e-14 * mass.norm());
  EXPECT_NEAR(s.weights.sum(), 0.8, 1e-14);  // the weights integrate 1 over the rectangle
}

TEST(Assembly, StencilEqualsElementByElementAssembly) {
  // The stencil shortcut against the textbook loop over elements.
  const Grid g = make_grid(6, 1.2, 0.8);
  const Matrix16 Ke = bfs_stiffness(g.h);
  std::vector<Eigen::Triplet<double>> t;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const auto d = g.element_dofs(ex, ey);
      for (int a = 0; a < 16; ++a)
        for (int b = 0; b < 16; ++b)
          if (d[a] >= 0 && d[b] >= 0) t.emplace_back(d[a], d[b], Ke(a, b));
    }
  SpMat ref(g.unknowns(), g.unknowns());
  ref.setFromTriplets(t.begin(), t.end());
  const SpMat K = assemble_matrix(g, Ke);
  EXPECT_LT(SpMat(K - ref).norm(), 1e-13 * ref.norm());
}

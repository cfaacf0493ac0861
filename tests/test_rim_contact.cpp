// The rim-contact series (rim_contact.hpp) against what does not come from it: the jump and
// corner conditions that define its fields (by finite differences), the clamped corner's exponent
// equation, Timoshenko's clamped square, the finite-element continuum answer, Betti's reciprocal
// theorem, and the scene's symmetries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "continuum_limits.hpp"
#include "gauss.hpp"
#include "paper_case.hpp"
#include "rim_contact.hpp"
#include "rim_report.hpp"

using namespace plate;

namespace {

// The paper's scene as the series reads it, and any such reading back as a scene.
RimScene paper_rim_scene(double height = NAN) {
  RimScene s = rim_scene(paper_scene());
  if (!std::isnan(height)) s.height = height;
  return s;
}
Scene as_scene(const RimScene& r) { return Scene::rectangle(r.lx, r.ly).over(Cylinder{r.cx, r.cy, r.radius, r.height}).loaded(r.load); }

double laplacian(const PlateSeries& f, const SeriesTerm& t, double x, double y) {
  const PointValues v = term_values(f, t, x, y);
  return v.wxx + v.wyy;
}

// Lap^2 of a term by the five-point difference of its (analytic) Laplacian, with step 1e-3 l,
// relative to what the second derivatives make of a fourth one at the scale l of the field's
// variation (n its angular order): |Lap^2 w| / (|D^2 w| n^2 / l^2). The difference's own error
// is about 1e-6 n^2 / 12 of that; a field that is not biharmonic would give a ratio near 1.
double bilaplacian_ratio(const PlateSeries& f, const SeriesTerm& t, double x, double y, double l, double n) {
  const double d = 1e-3 * l;
  const double b = (laplacian(f, t, x + d, y) + laplacian(f, t, x - d, y) + laplacian(f, t, x, y + d) +
                    laplacian(f, t, x, y - d) - 4 * laplacian(f, t, x, y)) / (d * d);
  const PointValues v = term_values(f, t, x, y);
  return std::abs(b) / ((std::abs(v.wxx) + std::abs(v.wyy) + 2 * std::abs(v.wxy)) * n * n / (l * l));
}

// Largest difference between a term's analytic first and second derivatives and central
// differences of its value and of its analytic first derivatives, relative to `scale`.
double derivative_mismatch(const PlateSeries& f, const SeriesTerm& t, double x, double y, double d) {
  auto at = [&](double dx, double dy) { return term_values(f, t, x + dx, y + dy); };
  const PointValues c = at(0, 0), px = at(d, 0), mx = at(-d, 0), py = at(0, d), my = at(0, -d);
  return std::max({std::abs((px.w - mx.w) / (2 * d) - c.wx), std::abs((py.w - my.w) / (2 * d) - c.wy),
                   std::abs((px.wx - mx.wx) / (2 * d) - c.wxx), std::abs((py.wy - my.wy) / (2 * d) - c.wyy),
                   std::abs((py.wx - my.wx) / (2 * d) - c.wxy), std::abs((px.wy - mx.wy) / (2 * d) - c.wxy)});
}

SeriesTerm rim_mode(int m, bool sine) {
  SeriesTerm t;
  t.kind = SeriesTerm::Kind::RimMode, t.n = m, t.imag = sine;
  return t;
}

SeriesTerm corner_term(int k, bool symmetric, bool imag, int corner) {
  SeriesTerm t;
  t.kind = SeriesTerm::Kind::Corner, t.n = k, t.symmetric = symmetric, t.imag = imag, t.corner = corner;
  t.mu = corner_exponent(k, symmetric);
  return t;
}

// The integral of g over the rectangle, in polar coordinates about the disk's centre: split at
// the rim and at the corners' angles, so that every piece is smooth and Gauss-Legendre converges
// fast (w is only C^2 across the rim).
double integrate_plate(const RimScene& s, const std::function<double(double, double)>& g, int n) {
  const Quadrature1D q = gauss_legendre(n);
  std::vector<double> cuts;
  for (double x : {0.0, s.lx})
    for (double y : {0.0, s.ly}) cuts.push_back(std::atan2(y - s.cy, x - s.cx));
  std::sort(cuts.begin(), cuts.end());
  cuts.push_back(cuts[0] + 2 * M_PI);
  auto reach = [&](double th) {  // distance from the centre to the edge along th
    double r = INFINITY;
    const double c = std::cos(th), si = std::sin(th);
    if (c > 0) r = std::min(r, (s.lx - s.cx) / c);
    if (c < 0) r = std::min(r, -s.cx / c);
    if (si > 0) r = std::min(r, (s.ly - s.cy) / si);
    if (si < 0) r = std::min(r, -s.cy / si);
    return r;
  };
  double sum = 0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = cuts[k], dt = cuts[k + 1] - cuts[k];
    for (int i = 0; i < n; ++i) {
      const double th = t0 + dt * q.points[i], c = std::cos(th), si = std::sin(th);
      for (auto [r0, r1] : {std::pair{0.0, s.radius}, {s.radius, reach(th)}})
        for (int j = 0; j < n; ++j) {
          const double r = r0 + (r1 - r0) * q.points[j];
          sum += dt * q.weights[i] * (r1 - r0) * q.weights[j] * r * g(s.cx + r * c, s.cy + r * si);
        }
    }
  }
  return sum;
}

}  // namespace

TEST(RimContact, ModeProfileIsContinuousToSecondOrderAndItsThirdDerivativeJumpsByOne) {
  for (int m = 0; m <= 16; ++m) {
    const RadialProfile in = rim_mode_profile(m, 1, true), out = rim_mode_profile(m, 1, false);
    EXPECT_NEAR(in.h, out.h, 1e-15) << "m = " << m;
    EXPECT_NEAR(in.h1, out.h1, 1e-15) << "m = " << m;
    EXPECT_NEAR(in.h2, out.h2, 1e-14) << "m = " << m;
    EXPECT_NEAR(out.h3 - in.h3, 1, 1e-13) << "m = " << m;
    // the derivatives the jump is read from are the derivatives of H (central differences)
    const double d = 1e-5;
    for (auto [s, inside] : {std::pair{0.6, true}, {1.7, false}}) {
      const RadialProfile p = rim_mode_profile(m, s, inside), hi = rim_mode_profile(m, s + d, inside),
                          lo = rim_mode_profile(m, s - d, inside);
      const double scale = std::abs(p.h1) + std::abs(p.h2) + std::abs(p.h3) + 1e-3;
      EXPECT_NEAR((hi.h - lo.h) / (2 * d), p.h1, 1e-8 * scale) << "m = " << m << ", s = " << s;
      EXPECT_NEAR((hi.h1 - lo.h1) / (2 * d), p.h2, 1e-8 * scale) << "m = " << m << ", s = " << s;
      EXPECT_NEAR((hi.h2 - lo.h2) / (2 * d), p.h3, 1e-8 * scale) << "m = " << m << ", s = " << s;
    }
  }
}

TEST(RimContact, ModeFieldIsTheLineLoadCosMThetaPerUnitLengthAndNothingElse) {
  // Off the origin and with a != 1, so that the centring and the a^3 scaling are tested too.
  PlateSeries f;
  f.cx = 0.4, f.cy = 0.55, f.radius = 0.3;
  const double a = f.radius;
  for (auto [m, sine] : {std::pair{0, false}, {1, false}, {1, true}, {2, false}, {3, true}, {5, false}, {8, true}}) {
    const SeriesTerm t = rim_mode(m, sine);
    for (double th : {0.3, 1.9, 4.0}) {
      const double c = std::cos(th), s = std::sin(th);
      // analytic derivatives, and biharmonic inside and outside the rim
      for (double r : {0.45 * a, 1.6 * a}) {
        const double x = f.cx + r * c, y = f.cy + r * s;
        const PointValues v = term_values(f, t, x, y);
        const double scale = std::abs(v.w) / (a * a) + std::abs(v.wx) / a + std::abs(v.wy) / a +
                             std::abs(v.wxx) + std::abs(v.wxy) + std::abs(v.wyy);
        EXPECT_LT(derivative_mismatch(f, t, x, y, 1e-5 * a), 1e-7 * scale) << "m = " << m << ", r = " << r;
        EXPECT_LT(bilaplacian_ratio(f, t, x, y, r < a ? a : r, m + 2), 1e-4) << "m = " << m << ", r = " << r;
      }
      // Across the rim: w and its first and second derivatives continuous...
      const PointValues in = term_values(f, t, f.cx + a * (1 - 1e-9) * c, f.cy + a * (1 - 1e-9) * s);
      const PointValues out = term_values(f, t, f.cx + a * (1 + 1e-9) * c, f.cy + a * (1 + 1e-9) * s);
      // (the points are 2e-9 a apart: a jump would be of order a^3, a^2, a; the drift is 1e-8 of that)
      EXPECT_NEAR(in.w, out.w, 1e-8 * a * a * a) << "m = " << m;
      EXPECT_NEAR(in.wx, out.wx, 1e-8 * a * a) << "m = " << m;
      EXPECT_NEAR(in.wy, out.wy, 1e-8 * a * a) << "m = " << m;
      EXPECT_NEAR(in.wxx + in.wyy, out.wxx + out.wyy, 1e-6 * a) << "m = " << m;
      EXPECT_NEAR(in.wxy, out.wxy, 1e-6 * a) << "m = " << m;
      // ... and the radial derivative of Lap w jumps by the load per unit length, cos(m theta):
      // integrating Lap^2 w = q delta(r - a) across the rim. Central differences of the analytic
      // Laplacian at a (1 +- e), extrapolated to e = 0 from e and 2e.
      auto dr_lap = [&](double r) {
        const double d = 1e-6 * a;
        return (laplacian(f, t, f.cx + (r + d) * c, f.cy + (r + d) * s) -
                laplacian(f, t, f.cx + (r - d) * c, f.cy + (r - d) * s)) / (2 * d);
      };
      auto jump = [&](double e) { return dr_lap(a * (1 + e)) - dr_lap(a * (1 - e)); };
      const double e = 5e-4, extrapolated = 2 * jump(e) - jump(2 * e);
      EXPECT_NEAR(extrapolated, sine ? std::sin(m * th) : std::cos(m * th), 1e-4) << "m = " << m << ", theta = " << th;
    }
  }
}

TEST(RimContact, CornerExponentsAreTheClampedRightAnglesFirstRoots) {
  // sin(lambda pi / 2) = -lambda (symmetric) or +lambda (antisymmetric), lambda = mu - 1, and no
  // root is skipped: Newton from a grid of starts finds no other root (bar the spurious
  // lambda = 1 of the antisymmetric equation) with real part up to the fourth exponent's.
  for (bool symmetric : {true, false}) {
    const double sign = symmetric ? 1 : -1;
    std::vector<std::complex<double>> listed;
    for (int k = 0; k < 4; ++k) {
      const std::complex<double> l = corner_exponent(k, symmetric) - 1.0;
      EXPECT_LT(std::abs(std::sin(l * M_PI / 2.0) + sign * l), 1e-12 * std::abs(l)) << "k = " << k;
      EXPECT_GT(l.imag(), 0) << "k = " << k;
      if (k > 0) {
        EXPECT_GT(l.real(), listed.back().real()) << "k = " << k;
      }
      listed.push_back(l);
    }
    for (double x0 = 0.25; x0 < listed.back().real(); x0 += 0.25)
      for (double y0 : {0.1, 0.7, 1.4, 2.2}) {
        std::complex<double> l(x0, y0);
        for (int it = 0; it < 60; ++it) l -= (std::sin(l * M_PI / 2.0) + sign * l) / (M_PI / 2 * std::cos(l * M_PI / 2.0) + sign);
        if (!(std::abs(std::sin(l * M_PI / 2.0) + sign * l) < 1e-10) || l.real() <= 0.5 || std::abs(l - 1.0) < 1e-6) continue;
        if (l.real() > listed.back().real() + 1e-6) continue;
        const std::complex<double> upper(l.real(), std::abs(l.imag()));
        double nearest = INFINITY;
        for (auto z : listed) nearest = std::min(nearest, std::abs(z - upper));
        EXPECT_LT(nearest, 1e-8) << "root " << l << " is not listed (symmetric = " << symmetric << ")";
      }
  }
  EXPECT_NEAR(corner_exponent(0, true).real(), 3.7396, 1e-4);  // w ~ r^(1 + lambda), lambda = 2.7396 + 1.1190i
  EXPECT_NEAR(corner_exponent(0, true).imag(), 1.1190, 1e-4);
}

TEST(RimContact, CornerFunctionsAreClampedOnTheirCornersEdgesAndBiharmonic) {
  PlateSeries f;
  f.lx = 1.3, f.ly = 0.9;
  const double cx[4] = {0, f.lx, f.lx, 0}, cy[4] = {0, 0, f.ly, f.ly};
  for (int corner = 0; corner < 4; ++corner)
    for (int k : {0, 1})
      for (bool symmetric : {true, false})
        for (bool imag : {false, true}) {
          const SeriesTerm t = corner_term(k, symmetric, imag, corner);
          double scale = 0;
          for (double u : {0.3, 0.6})
            for (double v : {0.3, 0.6}) scale = std::max(scale, std::abs(term_values(f, t, u * f.lx, v * f.ly).w));
          ASSERT_GT(scale, 0);
          for (double s : {0.1, 0.35, 0.7, 0.95}) {
            // the horizontal edge through the corner (normal y) and the vertical one (normal x)
            const PointValues h = term_values(f, t, s * f.lx, cy[corner]), v = term_values(f, t, cx[corner], s * f.ly);
            EXPECT_LT(std::abs(h.w), 1e-13 * scale) << corner << k << symmetric << imag;
            EXPECT_LT(std::abs(h.wy), 1e-12 * scale) << corner << k << symmetric << imag;
            EXPECT_LT(std::abs(v.w), 1e-13 * scale) << corner << k << symmetric << imag;
            EXPECT_LT(std::abs(v.wx), 1e-12 * scale) << corner << k << symmetric << imag;
          }
          for (auto [x, y] : {std::pair{0.4, 0.3}, {0.9, 0.6}}) {
            const double l = std::hypot(x - cx[corner], y - cy[corner]);
            EXPECT_LT(derivative_mismatch(f, t, x, y, 1e-5), 1e-6 * scale) << corner << k << symmetric << imag;
            EXPECT_LT(bilaplacian_ratio(f, t, x, y, l, std::abs(t.mu) + 2), 1e-4) << corner << k << symmetric << imag;
          }
        }
}

TEST(RimContact, ClampedSquareUnderUniformLoadMatchesTimoshenko) {
  const double published = plate_constant("uniform_centre");  // six digits
  const PlateSeries sym = solve_clamped_plate(1, 1, 1, rim_level(3));
  EXPECT_NEAR(sym.at(0.5, 0.5).w, published, 0.5e-8);
  RimSeriesOptions general = rim_level(2);
  general.use_symmetry = false;
  const PlateSeries all = solve_clamped_plate(1, 1, 1, general);
  EXPECT_NEAR(all.at(0.5, 0.5).w, sym.at(0.5, 0.5).w, 1e-12 * published);
  // clamped between the collocation points too
  for (double s : {0.013, 0.31, 0.77}) {
    EXPECT_LT(std::abs(sym.at(s, 0).w), 1e-12 * published);
    EXPECT_LT(std::abs(sym.at(1, s).wx), 1e-11 * published);
  }
}

TEST(RimContact, PaperSceneAgreesWithTheFiniteElementContinuumAndThePremiseHolds) {
  const auto limits = read_continuum_limits(std::string(PLATE_SOURCE_DIR) + "/results/continuum_limits.csv");
  const RimScene scene = paper_rim_scene();
  const RimSeries r = solve_rim_series(as_scene(scene), rim_level(5));
  const RimPeak peak = r.max_w();
  std::printf("rim series: max w = %.15g at (%.6g, %.6g), force = %.15g (FE: %.9g +- %.1g, %.9g +- %.1g)\n", peak.w,
              peak.x, peak.y, r.total_force(), limits.at("max_w"), limits.at("max_w_bar"), limits.at("total_force"),
              limits.at("total_force_bar"));
  EXPECT_NEAR(peak.w, limits.at("max_w"), std::max(limits.at("max_w_bar"), 1e-6 * peak.w));
  EXPECT_NEAR(r.total_force(), limits.at("total_force"), limits.at("total_force_bar"));
  EXPECT_NEAR(peak.x, scene.cx, 1e-9);  // the square's symmetry puts the top at the centre
  EXPECT_NEAR(peak.y, scene.cy, 1e-9);
  const RimPremise p = check_premise(r);
  EXPECT_TRUE(p.holds) << p.why;
  EXPECT_GT(p.min_q, 0);
  EXPECT_NEAR(p.theta_min_q, M_PI / 4, 1e-12);  // q is least towards the corners
}

TEST(RimContact, BettiReciprocityWithTheUniformlyLoadedPlate) {
  // The rim load q (f = 0, deflection w) and the uniform load 1 (deflection w1) on the same
  // clamped plate: int_plate 1 * w = int_rim q * w1 ds. The two fields come from separate solves,
  // and the identity tests q, not only its mean.
  for (const RimScene& s : {paper_rim_scene(), RimScene{1.2, 1, 0.55, 0.45, 0.22, 0.05, 0}}) {
    const RimSeries r = solve_rim_series(as_scene(s), rim_level(4));
    const PlateSeries w1 = solve_clamped_plate(s.lx, s.ly, 1, rim_level(4));
    const double lhs = integrate_plate(s, [&](double x, double y) { return r.w(x, y); }, 24);
    double rhs = 0;
    const int n = 256;
    for (int i = 0; i < n; ++i) {
      const double th = 2 * M_PI * i / n;
      rhs += r.q(th) * w1.at(s.cx + s.radius * std::cos(th), s.cy + s.radius * std::sin(th)).w * s.radius * 2 * M_PI / n;
    }
    EXPECT_NEAR(lhs, rhs, 1e-10 * std::abs(lhs)) << "lx = " << s.lx;
  }
}

TEST(RimContact, DeflectionAndLoadAreProportionalToTheObstacleHeight) {
  const RimSeries one = solve_rim_series(as_scene(paper_rim_scene()), rim_level(3));
  const RimSeries two = solve_rim_series(as_scene(paper_rim_scene(2 * paper_scene().cylinder->height)), rim_level(3));
  for (auto [x, y] : {std::pair{0.5, 0.5}, {0.3, 0.7}, {0.1, 0.45}, {0.62, 0.2}})
    EXPECT_NEAR(two.w(x, y), 2 * one.w(x, y), 1e-12 * std::abs(one.w(x, y)));
  for (double th : {0.0, 0.4, M_PI / 4, 2.0}) EXPECT_NEAR(two.q(th), 2 * one.q(th), 1e-11 * one.q(th));
  EXPECT_NEAR(two.total_force(), 2 * one.total_force(), 1e-12 * one.total_force());
}

// The least-squares problems of mirrored scenes are mirror images, but their solutions agree
// only to within what rounding can move in a problem that is not yet solved exactly: in
// least squares that grows with the residual (about kappa^2 |r|). So the tolerance of w is the
// fit's own misfit (edge_residual R), at a truncation where that is small; a wrong sign anywhere
// would show at the size of w itself.
TEST(RimContact, MirroredDiskGivesTheMirroredPlate) {
  const RimScene left{1, 1, 0.42, 0.56, 0.2, 0.0625, 0}, right{1, 1, 0.58, 0.56, 0.2, 0.0625, 0};
  const RimSeries a = solve_rim_series(as_scene(left), rim_level(4)), b = solve_rim_series(as_scene(right), rim_level(4));
  ASSERT_EQ(a.symmetry, RimSymmetry::None);
  const double tol = std::max(a.edge_residual, b.edge_residual) * left.height;
  for (auto [x, y] : {std::pair{0.42, 0.56}, {0.3, 0.7}, {0.1, 0.45}, {0.62, 0.2}, {0.5, 0.5}})
    EXPECT_NEAR(b.w(1 - x, y), a.w(x, y), tol);
  for (double th : {0.0, 0.4, 1.3, 2.0, 4.5}) EXPECT_NEAR(b.q(M_PI - th), a.q(th), 1e-6 * a.q_cos[0]);
  const RimPeak pa = a.max_w(), pb = b.max_w();
  EXPECT_NEAR(pb.x, 1 - pa.x, 1e-7);
  EXPECT_NEAR(pb.y, pa.y, 1e-7);
  EXPECT_NEAR(pb.w, pa.w, 1e-12 * pa.w);
}

TEST(RimContact, TransposedRectangleGivesTheTransposedPlate) {
  const RimScene wide{1.2, 1, 0.55, 0.45, 0.22, 0.0625, 0}, tall{1, 1.2, 0.45, 0.55, 0.22, 0.0625, 0};
  const RimSeries a = solve_rim_series(as_scene(wide), rim_level(4)), b = solve_rim_series(as_scene(tall), rim_level(4));
  const double tol = std::max(a.edge_residual, b.edge_residual) * wide.height;  // as for the mirror
  for (auto [x, y] : {std::pair{0.55, 0.45}, {0.3, 0.7}, {0.1, 0.45}, {1.1, 0.2}})
    EXPECT_NEAR(b.w(y, x), a.w(x, y), tol);
  for (double th : {0.0, 0.4, 1.3, 2.0, 4.5}) EXPECT_NEAR(b.q(M_PI / 2 - th), a.q(th), 1e-6 * a.q_cos[0]);
  const RimPeak pa = a.max_w(), pb = b.max_w();
  EXPECT_NEAR(pb.x, pa.y, 1e-7);
  EXPECT_NEAR(pb.y, pa.x, 1e-7);
}

TEST(RimContact, SymmetricBasesAgreeWithTheGeneralOne) {
  for (const RimScene& s : {paper_rim_scene(), RimScene{1.2, 1, 0.6, 0.5, 0.25, 0.0625, 0}}) {
    RimSeriesOptions o = rim_level(4);
    const RimSeries sym = solve_rim_series(as_scene(s), o);
    o.use_symmetry = false;
    const RimSeries all = solve_rim_series(as_scene(s), o);
    EXPECT_EQ(sym.symmetry, s.lx == s.ly ? RimSymmetry::Square : RimSymmetry::Mirrors);
    EXPECT_LT(sym.unknowns, all.unknowns);
    // to within the truncation error of level 4 (its residuals)
    const double tol = 10 * std::max(sym.edge_residual, all.edge_residual) * s.height;
    EXPECT_NEAR(sym.w(s.cx, s.cy), all.w(s.cx, s.cy), tol) << "lx = " << s.lx;
    EXPECT_NEAR(sym.w(0.3, 0.2), all.w(0.3, 0.2), tol) << "lx = " << s.lx;
    EXPECT_NEAR(sym.total_force(), all.total_force(), 1e3 * tol * sym.total_force() / s.height) << "lx = " << s.lx;
    for (size_t m = 1; m < all.q_sin.size(); ++m) EXPECT_NEAR(all.q_sin[m], 0, 1e-6 * sym.q_cos[0]) << "m = " << m;
  }
}

TEST(RimContact, PremiseRefusesScenesWhereTheContactIsNotTheWholeRim) {
  EXPECT_TRUE(check_premise(solve_rim_series(as_scene(paper_rim_scene()), rim_level(3))).holds);
  // Close to an edge, the plate pulls on the far side of the rim: q < 0 there.
  const RimPremise near_edge = check_premise(solve_rim_series(as_scene(RimScene{1, 1, 0.35, 0.6, 0.25, 0.0625, 0}), rim_level(3)));
  EXPECT_FALSE(near_edge.holds);
  EXPECT_LT(near_edge.min_q, 0);
  // A large disk: the plate leaves the rim towards the corners.
  const RimPremise large = check_premise(solve_rim_series(as_scene(RimScene{1, 1, 0.5, 0.5, 0.4, 0.0625, 0}), rim_level(3)));
  EXPECT_FALSE(large.holds);
  EXPECT_LT(large.min_q, 0);
  // A strong downward load: the rim pushes (q > 0), but the plate sags below R inside the disk.
  const RimPremise sags = check_premise(solve_rim_series(as_scene(RimScene{1, 1, 0.5, 0.5, 0.25, 0.0625, -2000}), rim_level(3)));
  EXPECT_FALSE(sags.holds);
  EXPECT_GT(sags.min_q, 0);
  EXPECT_LT(sags.min_w_minus_R, 0);
  // A strong upward load lifts the plate off the cylinder: q < 0.
  const RimPremise lifted = check_premise(solve_rim_series(as_scene(RimScene{1, 1, 0.5, 0.5, 0.25, 0.0625, 1000}), rim_level(3)));
  EXPECT_FALSE(lifted.holds);
  EXPECT_LT(lifted.min_q, 0);
}

TEST(RimContact, ConvergesGeometricallyOnThePaperScene) {
  const RimAnswer a = rim_answer(as_scene(paper_rim_scene()), 6);
  ASSERT_EQ(a.rows.size(), 6u);
  for (const auto& row : a.rows)
    std::printf("level %d: %3d unknowns, max w = %.15f, force = %.13f, q(0) = %.11f, q(pi/4) = %.11f, residuals %.1e %.1e\n",
                row.level, row.unknowns, row.max_w, row.total_force, row.q0, row.q45, row.edge_residual, row.rim_residual);
  const double floor_w = 100 * DBL_EPSILON * a.rows.back().max_w, floor_f = 100 * DBL_EPSILON * a.rows.back().total_force;
  for (size_t k = 2; k < a.rows.size(); ++k) {
    const double dw = std::abs(a.rows[k].max_w - a.rows[k - 1].max_w), dw0 = std::abs(a.rows[k - 1].max_w - a.rows[k - 2].max_w);
    const double df = std::abs(a.rows[k].total_force - a.rows[k - 1].total_force),
                 df0 = std::abs(a.rows[k - 1].total_force - a.rows[k - 2].total_force);
    EXPECT_LT(dw, std::max(dw0 / 10, floor_w)) << "level " << k;
    EXPECT_LT(df, std::max(df0 / 10, floor_f)) << "level " << k;
    EXPECT_LT(a.rows[k].edge_residual, a.rows[k - 1].edge_residual) << "level " << k;
  }
  EXPECT_TRUE(a.settled);
  EXPECT_LT(a.bar_max_w, 1e-9 * a.finest.max_w().w);
  EXPECT_LT(a.bar_force, 1e-9 * a.finest.total_force());
  EXPECT_LT(a.finest.edge_residual, 1e-10);
  EXPECT_LT(a.finest.rim_residual, 1e-10);
  EXPECT_TRUE(a.premise.holds) << a.premise.why;
}

TEST(RimContact, LongDoubleSolveAgreesWithDouble) {
  // The extended solve leaves w and the force where double put them and settles q further.
  RimSeriesOptions o = rim_level(5);
  const RimSeries d = solve_rim_series(as_scene(paper_rim_scene()), o);
  o.extended = true;
  const RimSeries e = solve_rim_series(as_scene(paper_rim_scene()), o);
  EXPECT_NEAR(e.w(0.5, 0.5), d.w(0.5, 0.5), 1e-13 * d.w(0.5, 0.5));
  EXPECT_NEAR(e.total_force(), d.total_force(), 1e-12 * d.total_force());
  for (double th : {0.0, M_PI / 4}) EXPECT_NEAR(e.q(th), d.q(th), 1e-9 * d.q_cos[0]);
  EXPECT_LT(e.edge_residual, 1e-11);
}

TEST(RimContact, RefusesScenesThatCannotHaveARimContact) {
  auto refuses = [](RimScene s, const char* name) {
    try {
      check(s);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted a bad " << name;
  };
  const RimScene paper = paper_rim_scene();
  RimScene s = paper;
  s.lx = NAN, refuses(s, "lx");
  s = paper, s.ly = INFINITY, refuses(s, "ly");
  s = paper, s.cx = NAN, refuses(s, "cx");
  s = paper, s.load = NAN, refuses(s, "load");
  s = paper, s.lx = -1, refuses(s, "lx");
  s = paper, s.radius = 0, refuses(s, "radius");
  s = paper, s.height = 0, refuses(s, "height");
  s = paper, s.height = -0.01, refuses(s, "height");
  s = paper, s.cx = 0.25, refuses(s, "cx");  // the disk touches the edge x = 0
  s = paper, s.cy = 0.8, refuses(s, "cy");   // and crosses y = ly
  s = paper, s.radius = 0.5, refuses(s, "cx");
  // A scene the series does not model, refused by the option that states it.
  EXPECT_THROW(rim_scene(Scene::rectangle(1, 1).over("0.01 - x*x").loaded("0")), std::invalid_argument);
  EXPECT_THROW(rim_scene(paper_scene().loaded("x")), std::invalid_argument);
  RimSeriesOptions o;
  o.degree = 1;
  EXPECT_THROW(solve_rim_series(as_scene(paper_rim_scene()), o), std::invalid_argument);
  o = {}, o.oversampling = 0.5;
  EXPECT_THROW(solve_rim_series(as_scene(paper_rim_scene()), o), std::invalid_argument);
  EXPECT_THROW(solve_clamped_plate(0, 1, 1), std::invalid_argument);
}

// The search for max |m12| (quarter lattice, then shrinking patterns) lands at or above a plain
// brute-force search of the whole plate, and within its lattice's reach of it, on a square, a wide
// and a tall rectangle (the tall one is where a pattern scaled by lx alone missed its rows).
TEST(RimContact, TheMaxM12SearchFindsAtLeastWhatABruteForceSearchFinds) {
  for (const RimScene sc : {paper_rim_scene(), RimScene{1.5, 1, 0.75, 0.5, 0.25, 0.0625, 0}, RimScene{1, 1.5, 0.5, 0.75, 0.25, 0.0625, 0}}) {
    const RimSeries s = solve_rim_series(as_scene(sc), rim_level(3));
    double brute = 0;
    const int k = 240;
    for (int i = 0; i <= k; ++i)
      for (int j = 0; j <= k; ++j) brute = std::max(brute, std::abs(s.moments(sc.lx * i / k, sc.ly * j / k, 0.3).m12));
    const double found = rim_max_abs_m12(s, 0.3);
    EXPECT_GE(found, brute * (1 - 1e-12)) << sc.lx << " x " << sc.ly;
    EXPECT_LE(found, brute * (1 + 1e-3)) << sc.lx << " x " << sc.ly;
  }
}

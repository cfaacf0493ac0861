// The fields of a contact's end (contact_end.hpp): their derivatives against finite differences,
// the conditions on the contact side that make them fields of a plate resting on a rim, the line
// load of F_52 against its closed form, the enrichment's vanishing at the nodes, and the fit that
// locates an end recovering a shift put into a gap by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "bfs_element.hpp"
#include "contact.hpp"
#include "contact_end.hpp"
#include "dual_active_set.hpp"
#include "edge.hpp"
#include "gauss.hpp"
#include "mirror.hpp"
#include "problem.hpp"
#include "rim_rows.hpp"

using namespace plate;

namespace {
// The 2 x 1 lift-off scene's end in the lower half (the quarter's), free for smaller angles.
ContactEnd scene_end() { return {1, 0.5, 0.25, M_PI + 0.98, -1, 0.05, 0.1}; }
double end_x(const ContactEnd& e) { return e.cx + e.a * std::cos(e.theta); }
double end_y(const ContactEnd& e) { return e.cy + e.a * std::sin(e.theta); }

// A rule blind to every curve: 6 x 6 Gauss points on s x s sub-squares of cell (ex, ey), those near
// the end halved towards it (24 times at most); at(t, u, x, y, weight) for each point, (t, u) local.
template <class At>
void blind_points(const Grid& g, const ContactEnd& e, int ex, int ey, int s, const At& at) {
  static const Quadrature1D q = gauss_legendre(6);
  auto square = [&](auto&& self, double t0, double u0, double size, int depth) -> void {
    const double dx = std::max({ex * g.h + t0 * g.h - end_x(e), 0.0, end_x(e) - (ex + t0 + size) * g.h});
    const double dy = std::max({ey * g.h + u0 * g.h - end_y(e), 0.0, end_y(e) - (ey + u0 + size) * g.h});
    if (depth < 24 && std::hypot(dx, dy) < size * g.h) {
      for (int c = 0; c < 4; ++c) self(self, t0 + (c & 1) * size / 2, u0 + (c >> 1) * size / 2, size / 2, depth + 1);
      return;
    }
    for (size_t i = 0; i < q.points.size(); ++i)
      for (size_t j = 0; j < q.points.size(); ++j) {
        const double t = t0 + size * q.points[i], u = u0 + size * q.points[j];
        at(t, u, (ex + t) * g.h, (ey + u) * g.h, q.weights[i] * q.weights[j] * size * size * g.h * g.h);
      }
  };
  for (int sy = 0; sy < s; ++sy)
    for (int sx = 0; sx < s; ++sx) square(square, static_cast<double>(sx) / s, static_cast<double>(sy) / s, 1.0 / s, 0);
}
}  // namespace

TEST(ContactEnd, DerivativesMatchFiniteDifferences) {
  const ContactEnd e = scene_end();
  for (EndField f : {EndField::Gap32, EndField::Gap52})
    for (double angle : {0.3, 1.7, 2.6, -1.2, -2.8})
      for (double rho : {0.004, 0.02, 0.07}) {
        const double x = end_x(e) + rho * std::cos(angle), y = end_y(e) + rho * std::sin(angle), d = 1e-3 * rho;
        const EndDerivatives v = end_field(e, f, x, y);
        // Fourth-order central differences, in x (dx = 1) or y (dx = 0).
        auto diff = [&](auto get, int dx) {
          auto at = [&](double k) { return get(end_field(e, f, x + dx * k * d, y + (1 - dx) * k * d)); };
          return (-at(2) + 8 * at(1) - 8 * at(-1) + at(-2)) / (12 * d);
        };
        auto w = [](const EndDerivatives& u) { return u.w; };
        auto wx = [](const EndDerivatives& u) { return u.wx; };
        const double slope = std::abs(v.wx) + std::abs(v.wy), scale = std::abs(v.wxx) + std::abs(v.wyy) + std::abs(v.wxy);
        EXPECT_NEAR(v.wx, diff(w, 1), 1e-8 * slope);
        EXPECT_NEAR(v.wy, diff(w, 0), 1e-8 * slope);
        EXPECT_NEAR(v.wxx, diff(wx, 1), 1e-8 * scale);
        EXPECT_NEAR(v.wxy, diff(wx, 0), 1e-8 * scale);
        const EndDerivatives X = end_cutoff(e, x, y);
        auto c = [&](double px, double py) { return end_cutoff(e, px, py).w; };
        const double h = 1e-5;
        EXPECT_NEAR(X.wxx + X.wyy, (c(x + h, y) + c(x - h, y) + c(x, y + h) + c(x, y - h) - 4 * c(x, y)) / (h * h),
                    1e-3 * (1 + std::abs(X.wxx) + std::abs(X.wyy)));
      }
}

// On the contact side (theta beyond the end, on the rim) each field vanishes with its normal slope,
// and its second normal derivative is the same from both sides: the plate is one piece resting on
// the rim.
TEST(ContactEnd, VanishesWithItsSlopeWhereThePlateTouches) {
  const ContactEnd e = scene_end();
  for (EndField f : {EndField::Gap32, EndField::Gap52})
    for (double s : {0.003, 0.02, 0.06}) {
      const double th = e.theta + s / e.a;  // the contact side (sigma = -1)
      const double nx = std::cos(th), ny = std::sin(th), x = e.cx + e.a * nx, y = e.cy + e.a * ny;
      const EndDerivatives v = end_field(e, f, x, y);
      const double size = std::pow(s, f == EndField::Gap32 ? 1.5 : 2.5);
      EXPECT_LT(std::abs(v.w), 1e-12 * size);
      EXPECT_LT(std::abs(v.wx * nx + v.wy * ny), 1e-10 * size / s);
      auto nn = [&](double d) {
        const EndDerivatives u = end_field(e, f, x + d * nx, y + d * ny);
        return u.wxx * nx * nx + 2 * u.wxy * nx * ny + u.wyy * ny * ny;
      };
      EXPECT_NEAR(nn(1e-12), nn(-1e-12), 1e-6 * size / (s * s));
    }
}

// F_52's third normal derivative jumps across the contact side by -30 s^(-1/2) (the line load of an
// end, which grows like the inverse square root of the distance to it): -2 G'''(pi) with
// G''' = (125/8) sin(5 w / 2) - (5/8) sin(w / 2), worked by hand. One-sided differences of the second
// normal derivative along the radius, which is the coordinate nu itself, so the rim's curvature
// does not enter.
TEST(ContactEnd, TheEndsFieldCarriesALoadThatGrowsLikeTheInverseSquareRoot) {
  const ContactEnd e = scene_end();
  for (double s : {0.0005, 0.002}) {
    const double th = e.theta + s / e.a, nx = std::cos(th), ny = std::sin(th), x = e.cx + e.a * nx, y = e.cy + e.a * ny;
    auto nn = [&](double d) {
      const EndDerivatives u = end_field(e, EndField::Gap52, x + d * nx, y + d * ny);
      return u.wxx * nx * nx + 2 * u.wxy * nx * ny + u.wyy * ny * ny;
    };
    const double d = 1e-3 * s;
    const double jump = (nn(d) - nn(1e-12)) / d - (nn(-1e-12) - nn(-d)) / d;
    EXPECT_NEAR(jump * std::sqrt(s), -30.0, 0.3);
  }
}

// chi (F - I_h F) is zero at every node with its slopes: the grid's unknowns stay the nodal values
// of the whole field. Between nodes it is not zero where F is not a bicubic.
TEST(ContactEnd, TheEnrichmentVanishesAtTheNodesWithItsSlopes) {
  const ContactEnd e = scene_end();
  const Grid g = make_grid(64, 1.0, 0.5);
  const double d = 1e-6 * g.h;
  double between = 0, slope_between = 0, slope_at_nodes = 0;
  auto w = [&](double x, double y) { return end_function(e, EndField::Gap52, g, x, y).w; };
  for (int j = 10; j < 25; ++j)
    for (int i = 45; i < 64; ++i) {
      const double x = i * g.h, y = j * g.h, xm = x + 0.5 * g.h, ym = y + 0.5 * g.h;
      EXPECT_LT(std::abs(w(x, y)), 1e-15);
      slope_at_nodes = std::max({slope_at_nodes, std::abs(w(x + d, y) - w(x - d, y)) / (2 * d), std::abs(w(x, y + d) - w(x, y - d)) / (2 * d)});
      between = std::max(between, std::abs(w(xm, ym)));
      slope_between = std::max(slope_between, std::abs(w(xm + d, ym) - w(xm - d, ym)) / (2 * d));
    }
  EXPECT_GT(between, 1e-8);
  EXPECT_LT(slope_at_nodes, 1e-4 * slope_between);
}

namespace {
// Points about the end, in the cut-off's band and near the end and off the rim (which kinks the
// field), each moved to near the centre of its cell so that a difference stencil stays inside it
// (where I_h F is one bicubic).
std::vector<std::array<double, 2>> probe_points(const ContactEnd& e, const Grid& g) {
  std::vector<std::array<double, 2>> out;
  for (double angle : {0.4, 2.0, -1.3, -2.6})
    for (double rho : {0.01, 0.06, 0.085}) {
      const double x = (std::floor((end_x(e) + rho * std::cos(angle)) / g.h) + 0.4) * g.h;
      const double y = (std::floor((end_y(e) + rho * std::sin(angle)) / g.h) + 0.6) * g.h;
      if (std::abs(std::hypot(x - e.cx, y - e.cy) - e.a) >= 0.2 * g.h) out.push_back({x, y});
    }
  return out;
}
}  // namespace

// The Laplacian that enters K (end_function's, the blocks' own formula) against five-point
// differences of the value; all the derivatives, which a field read at a point uses, against
// fourth-order differences; and the two Laplacians against each other.
TEST(ContactEnd, TheEnrichmentsDerivativesMatchDifferences) {
  const ContactEnd e = scene_end();
  const Grid g = make_grid(64, 1.0, 0.5);
  const std::vector<std::array<double, 2>> points = probe_points(e, g);
  ASSERT_GE(points.size(), 9u);
  for (EndField f : {EndField::Gap32, EndField::Gap52})
    for (const auto& [x, y] : points) {
      const double d = 1e-3 * g.h;
      auto w = [&](double px, double py) { return end_function(e, f, g, px, py).w; };
      const EndDerivatives D = end_function_derivatives(e, f, g, x, y);
      const double scale = std::abs(D.wxx) + std::abs(D.wyy) + std::abs(D.wxy) + 1e-3;
      // Fourth-order differences: the cut-off's third derivative (about (outer - inner)^-3) makes
      // a second-order rule's error a part in 1e5 here.
      auto dx = [&](double px, double py) { return (-w(px + 2 * d, py) + 8 * w(px + d, py) - 8 * w(px - d, py) + w(px - 2 * d, py)) / (12 * d); };
      auto dy = [&](double px, double py) { return (-w(px, py + 2 * d) + 8 * w(px, py + d) - 8 * w(px, py - d) + w(px, py - 2 * d)) / (12 * d); };
      auto d2 = [&](double ux, double uy) {
        auto at = [&](double k) { return w(x + k * ux, y + k * uy); };
        return (-at(2 * d) + 16 * at(d) - 30 * at(0) + 16 * at(-d) - at(-2 * d)) / (12 * d * d);
      };
      const double lap = end_function(e, f, g, x, y).lap;
      const double five_point = (w(x + d, y) + w(x - d, y) + w(x, y + d) + w(x, y - d) - 4 * w(x, y)) / (d * d);
      EXPECT_NEAR(lap, five_point, 1e-4 * (std::abs(lap) + 1e-3)) << "at " << x << ", " << y;
      EXPECT_NEAR(D.w, w(x, y), 1e-10 * std::abs(D.w));
      EXPECT_NEAR(D.wxx + D.wyy, lap, 1e-10 * scale);
      EXPECT_NEAR(D.wx, dx(x, y), 1e-7 * (std::abs(D.wx) + 1e-4));
      EXPECT_NEAR(D.wy, dy(x, y), 1e-7 * (std::abs(D.wy) + 1e-4));
      EXPECT_NEAR(D.wxx, d2(1, 0), 1e-4 * scale);
      EXPECT_NEAR(D.wyy, d2(0, 1), 1e-4 * scale);
      EXPECT_NEAR(D.wxy, (dx(x, y + d) - dx(x, y - d)) / (2 * d), 1e-4 * scale);
    }
}

// The functions' own block is symmetric and positive definite, and the border reaches only the
// unknowns of cells within the cut-off of the end.
TEST(ContactEnd, TheBlocksAreSymmetricPositiveAndLocal) {
  const ContactEnd e = scene_end();
  const Grid g = make_grid(32, 1.0, 0.5);
  const EndBlocks b = assemble_end_blocks(g, {e, e}, {EndField::Gap32, EndField::Gap52});
  EXPECT_NEAR(b.own(0, 1), b.own(1, 0), 1e-14 * std::abs(b.own(0, 1)));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(b.own);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0);
  int far = 0, near = 0;
  for (int i = 0; i < g.unknowns(); ++i)
    if (b.border.row(i).norm() > 0) ++near;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const double cx = (ex + 0.5) * g.h, cy = (ey + 0.5) * g.h;
      if (std::hypot(cx - end_x(e), cy - end_y(e)) < e.outer + g.h) continue;
      for (int dof : g.element_dofs(ex, ey))
        if (dof >= 0 && std::hypot(cx - end_x(e), cy - end_y(e)) > e.outer + 2 * g.h) far += b.border.row(dof).norm() > 0;
    }
  EXPECT_GT(near, 20);
  EXPECT_EQ(far, 0);
}

// The blocks against a rule that knows nothing of the rim or the cut-off: 6 x 6 Gauss points on
// s x s sub-squares of every cell (those near the end halved towards it, where Lap F_32 grows like
// rho^(-1/2)), the functions read point by point (end_function). Its own error, estimated from
// s = 16 to 32, sets how far the border and the load may lie from it (twice that change: a bound
// only if the blind rule's error keeps falling, which it does here like about s^-2); the own block,
// whose integrand grows like 1 / rho, is left out. The rule as it was before, halving each cell
// towards the rim, fails it: its border lay 5.4e-4 (F_32) and 3.1e-4 (F_52) from the blind rule's,
// against 1.1e-4 and 1.0e-5 allowed; this one lies 7.1e-5 and 1.9e-6 from it.
TEST(ContactEnd, TheBlocksMatchARuleBlindToTheCurves) {
  const ContactEnd e = scene_end();
  const Grid g = make_grid(32, 1.0, 0.5);
  const std::function<double(double, double)> f = [](double x, double y) { return 1 + x * y; };
  const std::vector<EndField> fields{EndField::Gap32, EndField::Gap52};
  const EndBlocks b = assemble_end_blocks(g, {e, e}, fields, 0, {}, &f);
  auto blind = [&](int s, Eigen::MatrixXd& border, Eigen::VectorXd& load) {
    border = Eigen::MatrixXd::Zero(g.unknowns(), 2), load = Eigen::VectorXd::Zero(2);
    for (int ey = 0; ey < g.ny; ++ey)
      for (int ex = 0; ex < g.nx; ++ex) {
        if (std::hypot((ex + 0.5) * g.h - end_x(e), (ey + 0.5) * g.h - end_y(e)) > e.outer * 1.2 + g.h) continue;
        const auto dofs = g.element_dofs(ex, ey);
        blind_points(g, e, ex, ey, s, [&](double t, double u, double x, double y, double wt) {
          const LocalBasis lb = bfs_basis(t, u, g.h);
          for (int k = 0; k < 2; ++k) {
            const EndValue v = end_function(e, fields[k], g, x, y);
            load[k] += wt * f(x, y) * v.w;
            for (int d = 0; d < 16; ++d)
              if (dofs[d] >= 0) border(dofs[d], k) += wt * (lb.dxx[d] + lb.dyy[d]) * v.lap;
          }
        });
      }
  };
  Eigen::MatrixXd coarse, fine;
  Eigen::VectorXd l_coarse, l_fine;
  blind(16, coarse, l_coarse);
  blind(32, fine, l_fine);
  for (int k = 0; k < 2; ++k) {
    const double size = fine.col(k).lpNorm<Eigen::Infinity>(), own_error = (fine.col(k) - coarse.col(k)).lpNorm<Eigen::Infinity>();
    EXPECT_LT(own_error, 1e-4 * size);  // the blind rule is good enough to judge by
    EXPECT_LE((b.border.col(k) - fine.col(k)).lpNorm<Eigen::Infinity>(), 2 * own_error + 1e-12 * size) << "field " << k;
    EXPECT_LE(std::abs(b.load[k] - l_fine[k]), 2 * std::abs(l_fine[k] - l_coarse[k]) + 1e-12 * std::abs(l_fine[k])) << "field " << k;
  }
}

// The cross block with other functions of the space: given, as those, three of the grid's own basis
// functions (their Laplacians read off the cell's basis), it must give their rows of the border.
TEST(ContactEnd, TheCrossBlockOfOtherFunctionsMatchesTheBorderForGridFunctions) {
  const ContactEnd e = scene_end();
  const Grid g = make_grid(32, 1.0, 0.5);
  const std::vector<EndField> fields{EndField::Gap32, EndField::Gap52};
  const EndBlocks plain = assemble_end_blocks(g, {e, e}, fields);
  std::vector<int> picked;  // three unknowns the border reaches
  for (int i = 0; i < g.unknowns() && picked.size() < 3; i += 7)
    if (plain.border.row(i).norm() > 0) picked.push_back(i);
  ASSERT_EQ(picked.size(), 3u);
  const OtherLaplacians basis = [&](int ex, int ey, double x, double y, Eigen::VectorXd& out) {
    out.setZero();
    const auto dofs = g.element_dofs(ex, ey);
    const LocalBasis b = bfs_basis((x - ex * g.h) / g.h, (y - ey * g.h) / g.h, g.h);
    for (int i = 0; i < 16; ++i)
      for (int j = 0; j < 3; ++j)
        if (dofs[i] == picked[j]) out[j] += b.dxx[i] + b.dyy[i];
  };
  const EndBlocks b = assemble_end_blocks(g, {e, e}, fields, 3, basis);
  for (int j = 0; j < 3; ++j)
    for (int f = 0; f < 2; ++f) {
      const double want = plain.border(picked[j], f);
      EXPECT_NEAR(b.cross(j, f), want, 1e-12 * std::abs(want)) << "unknown " << picked[j] << ", field " << f;
    }
  EXPECT_EQ(b.border, plain.border);
}

// The fit iterated: the end put at e, the gap sampled beyond it (where it is open), e moved by the
// shift the fit finds (at most an eighth of the samples' reach: the expansion holds where the shift
// is small against s), again. On a gap with the next term of an end's expansion it settles on it.
TEST(ContactEnd, TheFitFindsAnEndPutOffByHand) {
  for (double end : {-0.004, 0.0, 0.003}) {
    auto gap = [&](double x) { return x > end ? 0.34 * std::pow(x - end, 2.5) - 1.5 * std::pow(x - end, 3.5) : 0.0; };
    double e = end == 0 ? 0.002 : 0.0;
    for (int k = 0; k < 12; ++k) {
      std::vector<double> s, g;
      for (int i = 0; i < 60; ++i) {
        const double si = 0.001 + 0.02 * i / 59.0;
        if (gap(e + si) > 0) s.push_back(si), g.push_back(gap(e + si));
      }
      e += std::clamp(end_shift(s, g), -0.0025, 0.0025);
    }
    EXPECT_NEAR(e, end, 1e-7) << "end " << end;
  }
  // One fit alone pins the factor 2/5: a small shift is found to a percent.
  std::vector<double> s1, g1;
  for (int i = 0; i < 40; ++i) s1.push_back(0.001 + 0.02 * i / 39.0), g1.push_back(0.34 * std::pow(s1.back() - 1e-5, 2.5));
  EXPECT_NEAR(end_shift(s1, g1), 1e-5, 1e-7);
  EXPECT_THROW(end_shift({0.01, 0.02}, {1e-6, 2e-6}), std::invalid_argument);
  std::vector<double> s, below;  // a plate that dips below the rim beyond the end
  for (double si : {0.01, 0.02, 0.03, 0.04}) s.push_back(si), below.push_back(-std::pow(si, 2.5));
  EXPECT_THROW(end_shift(s, below), std::invalid_argument);
}

namespace {
// The 2 x 1 lift-off scene's quarter on n cells along x, its rows laid out for contact on
// [theta_e, pi - theta_e] and its images, with points a cell apart off the arcs.
Problem quarter_laid_out(int n, double theta_e, bool kink = false) {
  const Scene scene = Scene::rectangle(2, 1).over(Cylinder{1, 0.5, 0.25, 0.0625});
  SamplingSpec spec{SamplingKind::Edge, EdgeRows{}};
  if (kink) spec.enrich.kind = EnrichSpec::Kind::Ring;
  const Grid whole = scene.grid(n);
  Problem p = make_problem(scene, part_of(whole, find_mirrors(scene, whole, spec)), spec);
  const double cell = p.grid.h / 0.25;
  ContactArcs contact;
  contact.arcs = {{theta_e, M_PI - theta_e}, {M_PI + theta_e, 2 * M_PI - theta_e}};
  lay_out_rim(p, layout_for(contact, 0, 2 * cell, 4 * cell, edge_points(p.scene.edge, p.grid.h).theta, 1e-14));
  return p;
}
}  // namespace

// The ends' functions as part of a problem (attach_ends): the space only grows and the rows are the
// same, so the constrained minimum of the energy cannot rise, and it falls since the end's field is
// new to the grid; the answer is certified, refinement (D22) included. The field read at a point is
// the grid's plus the ends' share, and read in the mirror image it is the same with the slopes
// across the line turned. A second attach, and a cut-off that reaches a mirror line, are refused.
TEST(ContactEnd, TheEndsFunctionsLowerTheEnergyOfTheSameRows) {
  const double theta_e = 0.98;
  Problem plain = quarter_laid_out(64, theta_e);
  const ExactResult r0 = solve_exact_rows(plain, ExactOptions{}, NodeSet{}, RowExchange{}, nullptr);
  Problem p = quarter_laid_out(64, theta_e);
  const Grid& g = p.grid;
  const ContactEnd e{g.lx(), g.ly(), 0.25, M_PI + theta_e, -1, 0.05, 0.1};
  attach_ends(p, {e, e}, {EndField::Gap32, EndField::Gap52});
  ASSERT_EQ(p.unknowns(), plain.unknowns() + 2);
  const ExactResult r1 = solve_exact_rows(p, ExactOptions{}, NodeSet{}, RowExchange{}, nullptr);
  ASSERT_TRUE(r0.converged && r1.converged);
  const double e0 = energy(plain, r0.w), e1 = energy(p, r1.w);
  EXPECT_LT(e1, e0 - 1e-9 * std::abs(e0));
  EXPECT_GT(e1, e0 - 1e-3 * std::abs(e0));
  EXPECT_NE(r1.w[p.unknowns() - 1], 0.0);
  const double x = e.cx + 0.27 * std::cos(e.theta - 0.05), y = e.cy + 0.27 * std::sin(e.theta - 0.05);
  const VectorXd grid_only = r1.w.head(g.unknowns());
  const double ends = r1.w[p.unknowns() - 2] * end_function(e, EndField::Gap32, g, x, y).w +
                      r1.w[p.unknowns() - 1] * end_function(e, EndField::Gap52, g, x, y).w;
  const PlateField field(p, r1.w);
  EXPECT_NEAR(field.at(x, y).w, evaluate(g, grid_only, x, y).w + ends, 1e-15);
  EXPECT_NE(ends, 0.0);
  const PointValues here = field.enrichment_at(x, y), there = field.enrichment_at(2 * g.lx() - x, y);
  EXPECT_NE(here.wx, 0.0);
  // (2 lx - x is folded back to x only to round-off.)
  EXPECT_NEAR(there.w, here.w, 1e-9 * std::abs(here.w));
  EXPECT_NEAR(there.wx, -here.wx, 1e-9 * std::abs(here.wx));
  EXPECT_NEAR(there.wy, here.wy, 1e-9 * std::abs(here.wy));
  EXPECT_NEAR(there.wxy, -here.wxy, 1e-9 * std::abs(here.wxy));
  EXPECT_THROW(attach_ends(p, {e}, {EndField::Gap52}), std::logic_error);
  Problem near_line = quarter_laid_out(64, theta_e);
  ContactEnd too_close = e;
  too_close.outer = 0.15;  // its reach, 0.167 in the plane, crosses the mirror line x = 1 (0.139 away)
  EXPECT_THROW(attach_ends(near_line, {too_close}, {EndField::Gap52}), std::invalid_argument);
}

// The ends' columns of S: at a point row the function's value, on a spline row its average against
// the row's spline, here by a rule of its own (eight Gauss points on each sixteenth of a span). The
// rows take four on pieces of about a cell, not split where I_h F's curvature jumps at the cells'
// sides: that rule defines the constraint, for the grid's functions as for these, and it stands
// within a percent of the finer one, so a row read on the wrong arc, basis or circle fails. The
// grid's columns are as they were without the ends.
TEST(ContactEnd, TheEndsColumnsReadEveryRowByItsOwnRule) {
  const double theta_e = 0.98;
  const Problem plain = quarter_laid_out(64, theta_e);
  Problem p = quarter_laid_out(64, theta_e);
  const Grid& g = p.grid;
  const ContactEnd e{g.lx(), g.ly(), 0.25, M_PI + theta_e, -1, 0.05, 0.1};
  attach_ends(p, {e}, {EndField::Gap52});
  const int N = g.unknowns(), col = p.unknowns() - 1;
  const RowSpMat grid_part = p.sampling.S.leftCols(N), before = plain.sampling.S.leftCols(N);
  EXPECT_EQ((RowSpMat(grid_part - before)).norm(), 0.0);
  const Quadrature1D q = gauss_legendre(8);
  int points = 0, splines = 0;
  double largest = 0, worst = 0;
  for (int k = 0; k < p.sampling.edge_size(); ++k) {
    const int row = p.sampling.edge_begin + k;
    const RimRow& r = p.sampling.rim_rows[k];
    double want = 0;
    if (r.point()) {
      want = end_function(e, EndField::Gap52, g, p.sampling.x[row], p.sampling.y[row]).w;
      EXPECT_DOUBLE_EQ(p.sampling.S.coeff(row, col), want);
      points += want != 0;
      continue;
    }
    const SplineArc& arc = p.sampling.rim.arcs[r.arc];
    for (int span = r.basis; span <= r.basis + 3; ++span)
      for (int piece = 0; piece < 16; ++piece)
        for (size_t i = 0; i < q.points.size(); ++i) {
          const double lo = arc.knot(span, 3), hi = arc.knot(span + 1, 3), t = lo + (hi - lo) * (piece + q.points[i]) / 16;
          want += clamped_bspline(arc, 3, r.basis, t) * (hi - lo) * q.weights[i] / 16 *
                  end_function(e, EndField::Gap52, g, e.cx + e.a * std::cos(t), e.cy + e.a * std::sin(t)).w;
        }
    want /= clamped_bspline_integral(arc, 3, r.basis);
    splines += want != 0;
    largest = std::max(largest, std::abs(want));
    worst = std::max(worst, std::abs(p.sampling.S.coeff(row, col) - want));
  }
  EXPECT_GT(points, 2);
  EXPECT_GT(splines, 2);
  EXPECT_LT(worst, 1e-2 * largest);
}

namespace {
// Every psi_j's Laplacian of (D31) at (x, y) in cell (ex, ey), its interpolant read off the cell's
// basis with P, the interpolant as a dense matrix (kept alive by the caller): each function formed
// in full, where attach_ends forms only those met in the cell.
OtherLaplacians kink_laplacians_by_basis(const Problem& p, const Eigen::MatrixXd& P) {
  return [&p, &P](int ex, int ey, double x, double y, Eigen::VectorXd& out) {
    const Grid& g = p.grid;
    const auto dofs = g.element_dofs(ex, ey);
    const LocalBasis b = bfs_basis((x - ex * g.h) / g.h, (y - ey * g.h) / g.h, g.h);
    const int Kk = p.kink->size();
    for (int j = 0; j < Kk; ++j) {
      KinkValue I;
      for (int i = 0; i < 16; ++i)
        if (dofs[i] >= 0)
          I.w += P(dofs[i], j) * b.v[i], I.wx += P(dofs[i], j) * b.dx[i], I.wy += P(dofs[i], j) * b.dy[i],
              I.wxx += P(dofs[i], j) * b.dxx[i], I.wxy += P(dofs[i], j) * b.dxy[i], I.wyy += P(dofs[i], j) * b.dyy[i];
      const KinkValue v = kink_field(*p.kink, VectorXd::Unit(Kk, j), I, x, y);
      out[j] = v.wxx + v.wyy;
    }
  };
}
}  // namespace

// With (D31) on the rim too, the ends' cross block with its functions: attach_ends forms only the
// functions met in each cell; here every function is formed at every point, and K's entries must
// be the same.
TEST(ContactEnd, TheCrossBlockWithTheKinksFunctionsMissesNone) {
  const double theta_e = 0.98;
  Problem p = quarter_laid_out(64, theta_e, true);
  ASSERT_TRUE(p.kink.has_value());
  const Grid& g = p.grid;
  const int N = g.unknowns(), Kk = p.kink->size();
  const ContactEnd e{g.lx(), g.ly(), 0.25, M_PI + theta_e, -1, 0.05, 0.1};
  const Eigen::MatrixXd P(p.kink_interp);
  const OtherLaplacians every = kink_laplacians_by_basis(p, P);
  const OtherKinks kinks = kink_curves(*p.kink);  // the same rule as attach_ends
  const EndBlocks full = assemble_end_blocks(g, {e}, {EndField::Gap52}, Kk, every, &p.scene.load, &kinks);
  attach_ends(p, {e}, {EndField::Gap52});
  int nonzero = 0;
  for (int j = 0; j < Kk; ++j) {
    EXPECT_NEAR(p.K.coeff(N + j, N + Kk), full.cross(j, 0), 1e-13 * full.cross.cwiseAbs().maxCoeff()) << "function " << j;
    nonzero += full.cross(j, 0) != 0;
  }
  EXPECT_GE(nonzero, 2);
}

// The cross block of the ends' functions with (D31)'s, (Lap psi_j, Lap E), against the same
// integral by a tensor rule blind to every curve either function kinks on (the rim, (D31)'s cut-off
// and knot rays, the end's own cut-off), on s x s sub-squares of each cell, halved again near the
// end itself (blind_points): its own error shows from s = 8 to 16, and the assembled block must lie within it.
TEST(ContactEnd, TheCrossBlockWithTheKinksFunctionsMatchesARuleBlindToTheCurves) {
  const double theta_e = 0.98;
  Problem p = quarter_laid_out(32, theta_e, true);
  ASSERT_TRUE(p.kink.has_value());
  const Grid& g = p.grid;
  const int Kk = p.kink->size();
  const ContactEnd e{g.lx(), g.ly(), 0.25, M_PI + theta_e, -1, 0.05, 0.1};
  const Eigen::MatrixXd P(p.kink_interp);
  const OtherLaplacians every = kink_laplacians_by_basis(p, P);
  const OtherKinks kinks = kink_curves(*p.kink);
  const EndBlocks b = assemble_end_blocks(g, {e}, {EndField::Gap52}, Kk, every, &p.scene.load, &kinks);
  auto blind = [&](int s) {
    Eigen::VectorXd cross = Eigen::VectorXd::Zero(Kk), lap(Kk);
    for (int ey = 0; ey < g.ny; ++ey)
      for (int ex = 0; ex < g.nx; ++ex) {
        if (std::hypot((ex + 0.5) * g.h - end_x(e), (ey + 0.5) * g.h - end_y(e)) > end_reach(e) + g.h) continue;
        blind_points(g, e, ex, ey, s, [&](double, double, double x, double y, double wt) {
          const EndValue v = end_function(e, EndField::Gap52, g, x, y);
          if (v.lap == 0) return;
          every(ex, ey, x, y, lap);
          cross += wt * v.lap * lap;
        });
      }
    return cross;
  };
  const Eigen::VectorXd coarse = blind(8), fine = blind(16);
  const double size = fine.lpNorm<Eigen::Infinity>(), own = (fine - coarse).lpNorm<Eigen::Infinity>();
  ASSERT_GT(size, 0);
  EXPECT_LT(own, 1e-4 * size);  // the blind rule is good enough to judge by
  int reached = 0;
  for (int j = 0; j < Kk; ++j) {
    EXPECT_LE(std::abs(b.cross(j, 0) - fine[j]), 2 * own + 1e-12 * size) << "function " << j;
    reached += std::abs(fine[j]) > 100 * own;
  }
  EXPECT_GE(reached, 2);  // the comparison is not among zeros
}

// Two distinct ends on one rim, as the whole 2 x 1 plate has them (theta = pi + 0.98 and
// 2 pi - 0.98, the lower half's two): assembled together, each end's border, load and own entry
// are those it gets alone, to round-off, since the other end's curves and halvings reach none of
// the squares where this end's function lives (its reach plus a cell each side). Where
// the two cut-offs are far apart the coupling (Lap E_1, Lap E_2) is zero; brought within reach
// of each other it is not, and the own block stays symmetric and positive definite.
TEST(ContactEnd, TwoDistinctEndsOnOneRimAssembleAsEachAlone) {
  const Grid g = make_grid(64, 2.0, 1.0);
  const std::function<double(double, double)> f = [](double x, double y) { return 1 + x * y; };
  const ContactEnd left{1, 0.5, 0.25, M_PI + 0.98, -1, 0.04, 0.08}, right{1, 0.5, 0.25, 2 * M_PI - 0.98, +1, 0.04, 0.08};
  const EndBlocks both = assemble_end_blocks(g, {left, right}, {EndField::Gap52, EndField::Gap52}, 0, {}, &f);
  const EndBlocks l = assemble_end_blocks(g, {left}, {EndField::Gap52}, 0, {}, &f);
  const EndBlocks r = assemble_end_blocks(g, {right}, {EndField::Gap52}, 0, {}, &f);
  const double scale = both.border.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0);
  EXPECT_LE((both.border.col(0) - l.border.col(0)).lpNorm<Eigen::Infinity>(), 1e-13 * scale);
  EXPECT_LE((both.border.col(1) - r.border.col(0)).lpNorm<Eigen::Infinity>(), 1e-13 * scale);
  EXPECT_NEAR(both.load[0], l.load[0], 1e-13 * std::abs(l.load[0]));
  EXPECT_NEAR(both.load[1], r.load[0], 1e-13 * std::abs(r.load[0]));
  EXPECT_NEAR(both.own(0, 0), l.own(0, 0), 1e-13 * l.own(0, 0));
  EXPECT_NEAR(both.own(1, 1), r.own(0, 0), 1e-13 * r.own(0, 0));
  // The ends lie 2 a cos(0.98) = 0.28 apart and each reaches about 0.085: no overlap.
  ASSERT_GT(std::hypot(end_x(left) - end_x(right), end_y(left) - end_y(right)), 2 * end_reach(left) + 2 * g.h);
  EXPECT_EQ(both.own(0, 1), 0);
  EXPECT_EQ(both.own(1, 0), 0);
  // Wider cut-offs that overlap: a coupling, symmetric, and the block still positive definite.
  ContactEnd wl = left, wr = right;
  wl.inner = wr.inner = 0.08, wl.outer = wr.outer = 0.16;
  const EndBlocks wide = assemble_end_blocks(g, {wl, wr}, {EndField::Gap52, EndField::Gap52});
  EXPECT_NE(wide.own(0, 1), 0);
  EXPECT_NEAR(wide.own(0, 1), wide.own(1, 0), 1e-13 * std::abs(wide.own(0, 1)));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(wide.own);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0);
  // A cut-off past a - sqrt(2) h, where the fitted coordinates stop, is refused (it gave NaN), as is
  // an empty one.
  wl.outer = 0.3;
  EXPECT_THROW(assemble_end_blocks(g, {wl}, {EndField::Gap52}), std::invalid_argument);
  wl.outer = wl.inner;
  EXPECT_THROW(assemble_end_blocks(g, {wl}, {EndField::Gap52}), std::invalid_argument);
}

// The kink-carrying functions of (D31): their blocks against a brute-force quadrature of the same
// integrals, the properties the derivation asks of them, and the order they buy against the
// rim-contact series, an independent solution of the same problem.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/SparseCholesky>

#include "active_set.hpp"
#include "assemble.hpp"
#include "bfs_element.hpp"
#include "contact.hpp"
#include "extrema.hpp"
#include "gauss.hpp"
#include "kink_enrichment.hpp"
#include "mirror.hpp"
#include "published.hpp"
#include "rim_contact.hpp"
#include "side_kinks.hpp"

using namespace plate;

namespace {
const EdgeCurve kRim = circle_edge(0.5, 0.5, 0.25);

// sum_k c_k psi_k at (x, y), its interpolant's part read from the grid as plate reads it.
KinkValue field(const Grid& g, const KinkEnrichment& e, const VectorXd& c, const VectorXd& Pc, double x, double y) {
  const PointValues I = evaluate(g, Pc, x, y);
  return kink_field(e, c, KinkValue{I.w, I.wx, I.wy, I.wxx, I.wxy, I.wyy}, x, y);
}

// The coefficients of one function.
VectorXd unit(int m, int k) {
  VectorXd c = VectorXd::Zero(m);
  c[k] = 1;
  return c;
}

// (Lap psi_k, Lap phi_i), (Lap psi_k, Lap psi_k) and (1, psi_k) by tensor Gauss rules on s x s
// sub-squares of every cell, psi_k read through kink_field: a rule that knows nothing of the rim, so
// it converges slowly where the rim cuts a sub-square, and its own error shows from s to 2 s.
struct Brute {
  double b = 0, e = 0, load = 0;
};
Brute brute(const Grid& g, const KinkEnrichment& e, const SpMat& P, int k, int dof, int s, int points = 6) {
  const VectorXd c = unit(e.size(), k), Pc = P * c;
  const Quadrature1D q = gauss_legendre(points);
  Brute out;
  const double hs = g.h / s;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const auto dofs = g.element_dofs(ex, ey);
      int local = -1;
      for (int i = 0; i < 16; ++i)
        if (dofs[i] == dof) local = i;
      if (e.polygon() && local < 0 && !kink_near(e, (ex + 0.5) * g.h, (ey + 0.5) * g.h) && !kink_near(e, ex * g.h, ey * g.h)) {
        bool any = false;  // a square none of whose points is near: psi_k is 0 on it
        for (int i = 0; i <= 4 && !any; ++i)
          for (int j = 0; j <= 4 && !any; ++j) any = kink_near(e, (ex + i / 4.0) * g.h, (ey + j / 4.0) * g.h);
        if (!any) continue;
      }
      for (int sy = 0; sy < s; ++sy)
        for (int sx = 0; sx < s; ++sx)
          for (size_t i = 0; i < q.points.size(); ++i)
            for (size_t j = 0; j < q.points.size(); ++j) {
              const double x = ex * g.h + (sx + q.points[i]) * hs, y = ey * g.h + (sy + q.points[j]) * hs;
              const double wt = q.weights[i] * q.weights[j] * hs * hs;
              const KinkValue v = field(g, e, c, Pc, x, y);
              const double lap = v.wxx + v.wyy;
              out.e += wt * lap * lap;
              out.load += wt * v.w;
              if (local >= 0) {
                const LocalBasis lb = bfs_basis((x - ex * g.h) / g.h, (y - ey * g.h) / g.h, g.h);
                out.b += wt * lap * (lb.dxx[local] + lb.dyy[local]);
              }
            }
    }
  return out;
}

// The grid unknown with the largest coupling to function k in the border.
int strongest_dof(const KinkBlocks& b, int N, int k) {
  int dof = -1;
  double largest = 0;
  for (SpMat::InnerIterator it(b.border, N + k); it; ++it)
    if (it.row() < N && std::abs(it.value()) > largest) largest = std::abs(it.value()), dof = static_cast<int>(it.row());
  return dof;
}

// The assembled (Lap phi_dof, Lap psi_k), (Lap psi_k, Lap psi_k) and (1, psi_k) within the brute-force
// rule's own error (its step from `coarse` to `fine`, or `floor` of the entry where that is smaller),
// and that error at most `resolved` of each entry: the rule must resolve what it judges.
void expect_within_brute(const KinkBlocks& b, int N, int k, int dof, const Brute& coarse, const Brute& fine, double floor,
                         const double resolved[3]) {
  const double assembled[3] = {b.border.coeff(dof, N + k), b.border.coeff(N + k, N + k), b.load[k]};
  const double rough[3] = {coarse.b, coarse.e, coarse.load}, good[3] = {fine.b, fine.e, fine.load};
  for (int i = 0; i < 3; ++i) {
    const double own = std::abs(good[i] - rough[i]);
    EXPECT_LE(std::abs(assembled[i] - good[i]), std::max(own, floor * std::abs(good[i]))) << i << " assembled " << assembled[i] << " good " << good[i] << " rough " << rough[i];
    EXPECT_LT(own, resolved[i] * std::abs(good[i])) << i;
  }
}

// Over the grid's interior nodes: the largest of |w|, |w_x|, |w_y|, |w_xy| of sum c_k psi_k (which
// must vanish there) and the largest |w_xx| + |w_yy| (its size).
struct NodeScan {
  double at_nodes = 0, size = 0;
};
NodeScan scan_nodes(const Grid& g, const KinkEnrichment& e, const VectorXd& c, const VectorXd& Pc) {
  NodeScan o;
  for (int j = 1; j < g.ny; ++j)
    for (int i = 1; i < g.nx; ++i) {
      const KinkValue v = field(g, e, c, Pc, g.x(i), g.y(j));
      o.at_nodes = std::max({o.at_nodes, std::abs(v.w), std::abs(v.wx), std::abs(v.wy), std::abs(v.wxy)});
      o.size = std::max(o.size, std::abs(v.wxx) + std::abs(v.wyy));
    }
  return o;
}

// The field and its slopes agree from either side of the cell side x = xs, at each y.
void expect_c1_across(const Grid& g, const KinkEnrichment& e, const VectorXd& c, const VectorXd& Pc, double xs,
                      std::initializer_list<double> ys) {
  const double d = 1e-10;
  for (double y : ys) {
    const KinkValue l = field(g, e, c, Pc, xs - d, y), r = field(g, e, c, Pc, xs + d, y);
    EXPECT_NEAR(l.w, r.w, 1e-12) << y;
    EXPECT_NEAR(l.wx, r.wx, 1e-9) << y;
    EXPECT_NEAR(l.wy, r.wy, 1e-9) << y;
  }
}

// The paper's scene at n = 64 with (D31), solved on its quarter.
SceneSolution paper_scene_with_kink() {
  SamplingSpec spec{SamplingKind::Edge};
  spec.enrich.kind = EnrichSpec::Kind::Ring;
  return solve_exact_scene(paper_scene(), 64, spec, ExactOptions{});
}
}  // namespace

// The assembled blocks (polar rule split at the rim, the cut-off, the knots and the cells' corners)
// agree with the brute-force rule to within the brute-force rule's own error, estimated from
// 8 x 8 to 16 x 16 sub-squares.
TEST(KinkEnrichment, BlocksMatchABruteForceQuadrature) {
  const Grid g = make_grid(32);
  const KinkEnrichment e = make_kink_enrichment(g, kRim, 64);
  const SpMat P = kink_interpolant(g, e);
  const KinkBlocks blocks = assemble_kink_blocks(g, e, P, [](double, double) { return 1.0; });
  const int N = g.unknowns(), k = 5;
  const int dof = strongest_dof(blocks, N, k);
  ASSERT_GE(dof, 0);
  const double resolved[3] = {0.01, 0.01, 0.01};
  expect_within_brute(blocks, N, k, dof, brute(g, e, P, k, dof, 8), brute(g, e, P, k, dof, 16), 1e-13, resolved);
  EXPECT_EQ(blocks.border.coeff(N + k, dof), blocks.border.coeff(dof, N + k));
}

// psi_k vanishes with its slopes and twist at every node, so the grid's unknowns are the field's
// nodal values; it is C^1 across cell sides; and its third radial derivative jumps by 6 B_k / h^3 at the
// rim (read off by one-sided differences), the kink of (D31).
TEST(KinkEnrichment, VanishesAtNodesIsC1AndCarriesTheJump) {
  const Grid g = make_grid(32);
  const KinkEnrichment e = make_kink_enrichment(g, kRim, 64);
  const SpMat P = kink_interpolant(g, e);
  VectorXd c(e.size());
  // Times h^3, which F_k divides by: the field is then sum (1 + sin / 2) of the unscaled profiles.
  for (int k = 0; k < e.size(); ++k) c[k] = (1 + 0.5 * std::sin(0.3 * k)) * std::pow(e.unit, 3);
  const VectorXd Pc = P * c;
  const NodeScan scan = scan_nodes(g, e, c, Pc);
  EXPECT_GT(scan.size, 1e-2);  // about 6 h c at the rim
  EXPECT_LT(scan.at_nodes, 1e-12 * scan.size);
  expect_c1_across(g, e, c, Pc, g.x(24), {0.45, 0.5, 0.53});  // cells cut by the rim near y = 0.5
  for (double theta : {0.1, 1.0, 2.5}) {
    const double cs = std::cos(theta), sn = std::sin(theta), step = 2e-5;
    auto w = [&](double r) { return field(g, e, c, Pc, 0.5 + r * cs, 0.5 + r * sn).w; };
    auto third = [&](double side) {
      const double a = 0.25;
      return side * (w(a + 3 * side * step) - 3 * w(a + 2 * side * step) + 3 * w(a + side * step) - w(a)) / (step * step * step);
    };
    double jump = 0;  // 6 sum_j c_j B_j(theta) (1 - d / (2a)), d = 1e-4: F_k's third derivative outside
    for (int k = 0; k < e.size(); ++k) jump += 6 * c[k] * kink_profile(e, k, 0.5 + 0.2501 * cs, 0.5 + 0.2501 * sn).w / std::pow(1e-4, 3);
    EXPECT_NEAR(third(1) - third(-1), jump, 0.01 * std::abs(jump)) << theta;
  }
}

// On either side of the rim the plate obeys Lap^2 w = f, so the jumps of F_k must leave Lap^2 F_k
// continuous: Lap^2 F_k -> 0 as r -> a from outside (F_k is 0 inside). With the cube alone it tends to
// 12 B_k / a, the fourth-derivative jump (D32) missing; with (D32) carried what is left is the fifth
// derivative's, linear in r - a. Lap^2 by the five-point stencil on the exact Laplacian of F_k.
TEST(KinkEnrichment, CarriesTheFourthDerivativesJumpThatACircleForces) {
  const Grid g = make_grid(32);
  const KinkEnrichment e = make_kink_enrichment(g, kRim, 64);
  const int k = 5;
  // Half a spacing from spline k's centre, between knots, where B_k''' does not jump under the stencil:
  // B_k = 23/48 and B_k'' = -1 / (2 spacing^2) there.
  const double spacing = 2 * M_PI / e.knots, theta = (k + 0.5) * spacing, B = 23.0 / 48, B2 = -0.5 / (spacing * spacing);
  auto lap = [&](double x, double y) {  // of the unscaled profile: F_k times h^3
    const KinkValue v = kink_profile(e, k, x, y);
    return (v.wxx + v.wyy) * std::pow(e.unit, 3);
  };
  auto bilap = [&](double d) {
    const double x = 0.5 + (e.a + d) * std::cos(theta), y = 0.5 + (e.a + d) * std::sin(theta), s = d / 8;
    return (lap(x + s, y) + lap(x - s, y) + lap(x, y + s) + lap(x, y - s) - 4 * lap(x, y)) / (s * s);
  };
  const double missing = 12 * B / e.a;  // what the cube alone leaves at the rim
  const double d = 1e-4, at_rim = 2 * bilap(d) - bilap(2 * d), slope = (bilap(2 * d) - bilap(d)) / d;
  EXPECT_LT(std::abs(at_rim), 0.02 * missing);
  // The slope is minus the fifth derivative's jump, which F_k leaves to the grid: 6 (7 B_k - 2 B_k'') /
  // a^2 from [d/dr Lap^2 w] = 0 (D32's next term).
  const double fifth = 6 * (7 * B - 2 * B2) / (e.a * e.a);
  EXPECT_NEAR(slope, -fifth, 0.02 * std::abs(fifth));
}

// (D31) does not fit a circle too close to a clamped edge or too small for the grid, and says so.
TEST(KinkEnrichment, RefusesWhereItDoesNotFit) {
  EXPECT_TRUE(kink_fits(make_grid(16), kRim));
  EXPECT_FALSE(kink_fits(make_grid(8), kRim));                                    // 2 cells to the edge
  EXPECT_FALSE(kink_fits(make_grid(64), circle_edge(0.5, 0.5, 0.02)));            // about one cell in radius
  EXPECT_FALSE(kink_fits(make_grid(64), circle_edge(0.3, 0.5, 0.25)));            // 0.05 from the edge: 3.2 cells
  EXPECT_THROW(make_kink_enrichment(make_grid(8), kRim, 16), std::invalid_argument);
  EXPECT_THROW(make_kink_enrichment(make_grid(32), kRim, 10), std::invalid_argument);
}

// The cut-off's band: its flat part must hold every square the rim cuts (more than sqrt(2) cells),
// it must reach 0 beyond that, and a wider band needs more room to the clamped edge.
TEST(KinkEnrichment, RefusesABandThatBreaksItsRules) {
  for (const KinkBand& b : {KinkBand{1.4, 2.5}, KinkBand{1.5, 1.5}, KinkBand{NAN, 2.5}, KinkBand{1.5, INFINITY}})
  {
    EXPECT_THROW(make_kink_enrichment(make_grid(32), kRim, 32, b), std::invalid_argument) << b.flat << " to " << b.zero;
    EXPECT_THROW(kink_fits(make_grid(32), kRim, b), std::invalid_argument) << b.flat << " to " << b.zero;  // not a quiet misfit
  }
  const KinkBand wide{4, 8};  // 9.5 cells to the edge: the paper's disk is 8 cells from it on n = 32, 16 on n = 64
  EXPECT_TRUE(kink_fits(make_grid(32), kRim));
  EXPECT_FALSE(kink_fits(make_grid(32), kRim, wide));
  EXPECT_TRUE(kink_fits(make_grid(64), kRim, wide));
  EXPECT_NEAR(make_kink_enrichment(make_grid(64), kRim, 32, wide).outer, 8.0 / 64, 1e-15);
}

// The paper's scene with every length times 1e-80: w scales with the lengths and the force with
// their inverse, so scaled back it is the paper's answer. Unscaled, (D31)'s blocks (of order h^4
// beside K's h^-2) underflowed there and the factorisation failed.
TEST(KinkEnrichment, SolvesAPlateStatedInTinyUnits) {
  const double L = 1e-80, R = paper_scene().cylinder->height;
  SamplingSpec spec{SamplingKind::Edge};
  spec.enrich.kind = EnrichSpec::Kind::Ring;
  const SceneSolution unit = solve_exact_scene(paper_scene(), 32, spec, ExactOptions{});
  const SceneSolution tiny = solve_exact_scene(Scene::rectangle(L, L).over(Cylinder{0.5 * L, 0.5 * L, 0.25 * L, R * L}), 32, spec, ExactOptions{});
  ASSERT_TRUE(tiny.result.converged) << tiny.result.message;
  ASSERT_TRUE(tiny.solved.kink.has_value());
  const double w1 = extremum_of_w(unit.whole(), unit.result.w, +1).value, wL = extremum_of_w(tiny.whole(), tiny.result.w, +1).value;
  const double f1 = total_contact_force(unit.whole(), unit.result.lambda), fL = total_contact_force(tiny.whole(), tiny.result.lambda);
  EXPECT_NEAR(wL / L, w1, 1e-12 * w1);
  EXPECT_NEAR(fL * L, f1, 1e-11 * f1);
}

// The smallest disk (D31) fits, two cells in radius on n = 64: still carried, certified, and
// converging at order four in max w and the force against the series (kink_study measures 4.5 and
// 4.3 from n = 64 to 128).
TEST(KinkEnrichment, ConvergesOnTheSmallestDiskItFits) {
  const Scene s = Scene::rectangle(1, 1).over(Cylinder{0.5, 0.5, 1.0 / 32, 0.0625});
  const RimAnswer series = rim_answer(s);
  ASSERT_TRUE(series.premise.holds);
  ASSERT_TRUE(series.settled);  // in long double: in double its last changes stall at round-off
  const double w = series.finest.max_w().w, f = series.finest.total_force();
  SamplingSpec spec{SamplingKind::Edge};
  spec.enrich.kind = EnrichSpec::Kind::Ring;
  std::vector<double> ew, ef;
  for (int n : {64, 128}) {
    const SceneSolution x = solve_exact_scene(s, n, spec, ExactOptions{});
    ASSERT_TRUE(x.result.converged) << x.result.message;
    ASSERT_TRUE(x.solved.kink.has_value()) << n;
    ew.push_back(std::abs(extremum_of_w(x.whole(), x.result.w, +1).value - w) / w);
    ef.push_back(std::abs(total_contact_force(x.whole(), x.result.lambda) - f) / f);
  }
  EXPECT_GE(std::log2(ew[0] / ew[1]), 3.8) << ew[0] << " " << ew[1];
  EXPECT_GE(std::log2(ef[0] / ef[1]), 3.8) << ef[0] << " " << ef[1];
}

// Against the rim-contact series on the paper's scene (a quarter solved) and an off-centre cylinder
// (a half: one mirror line): max w and the total force on n = 32, 64, 128 with the kink carried. The
// force at an observed order of at least 3.8 between the last two grids; max w, which has no steady
// order once (D32) is carried, closer on n = 128 than on 64; and n = 128 within 5e-9 (max w) and 5e-8
// (force) of the series, where the plain space is off by 3e-7 and 4e-7.
TEST(KinkEnrichment, ConvergesAgainstTheSeriesTheForceAtOrderFour) {
  for (const Scene& s : {paper_scene(), Scene::rectangle(1, 1).over(Cylinder{0.45, 0.5, 0.25, 0.0625})}) {
    const RimAnswer series = rim_answer(s, 6, false, 3);
    const RimPeak peak = series.finest.max_w();
    const double force = series.finest.total_force();
    SamplingSpec spec{SamplingKind::Edge};
    spec.enrich.kind = EnrichSpec::Kind::Ring;
    std::vector<double> ew, ef;
    for (int n : {32, 64, 128}) {
      const SceneSolution x = solve_exact_scene(s, n, spec, ExactOptions{});
      ASSERT_TRUE(x.result.converged) << n;
      ASSERT_TRUE(x.solved.kink.has_value()) << n;
      ew.push_back(std::abs(evaluate(x.whole(), x.result.w, peak.x, peak.y).w - peak.w) / peak.w);
      ef.push_back(std::abs(total_contact_force(x.whole(), x.result.lambda) - force) / force);
    }
    EXPECT_LT(ew[2], ew[1]);
    EXPECT_GE(std::log2(ef[1] / ef[2]), 3.8);
    EXPECT_LT(ew[2], 5e-9);
    EXPECT_LT(ef[2], 5e-8);
  }
}

// The field read on the whole plate (a quarter solved, unfolded) is the field of the part: at points
// near the rim, beyond the mirror lines too, where the enrichment's share is not small.
TEST(KinkEnrichment, UnfoldedFieldIsThePartsField) {
  const SceneSolution x = paper_scene_with_kink();
  ASSERT_TRUE(x.solved.kink && x.whole().kink);
  double share = 0;
  for (double theta : {0.3, 1.2, 2.0, 3.5, 5.0}) {
    const double r = 0.25 + 0.6 / 64, px = 0.5 + r * std::cos(theta), py = 0.5 + r * std::sin(theta);
    const PointValues whole = evaluate(x.whole(), x.result.w, px, py);
    const PointValues part = evaluate(x.solved, x.part_w, px, py);  // reflected into the quarter
    EXPECT_NEAR(whole.w, part.w, 1e-14);
    EXPECT_NEAR(whole.wxx, part.wxx, 1e-9);
    EXPECT_NEAR(whole.wxy, part.wxy, 1e-9);
    share = std::max(share, std::abs(PlateField(x.whole(), x.result.w).enrichment_at(px, py).wxx));
  }
  EXPECT_GT(share, 1e-3);
}

// value_at is at(x, y).w to the last bit, on the part and on the whole plate, near the rim (where
// the enrichment's share is read), deep inside it, beyond the cut-off, on the mirror lines and at
// the corner; and it refuses a point off the plate as at() does.
TEST(KinkEnrichment, ValueAtIsTheValueThatAtReads) {
  const SceneSolution x = paper_scene_with_kink();
  ASSERT_TRUE(x.solved.kink && x.whole().kink);
  int near = 0;
  for (const auto& [p, w] : {std::pair<const Problem*, const VectorXd*>{&x.solved, &x.part_w}, {&x.whole(), &x.result.w}}) {
    const PlateField field(*p, *w);
    for (int k = 0; k < 400; ++k) {
      // radii from deep inside the rim to beyond the cut-off, at angles all round
      const double r = 0.25 + (k % 20 - 8) * 0.25 / 64, theta = 0.0157 * k * 7.3;
      const double px = 0.5 + r * std::cos(theta), py = 0.5 + r * std::sin(theta);
      EXPECT_EQ(field.value_at(px, py), field.at(px, py).w) << px << ", " << py;
      near += kink_near(*p->kink, px, py) && field.enrichment_at(px, py).w != 0;
    }
    for (const auto& [px, py] : {std::pair{0.5, 0.5}, {0.5, 0.3}, {0.0, 0.0}, {1.0, 1.0}, {0.5, 0.7}})
      EXPECT_EQ(field.value_at(px, py), field.at(px, py).w) << px << ", " << py;
    EXPECT_THROW(field.value_at(1.5, 0.5), std::invalid_argument);
  }
  EXPECT_GT(near, 100);  // the enrichment's share was read, not only the grid's
}

// Every row of S reads the field of the whole space: a point row on the rim the enriched field at
// its point, a nodal row the nodal value, also after rows were laid out for the contact and added
// where the plate dipped (a lift-off scene, where both happen).
TEST(KinkEnrichment, RowsReadTheEnrichedField) {
  SamplingSpec spec{SamplingKind::Edge};
  spec.enrich.kind = EnrichSpec::Kind::Ring;
  const Scene s = Scene::rectangle(1.5, 1).over(Cylinder{0.6, 0.45, 0.25, 0.0625});
  const SceneSolution x = solve_exact_scene(s, 96, spec, ExactOptions{});
  ASSERT_TRUE(x.result.converged) << x.result.message;
  const Problem& p = x.solved;
  ASSERT_TRUE(p.kink.has_value());
  ASSERT_TRUE(p.sampling.rim_laid_out());
  const VectorXd Sw = p.sampling.S * x.part_w;
  const PlateField field(p, x.part_w);
  int points = 0;
  for (int q = 0; q < p.sampling.size(); ++q) {
    const int k = q - p.sampling.edge_begin;
    if (k >= 0 && !p.sampling.rim_rows[k].point()) continue;  // a spline average: no one point
    EXPECT_NEAR(Sw[q], field.at(p.sampling.x[q], p.sampling.y[q]).w, 1e-13) << q;
    points += k >= 0;
  }
  EXPECT_GT(points, 0);
}

// ---- (D33): the kink across a convex polygon's sides ----

namespace {
// A square whose sides, knots (4 cells apart) and cut-off lines (1.5 and 2.5 cells out) all lie on
// the lines of half cells on n = 64, so that a tensor Gauss rule on half cells meets no break; not
// on grid lines, where the plain space carries the kink and (D33) adds nothing.
const EdgeCurve kAlignedSquare = parse_edge("polygon:0.3828125,0.3828125;0.6328125,0.3828125;0.6328125,0.6328125;0.3828125,0.6328125");
// The hard cases' acute triangle, stated clockwise (the enrichment orders it itself).
const EdgeCurve kTriangle = parse_edge("polygon:0.3,0.5;0.8,0.45;0.3,0.3");

// The function of e with the largest coupling to any grid unknown, and that unknown.
std::pair<int, int> strongest(const KinkBlocks& b, int N, int functions) {
  std::pair<int, int> best{-1, -1};
  double largest = 0;
  for (int k = 0; k < functions; ++k)
    for (SpMat::InnerIterator it(b.border, N + k); it; ++it)
      if (it.row() < N && std::abs(it.value()) > largest) largest = std::abs(it.value()), best = {k, static_cast<int>(it.row())};
  return best;
}
}  // namespace

// Where every break of the integrand lies on a line of half cells, 15 Gauss points a direction on
// each half cell integrate (D33)'s polynomials exactly (degree at most 28 in each variable), and
// so, if the derivation holds, does cell_rule: the two agree to round-off, entry by entry.
TEST(SideKinks, BlocksAreExactWhereATensorRuleIsToo) {
  const Grid g = make_grid(64);
  const KinkEnrichment e = make_side_kinks(g, kAlignedSquare);
  const SpMat P = kink_interpolant(g, e);
  const KinkBlocks blocks = assemble_kink_blocks(g, e, P, [](double, double) { return 1.0; });
  const int N = g.unknowns();
  // The sides' splines only: a corner's r^2 log r (D34) is no polynomial (the next test).
  const int splines = e.corners.front().index;
  ASSERT_EQ(splines, 4 * 7);
  const auto [k, dof] = strongest(blocks, N, splines);
  ASSERT_GE(k, 0);
  for (int kk : {k, 0}) {  // the strongest and the first vertex's first spline, which runs past the corner
    int d = dof;
    if (kk != k) {
      double largest = 0;
      for (SpMat::InnerIterator it(blocks.border, N + kk); it; ++it)
        if (it.row() < N && std::abs(it.value()) > largest) largest = std::abs(it.value()), d = static_cast<int>(it.row());
    }
    const Brute exact = brute(g, e, P, kk, d, 2, 15);
    EXPECT_NEAR(blocks.border.coeff(d, N + kk), exact.b, 1e-12 * std::abs(exact.b)) << kk;
    EXPECT_NEAR(blocks.border.coeff(N + kk, N + kk), exact.e, 1e-12 * std::abs(exact.e)) << kk;
    EXPECT_NEAR(blocks.load[kk], exact.load, 1e-12 * std::abs(exact.load)) << kk;
    EXPECT_GT(std::abs(exact.e), 0);
  }
}

// A corner's function (D34) carries a logarithm at the corner, which the graded rule meets at its
// apex: its blocks lie within the tensor rule's own error, which shows from 4 x 4 to 8 x 8 sub-squares
// of 15 x 15 points (the corner and every other break on their lines, the boxes made so).
TEST(SideKinks, CornerBlocksMatchABruteForceQuadrature) {
  const Grid g = make_grid(64);
  KinkEnrichment e = make_side_kinks(g, kAlignedSquare);
  for (KinkCorner& V : e.corners) V.inner = 2 * g.h, V.outer = 4 * g.h;  // boxes on the half cells' lines too
  const SpMat P = kink_interpolant(g, e);
  const KinkBlocks blocks = assemble_kink_blocks(g, e, P, [](double, double) { return 1.0; });
  const int N = g.unknowns(), k = e.function_of_spline[e.corners[1].index];
  const int dof = strongest_dof(blocks, N, k);
  ASSERT_GE(dof, 0);
  // (Lap psi, Lap psi) has log^2 at the corner, which sub-squares close on slowly (a third of the
  // error a halving); the other two to 1e-6.
  const double resolved[3] = {1e-6, 1e-4, 1e-6};
  expect_within_brute(blocks, N, k, dof, brute(g, e, P, k, dof, 4, 15), brute(g, e, P, k, dof, 8, 15), 1e-12, resolved);
}

// On a triangle whose sides cut the squares anyhow, the blocks agree with the brute-force rule
// within that rule's own error (8 x 8 to 16 x 16 sub-squares), as (D31)'s do.
TEST(SideKinks, BlocksMatchABruteForceQuadratureOnATriangle) {
  const Grid g = make_grid(64);
  const KinkEnrichment e = make_side_kinks(g, kTriangle);
  const SpMat P = kink_interpolant(g, e);
  const KinkBlocks blocks = assemble_kink_blocks(g, e, P, [](double, double) { return 1.0; });
  const int N = g.unknowns();
  const auto [k, dof] = strongest(blocks, N, e.corners.front().index);  // a side's: the corners' have the test above
  ASSERT_GE(k, 0);
  const double resolved[3] = {0.01, 0.01, 0.01};
  expect_within_brute(blocks, N, k, dof, brute(g, e, P, k, dof, 8), brute(g, e, P, k, dof, 16), 1e-13, resolved);
}

// psi vanishes with its slopes and twist at every node; it is C^1 across cell sides; and across each
// side of the triangle its third normal derivative jumps by 6 sum_j c_j B_j(s) / h^3, the kink of
// (D33), read off by one-sided differences at points along the side.
TEST(SideKinks, VanishAtNodesAreC1AndCarryTheJump) {
  const Grid g = make_grid(64);
  const KinkEnrichment e = make_side_kinks(g, kTriangle);
  ASSERT_EQ(e.sides.size(), 3u);
  const SpMat P = kink_interpolant(g, e);
  VectorXd c(e.size());
  for (int k = 0; k < e.size(); ++k) c[k] = (1 + 0.5 * std::sin(0.7 * k)) * std::pow(e.unit, 3);
  const VectorXd Pc = P * c;
  const NodeScan scan = scan_nodes(g, e, c, Pc);
  EXPECT_GT(scan.size, 1e-3);
  EXPECT_LT(scan.at_nodes, 1e-12 * scan.size);
  expect_c1_across(g, e, c, Pc, g.x(52), {0.43, 0.45, 0.47});  // a cell side across the band near the acute corner
  for (const KinkSide& q : e.sides)
    for (double frac : {0.3, 0.55}) {
      const double s = frac * q.length, px = q.x0 + s * q.tx, py = q.y0 + s * q.ty, step = 2e-5;
      auto w = [&](double dd) { return field(g, e, c, Pc, px + dd * q.nx, py + dd * q.ny).w; };
      auto third = [&](double side) { return side * (w(3 * side * step) - 3 * w(2 * side * step) + 3 * w(side * step) - w(0)) / (step * step * step); };
      double jump = 0;  // 6 sum_j c_j B_j(s): F's third derivative just outside, over d^3
      for (int k = 0; k < e.size(); ++k) jump += 6 * c[k] * kink_profile(e, k, px + 1e-4 * q.nx, py + 1e-4 * q.ny).w / std::pow(1e-4, 3);
      EXPECT_GT(std::abs(jump), 1e-2);
      EXPECT_NEAR(third(1) - third(-1), jump, 0.01 * std::abs(jump)) << q.x0 << "," << q.y0 << " at " << frac;
    }
}

// (D33) needs a convex polygon with sides of at least two cells and room to the clamped edges, and
// says which it lacks; --enrich sides turns that into an error, auto into the plain space.
TEST(SideKinks, RefuseWhatTheyDoNotFitAndSayWhy) {
  const Grid g = make_grid(64);
  EXPECT_EQ(kink_misfit(g, kTriangle), "");
  EXPECT_NE(kink_misfit(g, parse_edge("polygon:0.3,0.3;0.7,0.3;0.5,0.45;0.7,0.7;0.3,0.7")).find("convex"), std::string::npos);
  EXPECT_NE(kink_misfit(g, parse_edge("polygon:0.3,0.3;0.7,0.3;0.7,0.32;0.3,0.33")).find("2 cells long"), std::string::npos);
  EXPECT_NE(kink_misfit(g, parse_edge("polygon:0.05,0.3;0.7,0.3;0.7,0.7;0.05,0.7")).find("clamped edge"), std::string::npos);
  const KinkEnrichment on_lines = make_side_kinks(g, parse_edge("polygon:0.375,0.375;0.625,0.375;0.625,0.625;0.375,0.625"));
  EXPECT_EQ(on_lines.sides.size(), 0u);  // every side on a grid line: the corners' functions alone
  EXPECT_EQ(on_lines.corners.size(), 4u);
  EXPECT_EQ(make_side_kinks(g, parse_edge("polygon:0.375,0.375;0.625,0.375;0.5,0.6")).sides.size(), 2u);  // the base on y = 24 h
  EXPECT_THROW(make_side_kinks(make_grid(16), kTriangle), std::invalid_argument);
  EXPECT_FALSE(kink_fits(make_grid(16), kTriangle));
  // A vertex on the line through its neighbours is no corner, and its two sides would bring the same
  // splines twice: it is left out. A pentagram turns left at every vertex, but twice round.
  const KinkEnrichment straight = make_side_kinks(g, parse_edge("polygon:0.3,0.3;0.5,0.3;0.7,0.3;0.7,0.7;0.3,0.7"));
  EXPECT_EQ(straight.sides.size(), 4u);
  EXPECT_EQ(straight.corners.size(), 4u);
  std::string star = "polygon:";
  for (int k = 0; k < 5; ++k)
    star += (k ? ";" : "") + std::to_string(0.5 + 0.2 * std::cos(4 * M_PI * k / 5)) + "," + std::to_string(0.5 + 0.2 * std::sin(4 * M_PI * k / 5));
  EXPECT_NE(kink_misfit(g, parse_edge(star)).find("convex"), std::string::npos) << star;
}

// A symmetric square pressed onto by the plate, solved with (D33) on its quarter and on the whole
// plate: the mirror images of the functions must pair up (one function per orbit on the quarter),
// or the two answers differ.
TEST(SideKinks, TheQuarterSolvesTheWholePlatesProblem) {
  Scene s = Scene::rectangle(1, 1).over("(x>=0.3 && x<=0.7 && y>=0.3 && y<=0.7) ? 0 : -inf", parse_edge("polygon:0.3,0.3;0.7,0.3;0.7,0.7;0.3,0.7")).loaded(-1);
  SamplingSpec spec{SamplingKind::Edge};
  spec.enrich.kind = EnrichSpec::Kind::Sides;
  const SceneSolution part = solve_exact_scene(s, 64, spec, ExactOptions{}, true), whole = solve_exact_scene(s, 64, spec, ExactOptions{}, false);
  ASSERT_TRUE(part.solved.kink && whole.solved.kink && part.solved.grid.is_part() && !whole.solved.grid.is_part());
  // One function per orbit of the quarter's mirrors: at most four splines each, and fewer on the lines.
  EXPECT_LT(part.solved.kink->size(), whole.solved.kink->size());
  EXPECT_GE(4 * part.solved.kink->size(), whole.solved.kink->size());
  ASSERT_TRUE(part.result.converged && whole.result.converged);
  const double fp = part.result.lambda.sum(), fw = whole.result.lambda.sum();
  const double size = whole.result.w.head(whole.solved.grid.unknowns()).cwiseAbs().maxCoeff();
  EXPECT_LT((part.result.w - whole.result.w).cwiseAbs().maxCoeff(), 1e-10 * size);
  EXPECT_NEAR(fp, fw, 1e-10 * std::abs(fw));
  const SceneSolution plain = solve_exact_scene(s, 64, SamplingSpec{SamplingKind::Edge}, ExactOptions{}, true);
  const int N = plain.solved.grid.unknowns();
  EXPECT_GT((plain.result.w - part.result.w.head(N)).cwiseAbs().maxCoeff(), 1e-6 * size);  // the functions do something
}

// The square that lifts the plate holds it at its four corners alone: point loads, whose r^2 log r no
// bicubic follows. With the corners' functions (D34) the force converges at order four or so from
// n = 64 to 256, where the plain space's steps do not shrink at all; the force of each is measured
// against itself, grid against grid (no series solves a polygon).
TEST(SideKinks, CornerFunctionsRestoreTheOrderWhereThePlateRestsOnCorners) {
  const Scene s = Scene::rectangle(1, 1).over("(x>=0.3 && x<=0.7 && y>=0.3 && y<=0.7) ? 0.0625 : -inf",
                                              parse_edge("polygon:0.3,0.3;0.7,0.3;0.7,0.7;0.3,0.7"));
  std::vector<double> kink, plain;
  for (int n : {64, 128, 256}) {
    SamplingSpec spec{SamplingKind::Edge};
    spec.enrich.kind = EnrichSpec::Kind::Sides;
    const SceneSolution x = solve_exact_scene(s, n, spec, ExactOptions{});
    ASSERT_TRUE(x.solved.kink && x.result.converged) << n;
    // The plate rests on the corners alone: of the edge rows only the four at the vertices carry force.
    const Sampling& rows = x.whole().sampling;
    int loaded = 0;
    for (int i = rows.edge_begin; i < rows.size(); ++i)
      if (x.result.lambda[i] > 0) {
        ++loaded;
        EXPECT_TRUE((std::abs(rows.x[i] - 0.3) < 1e-12 || std::abs(rows.x[i] - 0.7) < 1e-12) &&
                    (std::abs(rows.y[i] - 0.3) < 1e-12 || std::abs(rows.y[i] - 0.7) < 1e-12)) << rows.x[i] << ", " << rows.y[i];
      }
    EXPECT_EQ(loaded, 4) << n;
    kink.push_back(total_contact_force(x.whole(), x.result.lambda));
    const SceneSolution y = solve_exact_scene(s, n, SamplingSpec{SamplingKind::Edge}, ExactOptions{});
    ASSERT_TRUE(y.result.converged) << n;
    plain.push_back(total_contact_force(y.whole(), y.result.lambda));
  }
  const double k1 = std::abs(kink[1] - kink[0]), k2 = std::abs(kink[2] - kink[1]);
  const double p1 = std::abs(plain[1] - plain[0]), p2 = std::abs(plain[2] - plain[1]);
  EXPECT_GT(std::log2(k1 / k2), 3.5) << k1 << " then " << k2;
  EXPECT_LT(std::log2(p1 / p2), 1) << p1 << " then " << p2;  // the plain space: no order to speak of
  EXPECT_LT(k2, 1e-3 * p2);
}

// The derivatives kink_field returns are those of its values: first derivatives against central
// differences of w, second against central differences of the first, at points in a corner's box
// (near the corner, and where its cut-off varies) and in a side's band, with every function of the
// triangle at once.
TEST(SideKinks, FieldDerivativesAreThoseOfItsValues) {
  const Grid g = make_grid(64);
  const KinkEnrichment e = make_side_kinks(g, kTriangle);
  const SpMat P = kink_interpolant(g, e);
  VectorXd c(e.size());
  for (int k = 0; k < e.size(); ++k) c[k] = 1 + 0.5 * std::sin(1.3 * k);
  const VectorXd Pc = P * c;
  // A step small against a cell, for the truncation (d^2 f'''), and large against round-off: F and
  // its interpolant are of order ten where their difference is 1e-12.
  const double d = 1e-4 * g.h;
  int checked = 0;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {0.8 + 0.37 * g.h, 0.45 + 0.21 * g.h}, {0.3 - 1.3 * g.h, 0.3 + 0.6 * g.h}, {0.55 + 0.3 * g.h, 0.375 - 1.7 * g.h},
           {0.3 - 2.1 * g.h, 0.4 + 0.45 * g.h}, {0.78 - 0.4 * g.h, 0.47 + 2.2 * g.h},
           // across the corner (0.3, 0.3)'s box, where its cut-off varies in x, in y, or in both
           {0.3 + 2.5 * g.h, 0.3 + 2.7 * g.h}, {0.3 - 2.6 * g.h, 0.3 + 0.5 * g.h}, {0.3 + 0.4 * g.h, 0.3 - 2.3 * g.h}}) {
    const KinkValue v = field(g, e, c, Pc, x, y);
    const KinkValue xp = field(g, e, c, Pc, x + d, y), xm = field(g, e, c, Pc, x - d, y);
    const KinkValue yp = field(g, e, c, Pc, x, y + d), ym = field(g, e, c, Pc, x, y - d);
    const double size1 = std::abs(v.wx) + std::abs(v.wy) + 1e-3, size2 = std::abs(v.wxx) + std::abs(v.wyy) + std::abs(v.wxy) + 1;
    EXPECT_NEAR((xp.w - xm.w) / (2 * d), v.wx, 1e-5 * size1) << x << ", " << y;
    EXPECT_NEAR((yp.w - ym.w) / (2 * d), v.wy, 1e-5 * size1) << x << ", " << y;
    EXPECT_NEAR((xp.wx - xm.wx) / (2 * d), v.wxx, 1e-5 * size2) << x << ", " << y;
    EXPECT_NEAR((yp.wy - ym.wy) / (2 * d), v.wyy, 1e-5 * size2) << x << ", " << y;
    EXPECT_NEAR((yp.wx - ym.wx) / (2 * d), v.wxy, 1e-5 * size2) << x << ", " << y;
    EXPECT_NEAR((xp.wy - xm.wy) / (2 * d), v.wxy, 1e-5 * size2) << x << ", " << y;
    checked += size2 > 10;
  }
  EXPECT_GE(checked, 4);  // the points see the functions, not zeros
}

// A unit point load at a corner that is a node: the plate is r^2 log r / (8 pi) about it plus a smooth
// field, so the corner's function, h^2 rho^2 log rho less its interpolant, must take the coefficient
// h^2 / (8 pi), the fundamental solution's, and the other corners almost none. (The square's sides lie
// on grid lines, so the corners' functions are the whole enrichment.)
TEST(SideKinks, ACornersFunctionTakesThePointLoadsFundamentalSolution) {
  for (int n : {32, 64}) {
    const Grid g = make_grid(n);
    const KinkEnrichment e = make_side_kinks(g, parse_edge("polygon:0.25,0.25;0.75,0.25;0.75,0.75;0.25,0.75"));
    ASSERT_TRUE(e.sides.empty());
    const SpMat P = kink_interpolant(g, e);
    SpMat K = assemble_matrix(g, bfs_stiffness(g.h));
    const int N = g.unknowns();
    K.conservativeResize(N + e.size(), N + e.size());
    K += assemble_kink_blocks(g, e, P, [](double, double) { return 0.0; }).border;
    VectorXd load = VectorXd::Zero(N + e.size());
    load[g.dof(n / 4, n / 4, 0)] = 1;  // at (0.25, 0.25); every function of the enrichment is 0 there
    const Eigen::SimplicialLDLT<SpMat> solver(K);
    ASSERT_EQ(solver.info(), Eigen::Success);
    const VectorXd x = solver.solve(load);
    const double fundamental = g.h * g.h / (8 * M_PI);
    int at = -1;
    for (const KinkCorner& V : e.corners)
      if (std::abs(V.x - 0.25) < 1e-12 && std::abs(V.y - 0.25) < 1e-12) at = e.function_of_spline[V.index];
    ASSERT_GE(at, 0);
    EXPECT_NEAR(x[N + at], fundamental, 2e-3 * fundamental) << n;
    for (int k = 0; k < e.size(); ++k)
      if (k != at) {
        EXPECT_LT(std::abs(x[N + k]), 1e-3 * fundamental) << n << " " << k;
      }
  }
}

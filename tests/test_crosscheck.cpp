// The cross-code check in small: FreeFEM (HCT on gmsh meshes with vertices on the contact circle)
// and this code (BFS on squares, edge sampling), both exact, must agree on the paper's problem
// within the tolerance their own steady orders justify; FreeFEM must reproduce the disk's closed
// form and the clamped square's published centre deflection. The report's grids less the coarsest
// (the disk: its four coarsest meshes): about half a minute.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "active_set.hpp"
#include "msh.hpp"
#include "crosscheck.hpp"
#include "disk_punch.hpp"
#include "freefem.hpp"
#include "line_force.hpp"
#include "scratch.hpp"
#include "paper_case.hpp"
#include "run_program.hpp"

using namespace plate;

namespace {
const std::string kRef = std::string(PLATE_SOURCE_DIR) + "/reference";
const std::string kEdp = kRef + "/contact_hct.edp";

// FreeFEM's and gmsh's files, removed when the test's process ends.
std::string work_dir() {
  static const Scratch scratch("crosscheck");
  return scratch.dir().string();
}

// FreeFEM on levels n of a .geo (4 n cells per quarter circle), the paper's obstacle.
std::vector<CheckValues> freefem_runs(const std::string& geo, const std::vector<int>& levels,
                                      const std::vector<std::pair<double, double>>& points, const std::string& extra = "",
                                      double disk_radius = 0) {
  const Scene s = paper_scene();
  const std::string dir = work_dir(), pts = dir + "/points.txt";
  write_points(pts, points);
  std::vector<CheckValues> runs;
  for (int n : levels) {
    const std::string msh = dir + "/" + std::filesystem::path(geo).stem().string() + std::to_string(n) + ".msh";
    auto numbers = circle_numbers(s, n);
    if (disk_radius > 0) numbers.push_back({"a", disk_radius});
    gmsh_mesh(kRef + "/" + geo, numbers, msh);
    const std::string args = scene_args(s, pts) + " " + extra;
    runs.push_back(freefem_values(run_freefem(kEdp, msh, args, msh + ".json"), 4 * n, s.cylinder->radius));
    EXPECT_TRUE(runs.back().certified) << geo << ", n = " << n;
  }
  return runs;
}

std::vector<std::pair<double, double>> check_points() {
  std::vector<std::pair<double, double>> p;
  for (const CheckPoint& c : kCheckPoints) p.push_back({c.x, c.y});
  return p;
}

Extrapolation fit_freefem(const std::vector<CheckValues>& runs, const std::vector<double>& v) {
  std::vector<double> z;
  for (size_t k = 0; k < runs.size(); ++k) z.push_back(freefem_roundoff(runs[k].h, v[k]));
  return extrapolate(v, z);
}
Extrapolation fit_ours(const std::vector<CheckValues>& runs, const std::vector<double>& v) {
  std::vector<double> z;
  for (size_t k = 0; k < runs.size(); ++k) z.push_back(exact_solve_roundoff(runs[k].cells, v[k]));
  return extrapolate(v, z);
}
}  // namespace

TEST(CrossCode, FreeFemAndThisCodeAgreeOnThePapersSquareToTheTargets) {
  const Scene s = paper_scene();
  const auto ff = freefem_runs("square_with_circle.geo", {2, 4, 8, 16}, check_points());
  std::vector<CheckValues> ours;
  for (int n : {64, 128, 256, 512}) {
    ours.push_back(solve_ours(s, n, SamplingSpec{SamplingKind::Edge}));
    ASSERT_TRUE(ours.back().certified) << "n = " << n;
  }
  const struct {
    const char* name;
    double CheckValues::*field;
    double target;
  } quantities[] = {{"max w", &CheckValues::max_w, 1e-6}, {"total contact force", &CheckValues::force, 1e-5}};
  for (const auto& q : quantities) {
    const Extrapolation a = fit_freefem(ff, values_of(ff, q.field)), b = fit_ours(ours, values_of(ours, q.field));
    const Agreement g = compare_limits(a, b);
    std::printf("  %-20s FreeFEM %.10g +- %.1e  BFS %.10g +- %.1e  difference %.1e  tolerance %.1e\n", q.name, a.limit,
                a.bar, b.limit, b.bar, g.difference, g.tolerance);
    EXPECT_TRUE(a.steady) << q.name << ": FreeFEM's order is not steady";
    EXPECT_TRUE(b.steady) << q.name << ": our order is not steady";
    EXPECT_TRUE(g.agree) << q.name;
    EXPECT_LE(g.tolerance, q.target * std::abs(b.limit)) << q.name << ": the tolerance misses the target";
  }
  // The point between the circle and the edge, where neither code holds w: agreement, no target,
  // but a tolerance that says something.
  const Extrapolation a = fit_freefem(ff, values_at(ff, 1)), b = fit_ours(ours, values_at(ours, 1));
  const Agreement g = compare_limits(a, b);
  EXPECT_TRUE(g.agree) << kCheckPoints[1].name;
  EXPECT_LT(g.tolerance, 1e-5 * std::abs(b.limit)) << kCheckPoints[1].name;
}

TEST(CrossCode, FreeFemReproducesTheDiskOnAFlatPunch) {
  const Scene s = paper_scene();
  const DiskPunch exact{0.5, s.cylinder->radius, s.cylinder->height};
  const auto ff = freefem_runs("disk_with_punch.geo", {1, 2, 4, 8}, {{s.cylinder->cx, s.cylinder->cy}}, "", exact.a);
  const Extrapolation w = fit_freefem(ff, values_at(ff, 0)), f = fit_freefem(ff, values_of(ff, &CheckValues::force));
  std::printf("  w(0): FreeFEM %.9g +- %.1e, closed form %.9g; force: FreeFEM %.7g +- %.1e, closed form %.7g\n", w.limit,
              w.bar, exact.centre(), f.limit, f.bar, exact.total_force());
  for (const auto* e : {&w, &f}) {
    EXPECT_TRUE(e->steady);
    EXPECT_NEAR(e->orders.back(), 2, 0.3);  // the polygonal clamped edge
  }
  EXPECT_NEAR(w.limit, exact.centre(), w.bar);
  EXPECT_NEAR(f.limit, exact.total_force(), f.bar);
  EXPECT_LT(w.bar, 1e-3 * exact.centre());  // and the bars are not vacuous
  EXPECT_LT(f.bar, 1e-3 * exact.total_force());
}

TEST(CrossCode, FreeFemReproducesTheClampedSquareUnderUniformLoad) {
  const auto ff = freefem_runs("square_with_circle.geo", {2, 4}, {{0.5, 0.5}}, "-obstacle none -load 1");
  const double published = plate_constant("uniform_centre"), w0 = ff[0].w_at.at(0), w1 = ff[1].w_at.at(0);
  std::printf("  FreeFEM HCT: w(0.5, 0.5) = %.9f, %.9f; published %g\n", w0, w1, published);
  // Within its discretisation error (the last increment) plus the published value's rounding.
  EXPECT_NEAR(w1, published, std::abs(w1 - w0) + 5e-9);
  EXPECT_LT(std::abs(w1 - w0), 1e-3 * published);  // and that error is small
}

// The quarter mesh with mirror conditions (a penalty on the normal slope) solves the same discrete
// problem as the whole plate meshed by the quarter and its mirror images: every value agrees within
// both runs' round-off bounds (freefem.hpp), at points in all four quarters and in the line load,
// which the quarter's JSON unfolds onto the whole rim. With the penalty a hundred times weaker
// (1e10 h^-2 in contact_hct.edp) the fitted line load leaves these bounds and the test fails.
TEST(CrossCode, FreeFemOnAQuarterMeshSolvesTheWholePlate) {
  const Scene s = paper_scene();
  const std::string dir = work_dir(), pts = dir + "/quarter_points.txt";
  write_points(pts, {{0.5, 0.5}, {0.3, 0.2}, {0.8, 0.3}, {0.65, 0.9}});
  for (int n : {2, 4}) {
    const std::string q = dir + "/quarter" + std::to_string(n) + ".msh", w = dir + "/unfolded" + std::to_string(n) + ".msh";
    gmsh_mesh(kRef + "/quarter_square_with_circle.geo", circle_numbers(s, n), q);
    unfold_quarter_mesh(q, w, s.cylinder->cx, s.cylinder->cy);
    const CheckValues quarter = freefem_values(run_freefem(kEdp, q, scene_args(s, pts) + " -symmetry quarter", q + ".json"), 4 * n, s.cylinder->radius),
                      whole = freefem_values(run_freefem(kEdp, w, scene_args(s, pts), w + ".json"), 4 * n, s.cylinder->radius);
    ASSERT_TRUE(quarter.certified && whole.certified) << "n = " << n;
    const auto near = [&](double a, double b, double scale, const char* what) {
      EXPECT_NEAR(a, b, 2 * freefem_roundoff(whole.h, scale)) << what << ", n = " << n;
    };
    near(whole.max_w, quarter.max_w, whole.max_w, "max w");
    near(whole.force, quarter.force, whole.force, "force");
    // The fitted line load's round-off is that of its largest point forces.
    near(whole.q0, quarter.q0, whole.line.max, "q(0)");
    near(whole.q45, quarter.q45, whole.line.max, "q(pi/4)");
    for (size_t k = 0; k < whole.w_at.size(); ++k) near(whole.w_at[k], quarter.w_at[k], whole.max_w, "w at a point");
    EXPECT_EQ(whole.line.theta.size(), quarter.line.theta.size()) << "the rim unfolded, n = " << n;
    EXPECT_LT(3 * quarter.unknowns, whole.unknowns);
  }
  // A mesh with no mirror lines, or with one, is refused, and the quarter's .geo has no circle off the
  // plate's centre.
  const std::string msh = dir + "/whole_for_quarter.msh";
  gmsh_mesh(kRef + "/square_with_circle.geo", {{"n", 1}}, msh);
  const Captured run = run_captured("FF_LOADPATH=/usr/lib/freefem++ FreeFem++ -nw -v 0 '" + kEdp + "' -mesh '" + msh +
                                    "' -points '" + pts + "' -symmetry quarter -out /dev/null 2>&1");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("-symmetry quarter"), std::string::npos) << run.output;
  const std::string quarter = dir + "/quarter_for_half.msh", half = dir + "/half.msh";
  gmsh_mesh(kRef + "/quarter_square_with_circle.geo", circle_numbers(s, 1), quarter);
  unfold_quarter_mesh(quarter, half, s.cylinder->cx, s.cylinder->cy, true);
  const Captured half_run = run_captured("FF_LOADPATH=/usr/lib/freefem++ FreeFem++ -nw -v 0 '" + kEdp + "' -mesh '" + half +
                                         "' -points '" + pts + "' -symmetry quarter -out /dev/null 2>&1");
  EXPECT_EQ(half_run.status, 2) << half_run.output;
  EXPECT_THROW(gmsh_mesh(kRef + "/quarter_square_with_circle.geo", {{"n", 1}, {"cx", 0.4}}, dir + "/off.msh"), std::runtime_error);
}

TEST(CrossCode, PointForcesOnTheCircleGiveTheLineLoad) {
  // q(theta) = 3 + cos(4 theta) at 64 equally spaced points, as point forces q times the arc each.
  const double r = 0.25;
  const int m = 64;
  std::vector<double> theta, force;
  for (int k = 0; k < m; ++k) {
    theta.push_back(-M_PI + 2 * M_PI * k / m);
    force.push_back((3 + std::cos(4 * theta.back())) * 2 * M_PI * r / m);
  }
  const LineForce f = line_force_from_point_forces(theta, force, r);
  EXPECT_NEAR(f.total, 3 * 2 * M_PI * r, 1e-12);
  EXPECT_NEAR(f.mean, 3, 1e-12);
  EXPECT_NEAR(line_force_fit(f, 0), 4, 1e-12);
  EXPECT_NEAR(line_force_fit(f, M_PI / 4), 2, 1e-12);
  EXPECT_THROW(line_force_from_point_forces({0.0, 0.0}, {1.0, 1.0}, r), std::invalid_argument);
}

TEST(CrossCode, GridsThatDoNotHalveAreRefusedByName) {
  for (const std::string& args : {std::string("--n 16,48,64"), std::string("--ff-n 1,2"), std::string("--disk-n 0,1,2")}) {
    const Captured run = run_captured("cd '" PLATE_SOURCE_DIR "' && '" BUILD_DIR "/crosscheck' " + args + " --out /nonexistent 2>&1");
    EXPECT_EQ(run.status, 2) << args << ": " << run.output;
    EXPECT_NE(run.output.find(args.substr(0, args.find(' '))), std::string::npos) << run.output;
  }
}

TEST(CrossCode, TheFreeFemScriptRefusesBadArgumentsByName) {
  const std::string dir = work_dir(), msh = dir + "/bad.msh", pts = dir + "/bad_points.txt";
  gmsh_mesh(kRef + "/square_with_circle.geo", {{"n", 1}}, msh);
  write_points(pts, {{0.5, 0.5}});
  {
    std::ofstream short_file(dir + "/short_points.txt");
    short_file << "3\n0.5 0.5\n";
  }
  const std::string ff = "FF_LOADPATH=/usr/lib/freefem++ FreeFem++ -nw -v 0 '" + kEdp + "' -mesh '" + msh + "' ";
  for (const auto& [args, name] : {std::pair{std::string("-points '" + pts + "' -radius 0.3"), std::string("-radius")},
                                   {"-points '" + pts + "' -R 1e400", "finite"}}) {
    const Captured run = run_captured(ff + args + " -out /dev/null 2>&1");
    EXPECT_EQ(run.status, 2) << args << ": " << run.output;
    EXPECT_NE(run.output.find(name), std::string::npos) << args << ": " << run.output;
  }
  // A points file shorter than its count stops FreeFem++ itself, in its read (exit 8), before the
  // script's own check can speak; either way the run fails and names the file read.
  const Captured run = run_captured(ff + "-points '" + dir + "/short_points.txt' -out /dev/null 2>&1");
  EXPECT_NE(run.status, 0) << run.output;
  EXPECT_TRUE(run.output.find("not good") != std::string::npos || run.output.find("fewer points") != std::string::npos)
      << run.output;
}

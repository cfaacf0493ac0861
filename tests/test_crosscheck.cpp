// The cross-code check in small: FreeFEM (HCT on gmsh meshes) and this code (BFS on squares) must
// agree on the paper's problem within the tolerance their own convergence justifies, and FreeFEM
// must reproduce the clamped square's centre deflection. Coarse meshes: well under a minute.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "crosscheck.hpp"
#include "freefem.hpp"
#include "paper_case.hpp"

using namespace plate;

namespace {
const std::string kGeo = std::string(PLATE_SOURCE_DIR) + "/reference/square_with_circle.geo";
const std::string kEdp = std::string(PLATE_SOURCE_DIR) + "/reference/penalty_hct.edp";

std::string work_dir() {
  const auto d = std::filesystem::temp_directory_path() / ("plate_crosscheck_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d.string();
}
}  // namespace

TEST(CrossCode, FreeFemAndThisCodeAgreeOnThePapersProblem) {
  const std::string dir = work_dir();
  const CrossSettings s;
  std::vector<CheckValues> ff, ours;
  for (double lc : {0.1, 0.05}) {
    const std::string msh = dir + "/lc" + std::to_string(lc) + ".msh";
    gmsh_mesh(kGeo, lc, msh);
    const std::string args = "-R " + std::to_string(paper_scene().height) + " -tol 1e-6 -eps0 0.1 -epsmin 1e-14";
    ff.push_back(freefem_values(run_freefem(kEdp, msh, args, msh + ".json"), lc));
    ASSERT_TRUE(ff.back().converged) << "FreeFEM on lc = " << lc;
  }
  for (int n : {16, 32}) {
    ours.push_back(solve_ours(n, SamplingKind::Gauss, paper_scene().obstacle(), s));
    ASSERT_TRUE(ours.back().converged) << "n = " << n;
  }
  for (auto [name, field] : {std::pair{"max w", &CheckValues::max_w}, {"w(0.5, 0.25)", &CheckValues::w_rim},
                             {"total contact force", &CheckValues::force}}) {
    double diff, tol;
    const bool ok = agree(values_of(ff, field), values_of(ours, field), &diff, &tol);
    std::printf("  %-20s FreeFEM %.6g  BFS %.6g  difference %.2e  tolerance %.2e\n", name, ff.back().*field,
                ours.back().*field, diff, tol);
    EXPECT_TRUE(ok) << name;
    EXPECT_LT(tol, 0.02 * std::abs(ours.back().*field)) << name << ": the tolerance would make the check vacuous";
  }
  std::filesystem::remove_all(dir);
}

TEST(CrossCode, FreeFemReproducesTheClampedSquareUnderUniformLoad) {
  const std::string dir = work_dir();
  std::vector<double> w;
  for (double lc : {0.1, 0.05}) {
    const std::string msh = dir + "/u" + std::to_string(lc) + ".msh";
    gmsh_mesh(kGeo, lc, msh);
    w.push_back(run_freefem(kEdp, msh, "-obstacle none -load 1", msh + ".json").at("w_centre").get<double>());
  }
  const double published = plate_constant("uniform_centre");
  std::printf("  FreeFEM HCT: w(0.5, 0.5) = %.9f (lc = 0.1), %.9f (lc = 0.05); published %g\n", w[0], w[1], published);
  // Within its discretisation error (the last increment) plus the published value's rounding.
  EXPECT_NEAR(w[1], published, std::abs(w[1] - w[0]) + 5e-9);
  EXPECT_LT(std::abs(w[1] - w[0]), 1e-3 * published);  // and that error is small
  std::filesystem::remove_all(dir);
}

// The cross-code check: the paper's problem solved by this code (Bogner-Fox-Schmit on squares) and
// by an independent FreeFEM script (HCT triangles on a gmsh mesh that follows the contact circle),
// compared at check points with a tolerance taken from each code's own convergence. Running
// FreeFEM and gmsh is the programs' business (src/programs/support/freefem.*).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "assemble.hpp"
#include "sampling.hpp"

namespace plate {

// What both codes report, at the same points: the centre (0.5, 0.5), where max w is, a point on
// the contact circle (0.5, 0.25), and two points between the circle and the clamped edge.
struct CheckValues {
  std::string code, grid;  // no commas: they go into CSV columns
  double h = 0;  // cell side (ours) or gmsh mesh size lc (FreeFEM)
  int unknowns = 0;
  bool converged = false;
  int iterations = 0;
  double eps_final = 0, max_w = 0, w_rim = 0, w_mid = 0, w_diag = 0, force = 0, seconds = 0;
};
// One quantity across a sequence of grids, coarse to fine.
std::vector<double> values_of(const std::vector<CheckValues>& runs, double CheckValues::*field);

constexpr double kCheckPoints[3][2] = {{0.5, 0.25}, {0.5, 0.125}, {0.25, 0.25}};

struct CrossSettings {
  double R = NAN;  // the obstacle's height: the programs read the paper's from reference/paper_numbers.csv
  double tol = 1e-6, eps_start = 0.1, eps_min = 1e-14;
};

// Our solver: nonlinear scheme (3a), eps continuation, obstacle phi (the paper's, of height s.R); f = 0.
CheckValues solve_ours(int n, SamplingKind kind, const Field& phi, const CrossSettings& s);
// Our clamped square under f = 1: w(0.5, 0.5).
double uniform_load_centre_ours(int n);

// The verdict rule. If a sequence of grid values converges at least linearly with a factor
// <= 1/2 per halving of h, the error of its finest value is at most its last increment. The
// contact circle cuts every grid differently, so the sequences here are irregular: we bound the
// error by the larger of the last two increments, which allows one irregular step. Two codes
// agree when their finest values differ by at most the sum of those two bounds.
double last_increment(const std::vector<double>& values);
double error_bound(const std::vector<double>& values);
bool agree(const std::vector<double>& a, const std::vector<double>& b, double* difference, double* tolerance);

}  // namespace plate

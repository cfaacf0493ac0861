// The cross-code check: the paper's problem solved by this code (Bogner-Fox-Schmit on squares) and
// by an independent FreeFEM script (HCT triangles on gmsh meshes whose vertices lie on the contact
// circle), each exactly, each on a sequence of grids; each code's Richardson limit, with the error
// bar its own steady order gives, is compared with the other's. Running FreeFEM and gmsh is the
// programs' business (src/programs/support/freefem.*).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "line_force.hpp"
#include "problem.hpp"
#include "scene.hpp"
#include "richardson.hpp"

namespace plate {

// The one list of check points: the centre's value is max w; a point on the contact circle; two
// points between the circle and the clamped edge. FreeFEM is handed the same list in a file.
struct CheckPoint {
  const char* name;
  double x, y;
};
constexpr CheckPoint kCheckPoints[3] = {{"w(0.5, 0.25)", 0.5, 0.25}, {"w(0.5, 0.125)", 0.5, 0.125}, {"w(0.25, 0.25)", 0.25, 0.25}};

// What both codes report, from the exact discrete solution on one grid.
struct CheckValues {
  std::string code, grid;  // no commas: they go into CSV columns
  int cells = 0;           // ours: n squares per side; FreeFEM: cells along a quarter of the circle
  double h = 0;            // ours: 1/n; FreeFEM: the longest mesh edge
  int unknowns = 0;
  bool certified = false;  // the solver's certificate of the discrete answer holds
  int iterations = 0;      // active-set iterations
  double max_w = 0, force = 0;
  std::vector<double> w_at;  // at the check points, in order
  // Ours: the round-off estimates of max w and of w at the check points (roundoff.hpp); empty for FreeFEM.
  std::vector<double> noise_w;  // max w first, then the check points
  // Ours, when the solve was refined (D22): the relative size of the forces' last correction, the
  // floor to which they are the same on every machine; NaN otherwise (then u n^3 is assumed).
  double force_floor = NAN;
  double mean_line = 0, q0 = 0, q45 = 0;  // line load on the rim: mean, and fitted q(0), q(pi/4)
  // The line load itself: at the edge points (edge sampling), at the circle's vertices (FreeFEM), or
  // binned by angle (the other samplings; q0 and q45 stay NaN for those).
  LineForce line;
  double seconds = 0;
};
// One quantity across a sequence of grids, coarse to fine.
std::vector<double> values_of(const std::vector<CheckValues>& runs, double CheckValues::*field);
std::vector<double> values_at(const std::vector<CheckValues>& runs, int point);

// Our side: the exact discrete solution of the scene (a cylinder) on n x n squares, the constraint
// sampled as `spec` says; its line load on the cylinder's rim (binned into kRimBins arcs for
// samplings off it).
constexpr int kRimBins = 32;  // arcs of about 6 h at n = 128: a few touching samples each
CheckValues solve_ours(const Scene& s, int n, const SamplingSpec& spec);
// Our clamped square under f = 1: w(0.5, 0.5).
double uniform_load_centre_ours(int n);

// The agreement rule. Each code's limit carries its error bar: where its order is steady, the
// distance between the Richardson limits of its last two triples of grids; otherwise its last
// increment (see richardson.hpp). Neither bar is taken smaller than what round-off can change in
// it. Two codes agree when their limits differ by at most the sum of the two bars.
struct Agreement {
  double difference = 0, tolerance = 0;
  // What round-off can move in each, by the two limits' noise models: digits below them are not printed.
  double difference_noise = 0, tolerance_noise = 0;
  bool agree = false;
  bool steady = false;  // both bars come from steady orders
};
Agreement compare_limits(const Extrapolation& a, const Extrapolation& b);

double last_increment(const std::vector<double>& values);

}  // namespace plate

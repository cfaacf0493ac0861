// A scene: what a user states of the plate and nothing else. The rectangle [0, lx] x [0, ly], the
// obstacle phi and the curve where its support ends, the load f. Built once (from a program's
// options, or from reference/ for the paper's), and handed whole to the finite elements, the
// mirror lines and the rim-contact series, so that a new attribute of a scene is one new field.
#pragma once
#include <optional>
#include <string>

#include "assemble.hpp"
#include "edge.hpp"
#include "grid.hpp"

namespace plate {

// The paper's kind of obstacle, eq. (10): height R on the closed disk of radius r about (cx, cy),
// no constraint outside it.
struct Cylinder {
  double cx = 0, cy = 0, radius = 0, height = 0;
};

struct Scene {
  double lx = 1, ly = 1;
  Field obstacle, load;
  EdgeCurve edge;                      // where the obstacle's support ends: the rows sit there; none: no edge rows
  std::optional<Cylinder> cylinder;    // the obstacle is this cylinder (and `edge` its rim)
  std::optional<double> uniform_load;  // the load is this constant
  std::string obstacle_text, load_text;  // as stated: for echoes and reports

  // The grid of n cells along x; throws std::invalid_argument (make_grid) if ly is not a whole
  // number of cells.
  Grid grid(int n) const { return make_grid(n, lx, ly); }
};

// The cylinder on the rectangle, under the uniform load f; its rim is the edge. Throws
// std::invalid_argument naming --centre and --radius if the disk is not inside the rectangle, and
// naming the quantity if a number is not finite (or the radius not > 0, the sides not > 0).
Scene cylinder_scene(double lx, double ly, const Cylinder& c, double load = 0);
// The same scene with the cylinder at another height (the answer scales with it).
Scene at_height(const Scene& s, double R);
// An obstacle and a load given as expressions in x, y (fields.hpp), and the obstacle's edge if it
// has one; a number for the load makes a uniform load. Throws std::invalid_argument naming
// --obstacle or --load for text muparser cannot read.
Scene expression_scene(double lx, double ly, const std::string& obstacle, const std::string& load, const EdgeCurve& edge = {});
// An obstacle and a load given as functions (a program's or a test's own), with no edge curve.
Scene field_scene(double lx, double ly, Field obstacle, Field load);
// The scene under another load: a number (uniform) or an expression in x, y; throws
// std::invalid_argument naming --load for text muparser cannot read.
Scene with_load(const Scene& s, const std::string& load);

}  // namespace plate

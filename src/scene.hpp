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

  // A scene is stated one attribute at a time, so that a new attribute is one new function here and
  // no signature elsewhere carries the parts side by side:
  //   Scene::rectangle(1.5, 1).over(Cylinder{0.75, 0.5, 0.25, 0.0625}).loaded(-1)
  // The rectangle [0, lx] x [0, ly], with no obstacle under it and no load; throws
  // std::invalid_argument naming --lx and --ly unless both are finite and > 0.
  static Scene rectangle(double lx, double ly);
  // The plate over the cylinder, its rim the edge. Throws std::invalid_argument naming --centre and
  // --radius if the disk is not inside the rectangle, and naming the quantity if a number is not
  // finite (or the radius not > 0).
  Scene over(const Cylinder& c) const;
  // Over an obstacle given as an expression in x, y (fields.hpp), with the edge of its support if it
  // has one; throws std::invalid_argument naming --obstacle for text muparser cannot read.
  Scene over(const std::string& expression, const EdgeCurve& edge = {}) const;
  // Over an obstacle given as a function (a program's or a test's own), with no edge curve.
  Scene over(Field obstacle) const;
  // Under the uniform load f; throws std::invalid_argument naming --load if f is not finite.
  Scene loaded(double f) const;
  // Under a load given as a number (uniform) or an expression in x, y; throws
  // std::invalid_argument naming --load for text muparser cannot read.
  Scene loaded(const std::string& load) const;
  // Under a load given as a function.
  Scene loaded(Field load) const;

  // The grid of n cells along x; throws std::invalid_argument (make_grid) if ly is not a whole
  // number of cells.
  Grid grid(int n) const { return make_grid(n, lx, ly); }
};

// The same scene with the cylinder at another height (the answer scales with it).
Scene at_height(const Scene& s, double R);

}  // namespace plate

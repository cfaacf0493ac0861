// The obstacle's edge: the curve where its support ends, and points on it with arc-length weights.
// The paper's cylinder touches the plate along its rim, the circle (10); sampling that curve puts
// constraint points where the contact force lives, instead of beside it.
#pragma once
#include <string>
#include <vector>

namespace plate {

struct EdgeCurve {
  enum class Kind { None, Circle, Polygon };
  Kind kind = Kind::None;
  double cx = 0, cy = 0, r = 0;                 // Circle
  std::vector<double> vx, vy;                   // Polygon vertices, in order; the last joins the first
  bool empty() const { return kind == Kind::None; }
};

EdgeCurve circle_edge(double cx, double cy, double r);

// "none", "circle:cx,cy,r" or "polygon:x1,y1;x2,y2;x3,y3[;...]". Throws std::invalid_argument
// naming --edge for anything else (a degenerate circle or polygon included).
EdgeCurve parse_edge(const std::string& text);

// Points on the curve, each with the length of curve it stands for (the weights sum to the
// length) and the unit normal pointing into the enclosed region.
struct EdgePoints {
  std::vector<double> x, y, weight, nx, ny;
  std::vector<double> theta;  // circle only: the angle of each point about the centre
  double length = 0;
  int size() const { return static_cast<int>(x.size()); }
};

// A circle gets M points at angles 2 pi k / M, with M the multiple of 8 nearest 2 pi r / h (at
// least 8): the square's eight symmetries about the circle's centre then map the set onto itself,
// and theta = 0 and pi/4 are among the points. A polygon gets points about h apart on each side,
// its vertices included.
EdgePoints edge_points(const EdgeCurve& e, double h);

// Distance from (x, y) to the curve (infinity when there is none).
double distance_to_edge(const EdgeCurve& e, double x, double y);

}  // namespace plate

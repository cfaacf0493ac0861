// Edge curves and their sample points.
#include "edge.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace plate {

EdgeCurve circle_edge(double cx, double cy, double r) {
  if (!(std::isfinite(cx) && std::isfinite(cy) && std::isfinite(r) && r > 0))
    throw std::invalid_argument("--edge circle needs a finite centre and a radius > 0");
  EdgeCurve e;
  e.kind = EdgeCurve::Kind::Circle;
  e.cx = cx, e.cy = cy, e.r = r;
  return e;
}

namespace {
std::vector<double> numbers(const std::string& text, char sep) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string field;
  while (std::getline(ss, field, sep)) {
    char* end = nullptr;
    const double d = std::strtod(field.c_str(), &end);
    if (field.empty() || *end != '\0' || !std::isfinite(d)) throw std::invalid_argument("not a finite number: '" + field + "'");
    v.push_back(d);
  }
  return v;
}

double signed_area(const EdgeCurve& e) {
  double a = 0;
  const size_t m = e.vx.size();
  for (size_t i = 0; i < m; ++i) a += e.vx[i] * e.vy[(i + 1) % m] - e.vx[(i + 1) % m] * e.vy[i];
  return 0.5 * a;
}

EdgeCurve parse_polygon(const std::string& body) {
  EdgeCurve e;
  e.kind = EdgeCurve::Kind::Polygon;
  std::stringstream ss(body);
  std::string vertex;
  while (std::getline(ss, vertex, ';')) {
    const auto xy = numbers(vertex, ',');
    if (xy.size() != 2) throw std::invalid_argument("a vertex is 'x,y', got '" + vertex + "'");
    e.vx.push_back(xy[0]);
    e.vy.push_back(xy[1]);
  }
  if (e.vx.size() < 3) throw std::invalid_argument("a polygon needs at least 3 vertices");
  if (std::abs(signed_area(e)) == 0) throw std::invalid_argument("the polygon encloses no area");
  return e;
}
}  // namespace

EdgeCurve parse_edge(const std::string& text) {
  try {
    if (text == "none") return {};
    if (text.rfind("circle:", 0) == 0) {
      const auto v = numbers(text.substr(7), ',');
      if (v.size() != 3) throw std::invalid_argument("a circle is 'circle:cx,cy,r'");
      return circle_edge(v[0], v[1], v[2]);
    }
    if (text.rfind("polygon:", 0) == 0) return parse_polygon(text.substr(8));
    throw std::invalid_argument("expected none, circle:cx,cy,r or polygon:x1,y1;x2,y2;...");
  } catch (const std::invalid_argument& err) {
    throw std::invalid_argument("--edge '" + text + "' is not valid: " + err.what());
  }
}

namespace {
// @region edge-points-circle
EdgePoints circle_points(const EdgeCurve& e, double h) {
  const double length = 2 * M_PI * e.r;
  const int M = 8 * (1 << std::max(0, static_cast<int>(std::lround(std::log2(length / (8 * h))))));
  EdgePoints p;
  p.length = length;
  for (int k = 0; k < M; ++k) {
    const double t = 2 * M_PI * k / M, c = std::cos(t), s = std::sin(t);
    p.theta.push_back(t);
    p.x.push_back(e.cx + e.r * c);
    p.y.push_back(e.cy + e.r * s);
    p.nx.push_back(-c);
    p.ny.push_back(-s);
    p.weight.push_back(length / M);  // equal arcs: the trapezoid rule, spectrally accurate on a circle
  }
  return p;
}
// @end edge-points-circle

EdgePoints polygon_points(const EdgeCurve& e, double h) {
  EdgePoints p;
  const size_t m = e.vx.size();
  const double orientation = signed_area(e) > 0 ? 1.0 : -1.0;  // inward is left of a counter-clockwise side
  std::vector<size_t> vertex_at;  // index of each vertex's point
  std::vector<double> piece;      // piece length of the side that starts there
  for (size_t i = 0; i < m; ++i) {
    const double x0 = e.vx[i], y0 = e.vy[i], dx = e.vx[(i + 1) % m] - x0, dy = e.vy[(i + 1) % m] - y0;
    const double len = std::hypot(dx, dy);
    if (len == 0) continue;  // a repeated vertex
    const int pieces = std::max(1, static_cast<int>(std::ceil(len / h)));
    p.length += len;
    vertex_at.push_back(p.x.size());
    piece.push_back(len / pieces);
    for (int k = 0; k < pieces; ++k) {  // the side's far vertex is the next side's first point
      p.x.push_back(x0 + dx * k / pieces);
      p.y.push_back(y0 + dy * k / pieces);
      p.nx.push_back(-orientation * dy / len);
      p.ny.push_back(orientation * dx / len);
      p.weight.push_back(len / pieces);
    }
  }
  // Trapezoid rule: a vertex stands for half a piece of each side it joins, and its normal is
  // the mean of theirs.
  const size_t v = vertex_at.size();
  for (size_t i = 0; i < v; ++i) {
    const size_t at = vertex_at[i];
    const size_t prev_side_last = (i == 0 ? p.x.size() : vertex_at[i]) - 1;
    p.weight[at] = 0.5 * (piece[i] + piece[(i + v - 1) % v]);
    const double nx = p.nx[at] + p.nx[prev_side_last], ny = p.ny[at] + p.ny[prev_side_last];
    const double norm = std::hypot(nx, ny);
    if (norm > 0) p.nx[at] = nx / norm, p.ny[at] = ny / norm;
  }
  return p;
}
}  // namespace

EdgePoints edge_points(const EdgeCurve& e, double h) {
  switch (e.kind) {
    case EdgeCurve::Kind::Circle: return circle_points(e, h);
    case EdgeCurve::Kind::Polygon: return polygon_points(e, h);
    default: return {};
  }
}

double distance_to_edge(const EdgeCurve& e, double x, double y) {
  if (e.kind == EdgeCurve::Kind::Circle) return std::abs(std::hypot(x - e.cx, y - e.cy) - e.r);
  double d = INFINITY;
  const size_t m = e.vx.size();
  for (size_t i = 0; i < m && e.kind == EdgeCurve::Kind::Polygon; ++i) {
    const double ax = e.vx[i], ay = e.vy[i], bx = e.vx[(i + 1) % m] - ax, by = e.vy[(i + 1) % m] - ay;
    const double len2 = bx * bx + by * by;
    const double t = len2 > 0 ? std::clamp(((x - ax) * bx + (y - ay) * by) / len2, 0.0, 1.0) : 0.0;
    d = std::min(d, std::hypot(x - ax - t * bx, y - ay - t * by));
  }
  return d;
}

}  // namespace plate

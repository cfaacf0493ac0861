// Scenes from their parts.
#include "scene.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "fields.hpp"

namespace plate {

namespace {
std::string text(double v) {
  std::ostringstream o;
  o.precision(12);
  o << v;
  return o.str();
}
void require_finite(double v, const std::string& what) {
  if (!std::isfinite(v)) throw std::invalid_argument(what + " must be a finite number, got " + text(v));
}
}  // namespace

Scene cylinder_scene(double lx, double ly, const Cylinder& c, double load) {
  if (!(lx > 0 && std::isfinite(lx) && ly > 0 && std::isfinite(ly)))
    throw std::invalid_argument("--lx and --ly must be finite and > 0, got " + text(lx) + " and " + text(ly));
  require_finite(c.cx, "--centre");
  require_finite(c.cy, "--centre");
  require_finite(c.height, "--obstacle-height");
  require_finite(load, "--load");
  if (!(c.radius > 0 && std::isfinite(c.radius))) throw std::invalid_argument("--radius must be finite and > 0, got " + text(c.radius));
  if (!(c.cx - c.radius >= 0 && c.cx + c.radius <= lx && c.cy - c.radius >= 0 && c.cy + c.radius <= ly))
    throw std::invalid_argument("--centre and --radius: the cylinder's disk (centre (" + text(c.cx) + ", " + text(c.cy) +
                                "), radius " + text(c.radius) + ") does not lie inside the plate [0, " + text(lx) +
                                "] x [0, " + text(ly) + "]");
  Scene s;
  s.lx = lx, s.ly = ly;
  s.obstacle = cylinder(c.cx, c.cy, c.radius, c.height);
  s.edge = circle_edge(c.cx, c.cy, c.radius);
  s.cylinder = c;
  s.load = [load](double, double) { return load; };
  s.uniform_load = load;
  s.obstacle_text = "cylinder";
  s.load_text = text(load);
  return s;
}

Scene at_height(const Scene& s, double R) {
  if (!s.cylinder) throw std::logic_error("at_height: the scene's obstacle is not a cylinder");
  Scene t = s;
  t.cylinder->height = R;
  t.obstacle = cylinder(s.cylinder->cx, s.cylinder->cy, s.cylinder->radius, R);
  return t;
}

Scene field_scene(double lx, double ly, Field obstacle, Field load) {
  if (!(lx > 0 && std::isfinite(lx) && ly > 0 && std::isfinite(ly)))
    throw std::invalid_argument("--lx and --ly must be finite and > 0, got " + text(lx) + " and " + text(ly));
  Scene s;
  s.lx = lx, s.ly = ly;
  s.obstacle = std::move(obstacle);
  s.load = std::move(load);
  s.obstacle_text = "(a function)";
  s.load_text = "(a function)";
  return s;
}

Scene with_load(const Scene& s, const std::string& load) {
  Scene t = s;
  t.load = expression("--load", load);
  t.load_text = load;
  t.uniform_load.reset();
  char* end = nullptr;
  const double f = std::strtod(load.c_str(), &end);
  if (end != load.c_str() && *end == '\0' && std::isfinite(f)) t.uniform_load = f;
  return t;
}

Scene expression_scene(double lx, double ly, const std::string& obstacle, const std::string& load, const EdgeCurve& edge) {
  if (!(lx > 0 && std::isfinite(lx) && ly > 0 && std::isfinite(ly)))
    throw std::invalid_argument("--lx and --ly must be finite and > 0, got " + text(lx) + " and " + text(ly));
  Scene s;
  s.lx = lx, s.ly = ly;
  s.obstacle = expression("--obstacle", obstacle);
  s.edge = edge;
  s.obstacle_text = obstacle;
  return with_load(s, load);
}

}  // namespace plate

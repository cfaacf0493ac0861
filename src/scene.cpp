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

Scene Scene::rectangle(double lx, double ly) {
  if (!(lx > 0 && std::isfinite(lx) && ly > 0 && std::isfinite(ly)))
    throw std::invalid_argument("--lx and --ly must be finite and > 0, got " + text(lx) + " and " + text(ly));
  Scene s;
  s.lx = lx, s.ly = ly;
  s.obstacle = [](double, double) { return -INFINITY; };
  s.obstacle_text = "-inf";
  return s.loaded(0.0);
}

Scene Scene::over(const Cylinder& c) const {
  require_finite(c.cx, "--centre");
  require_finite(c.cy, "--centre");
  require_finite(c.height, "--obstacle-height");
  if (!(c.radius > 0 && std::isfinite(c.radius))) throw std::invalid_argument("--radius must be finite and > 0, got " + text(c.radius));
  if (!(c.cx - c.radius >= 0 && c.cx + c.radius <= lx && c.cy - c.radius >= 0 && c.cy + c.radius <= ly))
    throw std::invalid_argument("--centre and --radius: the cylinder's disk (centre (" + text(c.cx) + ", " + text(c.cy) +
                                "), radius " + text(c.radius) + ") does not lie inside the plate [0, " + text(lx) +
                                "] x [0, " + text(ly) + "]");
  Scene s = *this;
  s.obstacle = plate::cylinder(c.cx, c.cy, c.radius, c.height);
  s.edge = circle_edge(c.cx, c.cy, c.radius);
  s.cylinder = c;
  s.obstacle_text = "cylinder";
  return s;
}

Scene Scene::over(const std::string& expr, const EdgeCurve& e) const {
  Scene s = *this;
  s.obstacle = expression("--obstacle", expr);
  s.edge = e;
  s.cylinder.reset();
  s.obstacle_text = expr;
  return s;
}

Scene Scene::over(Field phi) const {
  Scene s = *this;
  s.obstacle = std::move(phi);
  s.edge = {};
  s.cylinder.reset();
  s.obstacle_text = "(a function)";
  return s;
}

Scene Scene::loaded(double f) const {
  require_finite(f, "--load");
  Scene s = *this;
  s.load = [f](double, double) { return f; };
  s.uniform_load = f;
  s.load_text = text(f);
  return s;
}

Scene Scene::loaded(const std::string& f) const {
  Scene s = *this;
  s.load = expression("--load", f);
  s.load_text = f;
  s.uniform_load.reset();
  char* end = nullptr;
  const double v = std::strtod(f.c_str(), &end);
  if (end != f.c_str() && *end == '\0' && std::isfinite(v)) s.uniform_load = v;
  return s;
}

Scene Scene::loaded(Field f) const {
  Scene s = *this;
  s.load = std::move(f);
  s.uniform_load.reset();
  s.load_text = "(a function)";
  return s;
}

Scene at_height(const Scene& s, double R) {
  if (!s.cylinder) throw std::logic_error("at_height: the scene's obstacle is not a cylinder");
  Scene t = s;
  t.cylinder->height = R;
  t.obstacle = cylinder(s.cylinder->cx, s.cylinder->cy, s.cylinder->radius, R);
  return t;
}

}  // namespace plate

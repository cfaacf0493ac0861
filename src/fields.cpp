// Field constructors. A muparser Parser keeps pointers to its variables, so each expression owns
// its parser and variables on the heap and the Field closure shares them.
#include "fields.hpp"

#include <muParser.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace plate {

Field cylinder(double cx, double cy, double r, double R) {
  return [=](double x, double y) {
    const double dx = x - cx, dy = y - cy;
    return dx * dx + dy * dy <= r * r ? R : -INFINITY;
  };
}

namespace {
struct Compiled {
  double x = 0, y = 0;
  mu::Parser parser;
};
}  // namespace

Field expression(const std::string& what, const std::string& text) {
  auto c = std::make_shared<Compiled>();
  try {
    c->parser.DefineVar("x", &c->x);
    c->parser.DefineVar("y", &c->y);
    c->parser.DefineConst("pi", M_PI);
    c->parser.DefineConst("inf", INFINITY);
    c->parser.SetExpr(text);
    c->parser.Eval();  // muparser reports syntax errors and unknown names on first evaluation
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument(what + " expression \"" + text + "\" is not valid: " + e.GetMsg());
  }
  return [c](double x, double y) {
    c->x = x;
    c->y = y;
    return c->parser.Eval();
  };
}

}  // namespace plate

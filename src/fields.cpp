// Field constructors. A muparser Parser keeps pointers to its variables, so each expression owns
// its parser and variables on the heap and the Field closure shares them.
#include "fields.hpp"

#include <cfloat>

#include <muParser.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace plate {

// The closed disk, with a few units of round-off to spare on its rim: a point on the circle
// (the grid nodes of a Pythagorean triple, (0.3, 0.35) about (0.5, 0.5) with r = 1/4) is computed
// on either side of it by rounding, and would break the scene's mirror symmetry by chance.
Field cylinder(double cx, double cy, double r, double R) {
  return [=](double x, double y) {
    const double dx = x - cx, dy = y - cy;
    return dx * dx + dy * dy <= r * r * (1 + 8 * DBL_EPSILON) ? R : -INFINITY;
  };
}

namespace {
struct Compiled {
  double x = 0, y = 0;
  mu::Parser parser;
};
}  // namespace

Field expression(const std::string& what, const std::string& text) {
  // muparser also reads assignments (x = 1) and lists (a, b, whose value is the last); a field is
  // one expression in x and y, so both are refused rather than silently evaluated.
  for (size_t i = 0; i < text.size(); ++i) {
    const bool assignment = text[i] == '=' && (i == 0 || std::string("<>!=").find(text[i - 1]) == std::string::npos) &&
                            (i + 1 >= text.size() || text[i + 1] != '=');
    if (text[i] == ',' || assignment)
      throw std::invalid_argument(what + " expression \"" + text + "\" is not valid: '" + text[i] +
                                  "' at position " + std::to_string(i + 1) +
                                  " (one expression in x and y; no assignments or lists)");
  }
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

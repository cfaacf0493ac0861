// Obstacles and loads as functions of (x, y): the paper's cylinder, constants, and expressions
// in x and y read by muparser.
#pragma once
#include <string>

#include "assemble.hpp"

namespace plate {

// The paper's obstacle: height R on the closed disk of radius r around (cx, cy), no constraint
// (-inf) outside it.
Field cylinder(double cx, double cy, double r, double R);

// An expression in x and y (muparser syntax: + - * / ^, sin, exp, sqrt, ..., comparisons,
// a ? b : c; the constants pi and inf). Throws std::invalid_argument naming `what` and quoting
// muparser's message if it does not parse or uses a variable other than x and y.
Field expression(const std::string& what, const std::string& text);

}  // namespace plate

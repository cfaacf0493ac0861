// Global matrices and load vector of the Bogner-Fox-Schmit discretisation on a uniform grid.
#pragma once
#include <functional>

#include "bfs_element.hpp"
#include "grid.hpp"
#include "sparse.hpp"

namespace plate {

using Field = std::function<double(double, double)>;

// Assembles sum over elements of the element matrix `element`: the stiffness K of (Lap u, Lap v)
// with bfs_stiffness(h), the consistent mass M of (u, v) with bfs_mass(h).
SpMat assemble_matrix(const Grid& g, const Matrix16& element);

// (f, U_r^{ij}) for every unknown, by 4 x 4 Gauss points per element.
// Throws std::invalid_argument (naming `name`) if f is not finite at a quadrature point.
VectorXd assemble_load(const Grid& g, const Field& f, const char* name = "load");

}  // namespace plate

// The two norms the schemes and their checks are measured in.
#pragma once
#include "problem.hpp"

namespace plate {

// Max over grid nodes of |w|: the paper's C-norm on nodal values (only value unknowns count).
double max_nodal_abs(const VectorXd& w);

// ||v||_M = ||S v||_W, the norm in which the contraction is proved (the L2 norm for Gauss sampling).
double m_norm(const Problem& p, const VectorXd& v);

}  // namespace plate

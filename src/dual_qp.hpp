// The dual of the obstacle problem on a set of constraint rows, and Goldfarb and Idnani's dual
// active-set method for it. With w = w0 + K^{-1} S^T mu the problem min 1/2 w^T K w - F^T w,
// S w >= phi becomes
//   min_{mu >= 0} 1/2 mu^T G mu - b^T mu,   G = S K^{-1} S^T,   b = phi - S w0,
// whose gradient G mu - b = S w - phi is the gap. G is only positive semidefinite when rows are
// linearly dependent (many Gauss points on few unknowns, a node on the edge curve): then mu is not
// unique, but w is, and the method still returns one valid mu >= 0.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace plate {

struct DualQPResult {
  Eigen::VectorXd mu;      // >= 0; zero off the active rows
  Eigen::VectorXd gap;     // G mu - b: >= -tol at the end, zero on the active rows
  std::vector<int> active; // rows held, linearly independent
  int steps = 0;           // additions and drops
  int dependent = 0;       // rows that were linearly dependent on the active ones when added
  bool ok = false;
  std::string message;     // why not, when not ok
};

// Eq. (D20): the dual active-set method. A row is violated when its gap is below -tol.
DualQPResult solve_dual_qp(const Eigen::MatrixXd& G, const Eigen::VectorXd& b, double tol, int max_steps);

}  // namespace plate

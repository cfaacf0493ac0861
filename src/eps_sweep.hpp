// One penalty run at one fixed eps, measured against a reference solution: where the schemes
// (3a) and (5a) stop giving certified answers as eps -> 0, and why (results/hard_cases.md).
#pragma once
#include <string>
#include <vector>

#include "schemes.hpp"

namespace plate {

struct SweepRow {
  VectorXd w;                  // the last iterate
  Scheme scheme = Scheme::Linear;
  double eps = 0, tol = 0;
  bool stopped = false;        // the stopping rules were met
  bool converged = false;      // stopped and certified by the error bound
  std::string message;         // why not
  int iterations = 0, factorizations = 0;
  double first_step = 0;       // ||w^1 - w^0||_C, from which the linear scheme's count is predicted
  std::vector<double> steps;   // ||w^{k+1} - w^k||_M, the norm of Theorem 2
  PenaltyBound bound;
  double violation = 0;        // max over samples of (phi - S w)^+
  double error = 0;            // max over nodes |w - reference|
  double seconds = 0;
};

// Runs `scheme` at `eps` alone (no continuation) from w = 0.
SweepRow sweep_row(const Problem& p, Scheme scheme, double eps, double tol, int max_iter, const VectorXd& reference);

// Steps of (5a) shrink by 1/(1 + eps lambda1) (Theorem 2 with the sharp constant), so from a first
// step s1 it needs about 1 + ln(s1 / tol) / ln(1 + eps lambda1) steps to meet tol.
double predicted_linear_iterations(double first_step, double tol, double eps, double lambda1);

}  // namespace plate

// peer_snesvi: the peer of `make bench`. It solves the identical discrete problem our exact solver
// solves (the paper's plate, nodal sampling: K w = F + lambda at the nodal values, w >= phi there,
// the other degrees of freedom free) with PETSc's SNESVI, reduced-space (vinewtonrsls) or
// semismooth (vinewtonssls) Newton, a sparse direct factorisation inside, and judges the answer by
// our certificate. By default it is sequenced as ours is (--start sequenced: the coarser grids
// first, each answer the next grid's start); --start cold starts on the finest grid alone. Writes
// "key value" lines and the nodal values to --out, as bench's children do.
// `peer_snesvi --help` lists the options.
#include <CLI/CLI.hpp>
#include <petscsnes.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <vector>

#include "active_set.hpp"
#include "contact.hpp"
#include "exit_codes.hpp"
#include "fields.hpp"
#include "measurements.hpp"
#include "norms.hpp"
#include "published.hpp"
#include "stopwatch.hpp"

using namespace plate;

namespace {

// Our K as a PETSc matrix (every entry, both triangles), marked symmetric for the factorisation.
Mat petsc_matrix(const SpMat& K) {
  const RowSpMat rows(K);
  std::vector<PetscInt> nnz(rows.rows());
  for (Eigen::Index i = 0; i < rows.rows(); ++i) nnz[i] = static_cast<PetscInt>(rows.outerIndexPtr()[i + 1] - rows.outerIndexPtr()[i]);
  Mat A;
  MatCreateSeqAIJ(PETSC_COMM_SELF, rows.rows(), rows.cols(), 0, nnz.data(), &A);
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    const PetscInt row = static_cast<PetscInt>(i), begin = rows.outerIndexPtr()[i], count = nnz[i];
    std::vector<PetscInt> cols(rows.innerIndexPtr() + begin, rows.innerIndexPtr() + begin + count);
    MatSetValues(A, 1, &row, count, cols.data(), rows.valuePtr() + begin, INSERT_VALUES);
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE);
  MatSetOption(A, MAT_SPD, PETSC_TRUE);
  return A;
}

Vec petsc_vector(const VectorXd& v) {
  Vec x;
  VecCreateSeq(PETSC_COMM_SELF, v.size(), &x);
  double* a;
  VecGetArray(x, &a);
  for (Eigen::Index i = 0; i < v.size(); ++i) a[i] = v[i];
  VecRestoreArray(x, &a);
  return x;
}

VectorXd eigen_vector(Vec x) {
  PetscInt n;
  VecGetSize(x, &n);
  VectorXd v(n);
  const double* a;
  VecGetArrayRead(x, &a);
  for (PetscInt i = 0; i < n; ++i) v[i] = a[i];
  VecRestoreArrayRead(x, &a);
  return v;
}

struct Context {
  Mat K;  // the residual's matrix, never changed
  Vec F;
  const Problem* problem = nullptr;
  double tol = 1e-10;  // our certificate's: every entry <= tol
  int max_it = 200;
  std::vector<double> history;  // the certificate after each iteration
};

// The multipliers of w, read off the residual at the sampled values (row q is node q's value).
VectorXd multipliers(const Problem& p, const VectorXd& w) {
  const VectorXd res = p.K * w - p.F;
  VectorXd lambda(p.sampling.size());
  for (int q = 0; q < p.sampling.size(); ++q)
    lambda[q] = std::isfinite(p.phi[q]) ? res[4 * q] / p.sampling.weights[q] : 0.0;  // no bound, no force
  return lambda;
}

// The residual of K w = F: SNESVI drives it to zero where w is off its bounds.
PetscErrorCode residual(SNES, Vec w, Vec r, void* ctx) {
  const Context* c = static_cast<const Context*>(ctx);
  MatMult(c->K, w, r);
  VecAXPY(r, -1.0, c->F);
  return 0;
}

// The same stopping rule as our exact solver: SNESVI stops when our certificate holds to tol (its
// own residual tests stop at 2.7e-9 of it at n = 512 with rtol = 1e-14), or after max_it steps.
// It also gives up, as not converged, when the certificate is below 1e-6 (the active set found) but
// five iterations have not halved it: at n = 512 ssls stalls above the tolerance, and each further
// iteration is a new LU factorisation. (Before the set is found the certificate stays near 1.)
PetscErrorCode certified(SNES snes, PetscInt it, PetscReal, PetscReal, PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
  Context* c = static_cast<Context*>(ctx);
  Vec w;
  SNESGetSolution(snes, &w);
  const VectorXd x = eigen_vector(w);
  const double worst = certify(*c->problem, x, multipliers(*c->problem, x)).worst();
  c->history.push_back(worst);
  const size_t k = c->history.size();
  *reason = SNES_CONVERGED_ITERATING;
  if (!std::isfinite(fnorm)) *reason = SNES_DIVERGED_FNORM_NAN;
  else if (worst <= c->tol) *reason = SNES_CONVERGED_FNORM_ABS;  // 3.18 has no "user" reason: this one stands for ours
  else if (it >= c->max_it) *reason = SNES_DIVERGED_MAX_IT;
  else if (k > 5 && worst < 1e-6 && worst > 0.5 * c->history[k - 6]) *reason = SNES_DIVERGED_LINE_SEARCH;  // stalled
  return 0;
}

// The problem is quadratic: the Jacobian is K. It is copied afresh on each call because ssls scales
// its Jacobian in place (D_a + D_b J); handing it K itself would change the residual too.
PetscErrorCode jacobian(SNES, Vec, Mat J, Mat, void* ctx) {
  return MatCopy(static_cast<const Context*>(ctx)->K, J, SAME_NONZERO_PATTERN);
}

struct Options {
  int n = 64;
  std::string method = "rsls", start = "sequenced", reference = "reference", out;
  double tol = 1e-10;
  int max_it = 200;
};

// One grid's solve by SNESVI from `start`.
struct GridRun {
  VectorXd w;
  int iterations = 0, factorizations = 0;
  SNESConvergedReason reason = SNES_CONVERGED_ITERATING;
};
GridRun solve_grid(const Problem& p, const VectorXd& start, const Options& o) {
  const int N = p.grid.unknowns();
  // The bounds: phi at the value of each sampled node (row q of S is node q's value, 4 q), none elsewhere.
  VectorXd lower = VectorXd::Constant(N, PETSC_NINFINITY), upper = VectorXd::Constant(N, PETSC_INFINITY);
  for (int q = 0; q < p.sampling.size(); ++q)
    if (std::isfinite(p.phi[q])) lower[4 * q] = p.phi[q];
  Context c{petsc_matrix(p.K), petsc_vector(p.F), &p, o.tol, o.max_it, {}};
  Mat J;
  MatDuplicate(c.K, MAT_COPY_VALUES, &J);
  Vec w = petsc_vector(start.cwiseMax(lower)), lo = petsc_vector(lower), hi = petsc_vector(upper), r;
  VecDuplicate(w, &r);

  SNES snes;
  SNESCreate(PETSC_COMM_SELF, &snes);
  SNESSetType(snes, o.method == "rsls" ? SNESVINEWTONRSLS : SNESVINEWTONSSLS);
  SNESSetFunction(snes, r, residual, &c);
  SNESSetJacobian(snes, J, J, jacobian, &c);
  SNESVISetVariableBounds(snes, lo, hi);
  SNESSetTolerances(snes, 0.0, 0.0, 0.0, o.max_it, 100000);
  SNESSetConvergenceTest(snes, certified, &c, nullptr);
  KSP ksp;
  SNESGetKSP(snes, &ksp);
  KSPSetType(ksp, KSPPREONLY);
  PC pc;
  KSPGetPC(ksp, &pc);
  // rsls factors K on the free set, which stays symmetric positive definite: CHOLMOD, as ours.
  // ssls factors a row-scaled, unsymmetric K: MUMPS LU (UMFPACK, through PETSc's 32-bit interface,
  // runs out of index space at n = 512).
  PCSetType(pc, o.method == "rsls" ? PCCHOLESKY : PCLU);
  PCFactorSetMatSolverType(pc, o.method == "rsls" ? MATSOLVERCHOLMOD : MATSOLVERMUMPS);
  // Full projected Newton steps: on this quadratic problem they halve rsls's iterations against the
  // default backtracking (41 against 158 at n = 128, cold) and spare ssls one. PETSC_OPTIONS may override.
  SNESLineSearch search;
  SNESGetLineSearch(snes, &search);
  SNESLineSearchSetType(search, SNESLINESEARCHBASIC);
  SNESSetFromOptions(snes);
  if (SNESSolve(snes, nullptr, w) != 0)
    throw std::runtime_error("PETSc's SNESSolve failed (its message is above)");
  GridRun run;
  SNESGetConvergedReason(snes, &run.reason);
  PetscInt its, linear;
  SNESGetIterationNumber(snes, &its);
  SNESGetLinearSolveIterations(snes, &linear);
  run.iterations = static_cast<int>(its);
  run.factorizations = static_cast<int>(linear);
  run.w = eigen_vector(w);
  SNESDestroy(&snes);
  for (Vec* x : {&w, &lo, &hi, &r, &c.F}) VecDestroy(x);
  MatDestroy(&c.K);
  MatDestroy(&J);
  return run;
}

// The coarse answer as a start on the grid twice as fine: BFS spaces on nested grids are nested, so
// Hermite interpolation of w_2h (its value, slopes and twist at each fine node) is w_2h itself.
VectorXd prolong(const Grid& coarse, const VectorXd& wc, const Grid& fine) {
  VectorXd w = VectorXd::Zero(fine.unknowns());
  for (int j = 0; j <= fine.ny; ++j)
    for (int i = 0; i <= fine.nx; ++i) {
      if (fine.dof(i, j, kW) < 0) continue;
      const PointValues v = evaluate(coarse, wc, fine.x(i), fine.y(j));
      const double parts[4] = {v.w, v.wx, v.wy, v.wxy};
      for (int k = 0; k < 4; ++k)
        if (const int d = fine.dof(i, j, k); d >= 0) w[d] = parts[k];
    }
  return w;
}

int solve(const Options& o) {
  Measurements m;
  std::map<std::string, double>& v = m.v;
  const auto t0 = Clock::now();
  const Scene scene = paper_scene();
  const Problem p = make_problem(scene, make_grid(o.n), SamplingSpec{SamplingKind::Nodes});
  v["assemble_s"] = seconds_since(t0);
  v["unknowns"] = p.grid.unknowns();

  // Sequenced: the grids ours solves before n (n / 2, n / 4, ... while even and at least the
  // coarsest of ExactOptions), each started from the one before; each coarse solve to the same
  // certificate, and its answer used even when it misses it (as ours does). Cold: max(phi, 0) on n.
  // The time includes the coarse grids' assembly, as ours does; not the fine grid's.
  const auto t1 = Clock::now();
  std::vector<int> grids{o.n};
  if (o.start == "sequenced")
    while (grids.back() % 2 == 0 && grids.back() / 2 >= ExactOptions{}.coarsest) grids.push_back(grids.back() / 2);
  std::reverse(grids.begin(), grids.end());
  std::optional<Problem> before;
  VectorXd w_before;
  int iterations = 0, factorizations = 0;
  GridRun fine;
  for (int n : grids) {
    std::optional<Problem> level;
    if (n != o.n) level = make_problem(scene, make_grid(n), SamplingSpec{SamplingKind::Nodes});
    const Problem& q = level ? *level : p;
    const VectorXd guess = before ? prolong(before->grid, w_before, q.grid) : VectorXd::Zero(q.grid.unknowns());
    GridRun run = solve_grid(q, guess, o);
    iterations += run.iterations, factorizations += run.factorizations;
    if (n == o.n) fine = std::move(run);
    else before = std::move(level), w_before = std::move(run.w);
  }
  v["seconds"] = seconds_since(t1);
  v["iterations"] = iterations;
  v["fine_iterations"] = fine.iterations;
  v["factorizations"] = factorizations;
  v["reason"] = fine.reason;
  v["sequenced"] = o.start == "sequenced";

  const VectorXd& x = fine.w;
  const VectorXd lambda = multipliers(p, x);
  const Certificate cert = certify(p, x, lambda);
  v["certificate"] = cert.worst();
  v["certificate_violation"] = cert.violation;
  v["certificate_negative_multiplier"] = cert.negative_multiplier;
  v["certificate_complementarity"] = cert.complementarity;
  v["certificate_stationarity"] = cert.stationarity;
  v["converged"] = fine.reason > 0 && cert.worst() <= o.tol;
  v["w_centre"] = evaluate(p.grid, x, 0.5, 0.5).w;
  v["max_w"] = max_nodal_abs(x);
  v["total_force"] = p.sampling.weights.dot(lambda);

  for (int q = 0; q < p.grid.unknowns() / 4; ++q) m.nodal.push_back(x[4 * q]);
  write_measurements(o.out, m);
  if (v["converged"] == 0)
    std::cerr << "peer_snesvi: " << o.method << " (" << o.start << ") n = " << o.n << ": not converged (reason "
              << fine.reason << ", certificate " << cert.worst() << ")\n";
  return v["converged"] != 0 ? kSuccess : kNotConverged;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"peer_snesvi: the paper's problem (nodal sampling, as `plate --scheme exact`) by PETSc's SNESVI,\n"
               "for make bench. Writes 'key value' lines and the nodal values of w to --out."};
  Options o;
  app.add_option("-n,--cells", o.n, "cells per side")->check(CLI::Range(2, 2048))->capture_default_str();
  app.add_option("--method", o.method, "rsls (reduced space) or ssls (semismooth)")
      ->check(CLI::IsMember({"rsls", "ssls"}))->capture_default_str();
  app.add_option("--start", o.start, "sequenced: solve n / 2, n / 4, ... (down to 8 cells) first, each grid from the "
                 "one before, as our exact solver does; cold: from max(phi, 0) on n alone")
      ->check(CLI::IsMember({"sequenced", "cold"}))->capture_default_str();
  app.add_option("--reference", o.reference, "folder with paper_numbers.csv")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--out", o.out, "file for the measurements")->required();
  app.add_option("--tol", o.tol, "stop when every entry of our certificate is at most this")
      ->check(CLI::Range(1e-15, 1e-2))->capture_default_str();
  app.add_option("--max-it", o.max_it, "Newton iterations at most")->check(CLI::Range(1, 100000))->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "peer_snesvi"); status >= 0) return status;
  // PETSc reads its own options (-snes_monitor, ...) from PETSC_OPTIONS only: argv is CLI11's.
  int no_argc = 1;
  char** no_argv = argv;
  if (PetscInitialize(&no_argc, &no_argv, nullptr, nullptr) != 0) {
    std::cerr << "peer_snesvi: PETSc failed to start\n";
    return kFailure;
  }
  int status = kFailure;
  try {
    status = solve(o);
  } catch (const std::exception& e) {
    std::cerr << "peer_snesvi: error: " << e.what() << "\n";
  }
  PetscFinalize();
  return status;
}

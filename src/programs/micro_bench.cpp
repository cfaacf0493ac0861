// micro_bench: Google Benchmark timings of the three kernels every solver is built from: assembly of
// K, its numeric Cholesky factorisation (symbolic analysis done once, outside the loop), and one
// solve with the factor. Run by `make bench`, which keeps the table in results/micro_benchmarks.txt.
#include <benchmark/benchmark.h>

#include "cholesky.hpp"
#include "problem.hpp"

using namespace plate;

namespace {
void Assembly(benchmark::State& state) {
  const Grid g = make_grid(static_cast<int>(state.range(0)));
  const Matrix16 element = bfs_stiffness(g.h);
  for (auto _ : state) benchmark::DoNotOptimize(assemble_matrix(g, element));
  state.counters["unknowns"] = g.unknowns();
  state.SetComplexityN(g.unknowns());
}
BENCHMARK(Assembly)->RangeMultiplier(2)->Range(32, 512)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);

void Factorisation(benchmark::State& state) {
  const Grid g = make_grid(static_cast<int>(state.range(0)));
  const SpMat K = assemble_matrix(g, bfs_stiffness(g.h));
  Cholesky chol;
  chol.analyze(K);
  for (auto _ : state) chol.factorize(K);
  state.counters["unknowns"] = g.unknowns();
}
BENCHMARK(Factorisation)->RangeMultiplier(2)->Range(32, 256)->Unit(benchmark::kMillisecond);

void Solve(benchmark::State& state) {
  const Grid g = make_grid(static_cast<int>(state.range(0)));
  const SpMat K = assemble_matrix(g, bfs_stiffness(g.h));
  Cholesky chol;
  chol.factorize(K);
  const VectorXd b = VectorXd::Ones(K.rows());
  for (auto _ : state) benchmark::DoNotOptimize(chol.solve(b));
  state.counters["unknowns"] = g.unknowns();
}
BENCHMARK(Solve)->RangeMultiplier(2)->Range(32, 256)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();

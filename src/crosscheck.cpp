// Running the two codes for the cross-check and reading FreeFEM's output.
#include "crosscheck.hpp"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cholesky.hpp"
#include "contact.hpp"
#include "fields.hpp"
#include "schemes.hpp"
#include "stopwatch.hpp"

namespace plate {

CheckValues solve_ours(int n, SamplingKind kind, const CrossSettings& s) {
  const auto t0 = Clock::now();
  const Grid g = make_grid(n);
  const Field phi = cylinder(0.5, 0.5, 0.25, s.R);
  const Problem p = make_problem(g, kind, phi, [](double, double) { return 0.0; });
  SolveOptions o;
  o.scheme = Scheme::Nonlinear;
  o.tol = s.tol;
  o.eps_start = s.eps_start;
  o.eps_min = s.eps_min;
  const SolveResult r = solve(p, o);
  CheckValues v;
  v.code = std::string("bfs-") + to_string(kind);
  v.grid = std::to_string(n) + " x " + std::to_string(n);
  v.h = g.h;
  v.unknowns = g.unknowns();
  v.converged = r.converged;
  v.iterations = r.total_iterations();
  v.eps_final = r.eps;
  v.max_w = max_nodal_abs(r.w);
  v.w_rim = evaluate(g, r.w, kCheckPoints[0][0], kCheckPoints[0][1]).w;
  v.w_mid = evaluate(g, r.w, kCheckPoints[1][0], kCheckPoints[1][1]).w;
  v.w_diag = evaluate(g, r.w, kCheckPoints[2][0], kCheckPoints[2][1]).w;
  v.force = total_contact_force(p, contact_force_density(p, r.w, r.eps));
  v.seconds = seconds_since(t0);
  return v;
}

double uniform_load_centre_ours(int n) {
  const Grid g = make_grid(n);
  Cholesky c;
  c.factorize(assemble_matrix(g, bfs_stiffness(g.h)));
  return evaluate(g, c.solve(assemble_load(g, [](double, double) { return 1.0; })), 0.5, 0.5).w;
}

namespace {
std::string quote(const std::string& s) { return "'" + s + "'"; }
void run(const std::string& what, const std::string& cmd, const std::string& log) {
  const int raw = std::system((cmd + " > " + quote(log) + " 2>&1").c_str());
  const int status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  if (status != 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    throw std::runtime_error(what + " failed (exit " + std::to_string(status) + "): " + cmd + "\n" + text.str());
  }
}
}  // namespace

void gmsh_mesh(const std::string& geo, double lc, const std::string& msh) {
  std::ostringstream cmd;
  cmd.precision(17);
  cmd << "gmsh -2 -format msh22 -setnumber lc " << lc << " " << quote(geo) << " -o " << quote(msh);
  run("gmsh", cmd.str(), msh + ".log");
}

std::string run_freefem(const std::string& edp, const std::string& msh, const std::string& args,
                        const std::string& out_json) {
  // Debian's FreeFem++ looks for its plugins in the wrong folder unless told.
  setenv("FF_LOADPATH", "/usr/lib/freefem++", 0);
  std::remove(out_json.c_str());
  run("FreeFem++", "FreeFem++ -nw -v 0 " + quote(edp) + " -mesh " + quote(msh) + " " + args + " -out " + quote(out_json),
      out_json + ".log");
  std::ifstream in(out_json);
  std::stringstream text;
  text << in.rdbuf();
  if (text.str().empty()) throw std::runtime_error("FreeFem++ wrote no output to " + out_json);
  return text.str();
}

double json_number(const std::string& json, const std::string& key) {
  const std::string k = "\"" + key + "\":";
  const size_t at = json.find(k);
  if (at == std::string::npos) return NAN;
  size_t p = at + k.size();
  while (p < json.size() && (json[p] == ' ' || json[p] == '[')) ++p;
  return std::strtod(json.c_str() + p, nullptr);
}

CheckValues freefem_values(const std::string& json, double lc) {
  CheckValues v;
  v.code = "freefem-hct";
  std::ostringstream grid;
  grid << "gmsh lc = " << lc << " (" << json_number(json, "triangles") << " triangles)";
  v.grid = grid.str();
  v.h = lc;
  v.unknowns = static_cast<int>(json_number(json, "unknowns"));
  v.converged = json.find("\"converged\": true") != std::string::npos;
  v.iterations = static_cast<int>(json_number(json, "total_iterations"));
  v.eps_final = json_number(json, "eps_final");
  v.max_w = json_number(json, "max_w");
  // "w_at": [w(0.5, 0.25), w(0.5, 0.125), w(0.25, 0.25)]
  const size_t at = json.find("\"w_at\":");
  if (at != std::string::npos) {
    const char* p = json.c_str() + json.find('[', at) + 1;
    char* end = nullptr;
    v.w_rim = std::strtod(p, &end);
    v.w_mid = std::strtod(end + 1, &end);
    v.w_diag = std::strtod(end + 1, &end);
  }
  v.force = json_number(json, "total_contact_force");
  v.seconds = json_number(json, "seconds");
  return v;
}

std::vector<double> values_of(const std::vector<CheckValues>& runs, double CheckValues::*field) {
  std::vector<double> v;
  for (const auto& r : runs) v.push_back(r.*field);
  return v;
}

double last_increment(const std::vector<double>& values) {
  if (values.size() < 2) throw std::invalid_argument("last_increment: need at least two grids");
  return std::abs(values.back() - values[values.size() - 2]);
}

double error_bound(const std::vector<double>& values) {
  const double last = last_increment(values);
  if (values.size() < 3) return last;
  return std::max(last, std::abs(values[values.size() - 2] - values[values.size() - 3]));
}

bool agree(const std::vector<double>& a, const std::vector<double>& b, double* difference, double* tolerance) {
  *difference = std::abs(a.back() - b.back());
  *tolerance = error_bound(a) + error_bound(b);
  return *difference <= *tolerance;
}

}  // namespace plate

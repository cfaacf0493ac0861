// Running the other code of the cross-checks: gmsh meshes a plate with its contact circle, and
// FreeFEM solves the contact problem on that mesh, exactly (reference/contact_hct.edp) or by the
// paper's penalty method (reference/penalty_hct.edp), writing JSON.
#pragma once
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "crosscheck.hpp"
#include "published.hpp"

namespace plate {

// The code name FreeFEM's rows carry in CheckValues and the CSV.
inline constexpr const char* kFreefemCode = "freefem-hct";

// gmsh: mesh the .geo, its parameters set by `numbers` (name, value), into an MSH 2 file. Throws
// std::runtime_error on failure.
void gmsh_mesh(const std::string& geo, const std::vector<std::pair<std::string, double>>& numbers,
               const std::string& msh);

// The script's arguments for a cylinder scene's obstacle: the points file, R, the circle's centre
// and radius. Throws std::invalid_argument if the scene's obstacle is not a cylinder.
std::string scene_args(const Scene& scene, const std::string& points_file);
// gmsh's numbers for the scene's rectangle and circle, on the mesh of level n (4 n cells per
// quarter circle).
std::vector<std::pair<std::string, double>> circle_numbers(const Scene& scene, int n);
// Whether the cylinder sits at the plate's centre, so that the scene's mirror lines cut it into the
// quarter that quarter_square_with_circle.geo meshes (to the .geo's own 1e-12 of a side).
bool circle_at_centre(const Scene& scene);

// The check points, as the script's -points file wants them: their number, then "x y" each.
void write_points(const std::string& path, const std::vector<std::pair<double, double>>& points);

// A path as one shell word, for the "-name value" arguments below.
std::string shell_word(const std::string& s);

// FreeFEM: run the .edp on a mesh with extra "-name value" arguments, its JSON written to out_json
// and parsed. Throws std::runtime_error if FreeFem++ fails, exits with an error other than 3 (not
// settled: the JSON says "converged": false) or writes no JSON.
nlohmann::json run_freefem(const std::string& edp, const std::string& msh, const std::string& args,
                           const std::string& out_json);

// A bound on the round-off in a value v FreeFEM computes on a mesh whose longest edge is h:
// 30 u h^-4 |v| (the conditioning of the plate's stiffness grows as h^-4). The same runs with one and
// with two BLAS threads differ by at most a sixth of it, on the cross-check's meshes.
double freefem_roundoff(double h, double v);
inline constexpr const char* kFreefemRoundoffRule = "30 u h^-4 relative, h the longest edge";

// The check values in the script's JSON (w_at in the order of its points file), on the mesh with
// `cells` cells along a quarter of the contact circle of radius `radius`. Throws
// std::runtime_error naming a missing key.
CheckValues freefem_values(const nlohmann::json& j, int cells, double radius);

// What reference/penalty_hct.edp reports of one run of the penalty method (2).
struct PenaltyLevel {
  double eps = 0;
  int iterations = 0;
  double first_step = 0, last_step = 0;  // max over vertices of |w^{n+1} - w^n|, first and last
  double last_ratio = -1;                // last_step over the step before it; -1 after one step
  double level_change = -1;              // to the previous level; -1 on the first
  // > 0: the level ended above tol, where its steps stalled within twice this estimate of their
  // round-off (penalty_hct.edp, region roundoff-stop); 0: it met tol.
  double stopped_at_roundoff = 0;
};
struct PenaltyRun {
  std::string scheme, sampling;
  double h = 0;  // the longest mesh edge
  int unknowns = 0;
  bool converged = false;  // the stopping rules were met
  std::string why;         // why not
  int iterations = 0;      // over all levels
  double eps = 0;          // of the last level
  std::vector<PenaltyLevel> levels;
  double lambda1h = NAN;  // -eigen 1 only
  double max_w = 0, force = 0, max_m12 = 0, max_density = 0;
  // How far round-off moves max w and the force: the script's estimate from its last residual
  // (penalty_hct.edp, region ff-roundoff), or what the last step moved where that is larger and the
  // run's last level stopped at round-off (region roundoff-stop), or where it makes none (the force
  // from the penalty's integral) the worst case freefem_roundoff.
  double max_w_roundoff = 0, force_roundoff = 0;
  double residual = 0;  // of (2a) at the answer, relative
  std::vector<double> w_at;
  double seconds = 0;
};
// Throws std::runtime_error naming a missing key.
PenaltyRun penalty_values(const nlohmann::json& j);

}  // namespace plate

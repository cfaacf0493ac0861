// gmsh and FreeFem++ as child processes, their output captured in a log that an error quotes.
#include "freefem.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "line_force.hpp"

namespace plate {

// One shell word: in single quotes, each quote inside closed, escaped and reopened.
std::string shell_word(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs cmd, its output in log; throws, quoting the log, unless it exits with one of `accepted`.
int run(const std::string& what, const std::string& cmd, const std::string& log, std::vector<int> accepted = {0}) {
  const int raw = std::system((cmd + " > " + shell_word(log) + " 2>&1").c_str());
  if (raw == -1 || !WIFEXITED(raw))
    throw std::runtime_error(what + " did not run to its end (killed by a signal?): " + cmd + "\n" + read_all(log));
  const int status = WEXITSTATUS(raw);
  if (std::find(accepted.begin(), accepted.end(), status) == accepted.end())
    throw std::runtime_error(what + " failed (exit " + std::to_string(status) + "): " + cmd + "\n" + read_all(log));
  return status;
}
}  // namespace

void gmsh_mesh(const std::string& geo, const std::vector<std::pair<std::string, double>>& numbers,
               const std::string& msh) {
  std::ostringstream cmd;
  cmd.precision(17);
  cmd << "gmsh -2 -format msh22";
  for (const auto& [name, value] : numbers) cmd << " -setnumber " << name << " " << value;
  cmd << " " << shell_word(geo) << " -o " << shell_word(msh);
  run("gmsh", cmd.str(), msh + ".log");
}

namespace {
const Cylinder& cylinder_of(const Scene& s) {
  if (!s.cylinder) throw std::invalid_argument("FreeFEM's scripts model a cylinder, not '" + s.obstacle_text + "'");
  return *s.cylinder;
}
}  // namespace

std::string scene_args(const Scene& scene, const std::string& points_file) {
  const Cylinder& c = cylinder_of(scene);
  std::ostringstream args;
  args.precision(17);
  args << "-points " << shell_word(points_file) << " -R " << c.height << " -cx " << c.cx << " -cy " << c.cy << " -r " << c.radius;
  return args.str();
}

std::vector<std::pair<std::string, double>> circle_numbers(const Scene& scene, int n) {
  const Cylinder& c = cylinder_of(scene);
  return {{"n", n}, {"lx", scene.lx}, {"ly", scene.ly}, {"cx", c.cx}, {"cy", c.cy}, {"r", c.radius}};
}

bool circle_at_centre(const Scene& scene) {
  const Cylinder& c = cylinder_of(scene);
  return std::abs(c.cx - scene.lx / 2) <= 1e-12 * scene.lx && std::abs(c.cy - scene.ly / 2) <= 1e-12 * scene.ly;
}

void write_points(const std::string& path, const std::vector<std::pair<double, double>>& points) {
  std::ofstream out(path);
  out.precision(17);
  out << points.size() << "\n";
  for (const auto& [x, y] : points) out << x << " " << y << "\n";
  if (!out.flush()) throw std::runtime_error("cannot write the check points to " + path);
}

nlohmann::json run_freefem(const std::string& edp, const std::string& msh, const std::string& args,
                           const std::string& out_json) {
  // Debian's FreeFem++ looks for its plugins in the wrong folder unless told.
  setenv("FF_LOADPATH", "/usr/lib/freefem++", 0);
  std::remove(out_json.c_str());
  // Exit 3: the active set did not settle; the JSON says so ("converged": false), and the run
  // is reported as not certified rather than ending the whole check.
  run("FreeFem++", "FreeFem++ -nw -v 0 " + shell_word(edp) + " -mesh " + shell_word(msh) + " " + args + " -out " + shell_word(out_json),
      out_json + ".log", {0, 3});
  const std::string text = read_all(out_json);
  if (text.empty()) throw std::runtime_error("FreeFem++ wrote no output to " + out_json);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("FreeFem++ wrote malformed JSON to " + out_json + ": " + e.what());
  }
}

double freefem_roundoff(double h, double v) { return 30 * DBL_EPSILON * std::abs(v) / std::pow(h, 4); }

CheckValues freefem_values(const nlohmann::json& j, int cells, double radius) {
  try {
    CheckValues v;
    v.code = kFreefemCode;
    v.grid = std::to_string(cells) + " cells, " + std::to_string(j.at("triangles").get<int>()) + " triangles";
    v.cells = cells;
    v.h = j.at("hmax").get<double>();
    v.unknowns = j.at("unknowns").get<int>();
    // The script's certificate: the active set settled, every held multiplier >= 0 and every
    // other candidate on or above the obstacle (to round-off).
    const double R = j.at("R").get<double>();
    v.certified = j.at("converged").get<bool>() && j.at("min_multiplier").get<double>() >= 0 &&
                  j.at("min_gap").get<double>() >= -1e-12 * R;
    v.iterations = j.at("iterations").get<int>();
    v.max_w = j.at("max_w").get<double>();
    for (const auto& w : j.at("w_at")) v.w_at.push_back(w.get<double>());
    v.force = j.at("total_contact_force").get<double>();
    v.mean_line = v.force / (2 * M_PI * radius);
    std::vector<double> theta, force;
    for (const auto& p : j.at("rim")) theta.push_back(p.at(0).get<double>()), force.push_back(p.at(1).get<double>());
    if (theta.size() >= 2) {
      v.line = line_force_from_point_forces(theta, force, radius);
      v.q0 = line_force_fit(v.line, 0), v.q45 = line_force_fit(v.line, M_PI / 4);
    } else {
      v.q0 = v.q45 = NAN;
    }
    v.seconds = j.at("seconds").get<double>();
    return v;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("FreeFEM's JSON lacks a value: ") + e.what());
  }
}

PenaltyRun penalty_values(const nlohmann::json& j) {
  try {
    PenaltyRun r;
    r.scheme = j.at("scheme").get<std::string>();
    r.sampling = j.at("sampling").get<std::string>();
    r.h = j.at("hmax").get<double>();
    r.unknowns = j.at("unknowns").get<int>();
    r.converged = j.at("converged").get<bool>();
    r.why = j.at("why").get<std::string>();
    r.iterations = j.at("iterations").get<int>();
    r.eps = j.at("eps").get<double>();
    for (const auto& l : j.at("levels"))
      r.levels.push_back({l.at("eps").get<double>(), l.at("iterations").get<int>(), l.at("first_step").get<double>(),
                          l.at("last_step").get<double>(), l.at("last_ratio").get<double>(),
                          l.at("level_change").get<double>(), l.at("stopped_at_roundoff").get<double>()});
    if (j.contains("lambda1h")) r.lambda1h = j.at("lambda1h").get<double>();
    r.max_w = j.at("max_w").get<double>();
    r.force = j.at("total_contact_force").get<double>();
    const auto roundoff = [&](const char* key, double value) {
      const double v = j.contains(key) ? j.at(key).get<double>() : -1;
      return v >= 0 ? v : freefem_roundoff(r.h, value);  // -1: the script made no estimate
    };
    r.max_w_roundoff = roundoff("max_w_roundoff", r.max_w), r.force_roundoff = roundoff("force_roundoff", r.force);
    r.max_m12 = j.at("max_m12").get<double>();
    r.max_density = j.at("max_contact_density").get<double>();
    r.residual = j.at("residual").get<double>();
    for (const auto& w : j.at("w_at")) r.w_at.push_back(w.get<double>());
    r.seconds = j.at("seconds").get<double>();
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("FreeFEM's penalty JSON lacks a value: ") + e.what());
  }
}

}  // namespace plate

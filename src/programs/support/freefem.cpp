// gmsh and FreeFem++ as child processes, their output captured in a log that an error quotes.
#include "freefem.hpp"

#include <sys/wait.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "line_force.hpp"

namespace plate {

namespace {
std::string quote(const std::string& s) { return "'" + s + "'"; }

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void run(const std::string& what, const std::string& cmd, const std::string& log) {
  const int raw = std::system((cmd + " > " + quote(log) + " 2>&1").c_str());
  const int status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  if (status != 0)
    throw std::runtime_error(what + " failed (exit " + std::to_string(status) + "): " + cmd + "\n" + read_all(log));
}
}  // namespace

void gmsh_mesh(const std::string& geo, const std::vector<std::pair<std::string, double>>& numbers,
               const std::string& msh) {
  std::ostringstream cmd;
  cmd.precision(17);
  cmd << "gmsh -2 -format msh22";
  for (const auto& [name, value] : numbers) cmd << " -setnumber " << name << " " << value;
  cmd << " " << quote(geo) << " -o " << quote(msh);
  run("gmsh", cmd.str(), msh + ".log");
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
  run("FreeFem++", "FreeFem++ -nw -v 0 " + quote(edp) + " -mesh " + quote(msh) + " " + args + " -out " + quote(out_json),
      out_json + ".log");
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
    v.code = "freefem-hct";
    v.grid = std::to_string(cells) + " cells per quarter circle (" + std::to_string(j.at("triangles").get<int>()) + " triangles)";
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
      const LineForce line = line_force_from_point_forces(theta, force, radius);
      v.q0 = line_force_fit(line, 0), v.q45 = line_force_fit(line, M_PI / 4);
    } else {
      v.q0 = v.q45 = NAN;
    }
    v.seconds = j.at("seconds").get<double>();
    return v;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("FreeFEM's JSON lacks a value: ") + e.what());
  }
}

}  // namespace plate

// gmsh and FreeFem++ as child processes, their output captured in a log that an error quotes.
#include "freefem.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

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

void gmsh_mesh(const std::string& geo, double lc, const std::string& msh) {
  std::ostringstream cmd;
  cmd.precision(17);
  cmd << "gmsh -2 -format msh22 -setnumber lc " << lc << " " << quote(geo) << " -o " << quote(msh);
  run("gmsh", cmd.str(), msh + ".log");
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

CheckValues freefem_values(const nlohmann::json& j, double lc) {
  try {
    CheckValues v;
    v.code = "freefem-hct";
    std::ostringstream grid;
    grid << "gmsh lc = " << lc << " (" << j.at("triangles").get<int>() << " triangles)";
    v.grid = grid.str();
    v.h = lc;
    v.unknowns = j.at("unknowns").get<int>();
    v.converged = j.at("converged").get<bool>();
    v.iterations = j.at("total_iterations").get<int>();
    v.eps_final = j.at("eps_final").get<double>();
    v.max_w = j.at("max_w").get<double>();
    // "w_at": [w(0.5, 0.25), w(0.5, 0.125), w(0.25, 0.25)], the order of kCheckPoints
    const auto& at = j.at("w_at");
    v.w_rim = at.at(0).get<double>();
    v.w_mid = at.at(1).get<double>();
    v.w_diag = at.at(2).get<double>();
    v.force = j.at("total_contact_force").get<double>();
    v.seconds = j.at("seconds").get<double>();
    return v;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("FreeFEM's JSON lacks a value: ") + e.what());
  }
}

}  // namespace plate

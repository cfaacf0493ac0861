// Running the other code of the cross-check: gmsh meshes the square with its contact circle, and
// FreeFEM solves the paper's problem on that mesh (reference/penalty_hct.edp), writing JSON.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "crosscheck.hpp"

namespace plate {

// gmsh: mesh the .geo with size lc into an MSH 2 file. Throws std::runtime_error on failure.
void gmsh_mesh(const std::string& geo, double lc, const std::string& msh);

// FreeFEM: run the .edp on a mesh with extra "-name value" arguments, its JSON written to out_json
// and parsed. Throws std::runtime_error if FreeFem++ fails, exits with an error or writes no JSON.
nlohmann::json run_freefem(const std::string& edp, const std::string& msh, const std::string& args,
                           const std::string& out_json);

// The check values in the script's JSON, on a mesh of size lc. Throws std::runtime_error naming a
// missing key.
CheckValues freefem_values(const nlohmann::json& j, double lc);

}  // namespace plate

// Reading gmsh's MSH 2 files in the tests that check meshes themselves (the graded ring, the
// unfolded quarter).
#pragma once
#include <istream>
#include <string>
#include <utility>
#include <vector>

// The $Nodes section of an MSH 2 stream, read from wherever the stream stands: each node's (x, y),
// at its id (entry 0 unused). The stream is left after the last node; it fails if the section is
// missing or short.
inline std::vector<std::pair<double, double>> read_msh_nodes(std::istream& in) {
  std::string line;
  while (std::getline(in, line) && line != "$Nodes") {}
  int nodes = 0;
  in >> nodes;
  std::vector<std::pair<double, double>> xy(nodes + 1);
  for (int k = 0; k < nodes && in; ++k) {
    int id;
    double z;
    in >> id;
    if (id < 1 || id > nodes) in.setstate(std::ios::failbit);
    else in >> xy[id].first >> xy[id].second >> z;
  }
  return xy;
}

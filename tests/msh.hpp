// Reading gmsh's MSH 2 files in the tests that check meshes themselves (the graded ring, the
// unfolded quarter).
#pragma once
#include <cmath>
#include <fstream>
#include <iomanip>
#include <istream>
#include <map>
#include <stdexcept>
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

// The whole plate's mesh made from a quarter's (MSH 2) by reflecting it in x = cx and y = cy, so
// that it is exactly mirror-symmetric. square_with_circle.geo's is not: its alternating diagonals
// are mirror images in 414 of 640 triangles at n = 2, and its own rim forces then differ from their
// mirror images by 4e-9 of the largest, more than the round-off bound the exact script's quarter test
// holds them to (tests/test_crosscheck.cpp). The mirror lines (tag 3)
// become interior and are dropped. With `half`, only the reflection in y = cy: the lower half, whose
// mirror line x = cx keeps its tag.
inline void unfold_quarter_mesh(const std::string& quarter, const std::string& whole, double cx, double cy, bool half = false) {
  std::ifstream in(quarter);
  const std::vector<std::pair<double, double>> xy = read_msh_nodes(in);
  std::string line;
  while (std::getline(in, line) && line != "$Elements") {}
  int elements = 0;
  in >> elements;
  std::vector<std::vector<int>> elems;  // type, physical, elementary, nodes...
  for (int k = 0; k < elements; ++k) {
    int id, type, ntags;
    in >> id >> type >> ntags;
    std::vector<int> tags(ntags), e{type};
    for (int& t : tags) in >> t;
    e.push_back(tags.at(0)), e.push_back(tags.at(1));
    const int vertices = type == 1 ? 2 : type == 2 ? 3 : 1;
    for (int v = 0; v < vertices; ++v) e.push_back(0), in >> e.back();
    elems.push_back(e);
  }
  if (!in) throw std::runtime_error("unfold_quarter_mesh: cannot read the elements of " + quarter);
  // One node per distinct point: a mirror line's nodes are their own images.
  std::map<std::pair<long long, long long>, int> index;
  std::vector<std::pair<double, double>> out_xy;
  const auto node = [&](double x, double y) {
    const auto key = std::make_pair(std::llround(x * 1e9), std::llround(y * 1e9));
    const auto [it, added] = index.emplace(key, int(out_xy.size()) + 1);
    if (added) out_xy.push_back({x, y});
    return it->second;
  };
  std::vector<std::vector<int>> out_elems;
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (const auto& e : elems) {
        if (half && sx < 0) continue;
        const bool on_x = e[0] == 1 && std::abs(xy.at(e[3]).first - cx) < 1e-12 && std::abs(xy.at(e[4]).first - cx) < 1e-12;
        if (e[0] == 15 || (e[0] == 1 && e[1] == 3 && !(half && on_x))) continue;  // points; the mirror lines reflected in
        std::vector<int> f = {e[0], e[1], e[2]};
        for (size_t v = 3; v < e.size(); ++v) {
          const auto [x, y] = xy.at(e[v]);
          f.push_back(node(cx + sx * (x - cx), cy + sy * (y - cy)));
        }
        if (sx * sy < 0 && e[0] == 2) std::swap(f[4], f[5]);  // a reflection turns a triangle over
        out_elems.push_back(f);
      }
  std::ofstream out(whole);
  out << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << out_xy.size() << "\n";
  for (size_t k = 0; k < out_xy.size(); ++k) out << k + 1 << " " << out_xy[k].first << " " << out_xy[k].second << " 0\n";
  out << "$EndNodes\n$Elements\n" << out_elems.size() << "\n";
  for (size_t k = 0; k < out_elems.size(); ++k) {
    const auto& f = out_elems[k];
    out << k + 1 << " " << f[0] << " 2 " << f[1] << " " << f[2];
    for (size_t v = 3; v < f.size(); ++v) out << " " << f[v];
    out << "\n";
  }
  out << "$EndElements\n";
}

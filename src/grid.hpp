// The rectangle [0, lx] x [0, ly] cut into nx x ny squares of side h, and the numbering of
// the Bogner-Fox-Schmit unknowns: four per node that carries unknowns, none on a clamped edge.
// A grid may also be the part of a symmetric plate: its right (top) edge is then a line of mirror
// symmetry, where the plate is free to move but has no slope across the line.
#pragma once
#include <array>

namespace plate {

// Degree-of-freedom components at a node, in this order.
enum Component { kW = 0, kWx = 1, kWy = 2, kWxy = 3 };

struct Grid {
  int nx = 4, ny = 4;
  double h = 0.25;
  // The edge x = lx (y = ly) is a mirror line of the whole plate, not clamped: the whole plate is
  // [0, 2 lx] (x [0, 2 ly]) and w(2 lx - x, y) = w(x, y).
  bool mirror_x = false, mirror_y = false;

  double lx() const { return nx * h; }
  double ly() const { return ny * h; }
  double x(int i) const { return i * h; }
  double y(int j) const { return j * h; }
  // The whole plate this grid is part of.
  int whole_nx() const { return mirror_x ? 2 * nx : nx; }
  int whole_ny() const { return mirror_y ? 2 * ny : ny; }
  double whole_lx() const { return whole_nx() * h; }
  double whole_ly() const { return whole_ny() * h; }
  bool is_part() const { return mirror_x || mirror_y; }
  // Copies of this part that make up the whole plate (1, 2 or 4): an integral over the whole plate
  // of a mirror-symmetric field is this many times the part's.
  int images() const { return (mirror_x ? 2 : 1) * (mirror_y ? 2 : 1); }

  // Eq. (2b): w = dw/dn = 0 on the clamped edges, imposed by giving their nodes no unknowns. A
  // node on a mirror line keeps w and the slope along the line; the slope across it and w_xy are
  // zero for a symmetric plate: those components are "pinned" (kept in the numbering, but held at 0).
  bool is_interior(int i, int j) const {
    return i > 0 && j > 0 && (i < nx || (mirror_x && i == nx)) && (j < ny || (mirror_y && j == ny));
  }
  bool pinned(int i, int j, int c) const {
    return (mirror_x && i == nx && (c == kWx || c == kWxy)) || (mirror_y && j == ny && (c == kWy || c == kWxy));
  }
  int nodes_x() const { return nx - 1 + (mirror_x ? 1 : 0); }
  int nodes_y() const { return ny - 1 + (mirror_y ? 1 : 0); }
  int interior_nodes() const { return nodes_x() * nodes_y(); }
  // Four per node, pinned components included (they are held at zero by the matrices).
  int unknowns() const { return 4 * interior_nodes(); }
  int elements() const { return nx * ny; }

  // Index of a node with unknowns, row by row; -1 on a clamped edge.
  int node(int i, int j) const { return is_interior(i, j) ? (j - 1) * nodes_x() + (i - 1) : -1; }
  // The unknown of component c at node (i, j); -1 where there is none (clamped) or it is pinned.
  int dof(int i, int j, int c) const { return is_interior(i, j) && !pinned(i, j, c) ? 4 * node(i, j) + c : -1; }

  // Global unknowns of element (ex, ey) in local order 4 * (ax + 2 ay) + c; -1 where clamped or pinned.
  std::array<int, 16> element_dofs(int ex, int ey) const;

  // The element containing (x, y) (points on the far edges belong to the last element) and
  // the local coordinates (t, s) in [0, 1]^2. A point of the whole plate beyond a mirror line is
  // reflected into the grid first; `flips` (if given) gets bit 1 for a reflection in x, bit 2 in y,
  // so a caller can change the sign of the derivatives across the line. Returns false outside the
  // (whole) rectangle.
  bool locate(double x, double y, int& ex, int& ey, double& t, double& s, int* flips = nullptr) const;
};

// Grid of the rectangle [0, lx] x [0, ly] with nx cells along x; throws std::invalid_argument
// when a dimension is not positive or ly is not a whole number of cells.
Grid make_grid(int nx, double lx = 1.0, double ly = 1.0);

// The grid with cells twice as large, the same mirror lines; `whole` cells must be even.
Grid coarser(const Grid& g);

}  // namespace plate

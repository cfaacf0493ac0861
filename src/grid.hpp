// The rectangle [0, lx] x [0, ly] cut into nx x ny squares of side h, and the numbering of
// the Bogner-Fox-Schmit unknowns: four per interior node, none on the clamped boundary.
#pragma once
#include <array>

namespace plate {

// Degree-of-freedom components at a node, in this order.
enum Component { kW = 0, kWx = 1, kWy = 2, kWxy = 3 };

struct Grid {
  int nx = 4, ny = 4;
  double h = 0.25;

  double lx() const { return nx * h; }
  double ly() const { return ny * h; }
  double x(int i) const { return i * h; }
  double y(int j) const { return j * h; }

  bool is_interior(int i, int j) const { return i > 0 && i < nx && j > 0 && j < ny; }
  int interior_nodes() const { return (nx - 1) * (ny - 1); }
  int unknowns() const { return 4 * interior_nodes(); }
  int elements() const { return nx * ny; }

  // Eq. (2b): w = dw/dn = 0 on the boundary, imposed by giving boundary nodes no unknowns.
  // Index of an interior node, row by row; -1 on the boundary.
  int node(int i, int j) const { return is_interior(i, j) ? (j - 1) * (nx - 1) + (i - 1) : -1; }
  int dof(int i, int j, int c) const { return is_interior(i, j) ? 4 * node(i, j) + c : -1; }

  // Global unknowns of element (ex, ey) in local order 4 * (ax + 2 ay) + c; -1 where clamped.
  std::array<int, 16> element_dofs(int ex, int ey) const;

  // The element containing (x, y) (points on the far edges belong to the last element) and
  // the local coordinates (t, s) in [0, 1]^2. Returns false outside the rectangle.
  bool locate(double x, double y, int& ex, int& ey, double& t, double& s) const;
};

// Grid of the rectangle [0, lx] x [0, ly] with nx cells along x; throws std::invalid_argument
// when a dimension is not positive or ly is not a whole number of cells.
Grid make_grid(int nx, double lx = 1.0, double ly = 1.0);

}  // namespace plate

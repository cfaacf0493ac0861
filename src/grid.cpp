// Grid construction and the element-to-unknown map.
#include "grid.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace plate {

Grid make_grid(int nx, double lx, double ly) {
  if (nx < 1) throw std::invalid_argument("n (cells along x) must be >= 1, got " + std::to_string(nx));
  if (!(std::isfinite(lx) && lx > 0)) throw std::invalid_argument("lx (rectangle width) must be finite and > 0");
  if (!(std::isfinite(ly) && ly > 0)) throw std::invalid_argument("ly (rectangle height) must be finite and > 0");
  Grid g;
  g.nx = nx;
  g.h = lx / nx;
  const double cells = ly / g.h;
  g.ny = static_cast<int>(std::lround(cells));
  if (g.ny < 1 || std::abs(cells - g.ny) > 1e-9 * cells)
    throw std::invalid_argument("ly (rectangle height) must be a whole number of cells of side h = lx/n; got ly/h = " +
                                std::to_string(cells));
  if (4.0 * (g.nx - 1) * (g.ny - 1) > std::numeric_limits<int>::max())
    throw std::invalid_argument("n (cells along x): " + std::to_string(nx) + " x " + std::to_string(g.ny) +
                                " cells have more unknowns than an int can count");
  return g;
}

std::array<int, 16> Grid::element_dofs(int ex, int ey) const {
  std::array<int, 16> d{};
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) d[4 * a + c] = dof(ex + (a & 1), ey + (a >> 1), c);
  return d;
}

Grid coarser(const Grid& g) {
  if (g.nx % 2 || g.ny % 2) throw std::invalid_argument("coarser: the grid's cell counts must be even");
  Grid c = g;
  c.nx /= 2, c.ny /= 2, c.h *= 2;
  return c;
}

bool Grid::locate(double x, double y, int& ex, int& ey, double& t, double& s, int* flips) const {
  const double slack = 1e-12 * h;
  if (!(x >= -slack && x <= whole_lx() + slack && y >= -slack && y <= whole_ly() + slack)) return false;
  int f = 0;
  if (mirror_x && x > lx()) x = 2 * lx() - x, f |= 1;
  if (mirror_y && y > ly()) y = 2 * ly() - y, f |= 2;
  if (flips) *flips = f;
  ex = std::min(nx - 1, std::max(0, static_cast<int>(std::floor(x / h))));
  ey = std::min(ny - 1, std::max(0, static_cast<int>(std::floor(y / h))));
  t = x / h - ex;
  s = y / h - ey;
  return true;
}

}  // namespace plate

// The disk plate on a flat punch: six conditions fix the six coefficients of the radial solution.
#include "disk_punch.hpp"

#include <cmath>
#include <stdexcept>

namespace plate {

void check(const DiskPunch& s) {
  if (!(std::isfinite(s.a) && std::isfinite(s.b) && std::isfinite(s.R)) || !(s.b > 0) || !(s.b < s.a) || !(s.R > 0))
    throw std::invalid_argument("disk punch: need 0 < b < a and R > 0 (got a = " + std::to_string(s.a) +
                                ", b = " + std::to_string(s.b) + ", R = " + std::to_string(s.R) + ")");
}

// @region disk-punch
// Eq. (D24): the solution of the clamped conditions w(a) = w'(a) = 0, the contact w(b) = R from
// either side, and w', w'' continuous across the rim (the line load jumps the shear only).
DiskPunch::Coefficients DiskPunch::coefficients() const {
  check(*this);
  const double L = std::log(a / b), la = std::log(a), a2 = a * a, b2 = b * b;
  const double M = a2 * a2 - b2 * b2 - 4 * a2 * b2 * L;  // > 0 for every 0 < b < a
  return {R * a2 * (a2 - b2 - 2 * b2 * L) / M, R * (a2 - b2 - 2 * a2 * L) / M,
          R * a2 * (a2 + b2 - 2 * b2 * la) / M, -R * (a2 + b2 + 2 * a2 * la) / M,
          2 * R * a2 * b2 / M,                   2 * R * a2 / M};
}
// @end disk-punch

double DiskPunch::deflection(double r) const {
  const Coefficients c = coefficients();
  if (r <= b) return c.A + c.B * r * r;
  return c.C + c.D * r * r + c.E * std::log(r) + c.F * r * r * std::log(r);
}

double DiskPunch::centre() const { return coefficients().A; }
double DiskPunch::line_load() const { return 4 * coefficients().F / b; }
double DiskPunch::total_force() const { return 8 * M_PI * coefficients().F; }

}  // namespace plate

// The second scene of the cross-check, which has a closed form: a clamped circular plate of radius a
// lifted by a flat circular punch of radius b < a and height R, coaxial, with f = 0 and D = 1. The
// plate touches the punch along its rim r = b only and bulges above it inside.
#pragma once

namespace plate {

struct DiskPunch {
  double a = 0.5, b = 0.25, R = 0.0625;

  // w(r) = A + B r^2 inside the rim, C + D r^2 + E ln r + F r^2 ln r outside: the radial solutions
  // of Lap^2 w = 0 (the inner one bounded, and with no point load, at r = 0). Eq. (D23).
  struct Coefficients {
    double A, B, C, D, E, F;
  };
  Coefficients coefficients() const;

  double deflection(double r) const;  // Eq. (D23): w(r), 0 <= r <= a
  double centre() const;              // w(0) = A
  double line_load() const;    // Eq. (D25): q on the rim, the jump of (Lap w)' there, 4 F / b
  double total_force() const;  // Eq. (D25): 2 pi b q = 8 pi F
};

// Throws std::invalid_argument unless 0 < b < a and R > 0 are finite.
void check(const DiskPunch& s);

}  // namespace plate

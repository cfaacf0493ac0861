// The derivatives in x and y of a function given in polar coordinates (r, theta) about a centre:
// the chain rule that both enrichments (D31, and the fields of a contact's end) need.
#pragma once

namespace plate {

struct PlaneDerivatives {
  double w = 0, wx = 0, wy = 0, wxx = 0, wxy = 0, wyy = 0;
};

// From f and its derivatives in r and theta at radius r, with (c, s) = (cos theta, sin theta).
inline PlaneDerivatives from_polar(double r, double c, double s, double f, double Fr, double Ft, double Frr, double Frt, double Ftt) {
  PlaneDerivatives v;
  v.w = f;
  v.wx = c * Fr - s / r * Ft;
  v.wy = s * Fr + c / r * Ft;
  v.wxx = c * c * Frr - 2 * c * s / r * Frt + s * s / (r * r) * Ftt + s * s / r * Fr + 2 * c * s / (r * r) * Ft;
  v.wyy = s * s * Frr + 2 * c * s / r * Frt + c * c / (r * r) * Ftt + c * c / r * Fr - 2 * c * s / (r * r) * Ft;
  v.wxy = c * s * Frr + (c * c - s * s) / r * Frt - c * s / (r * r) * Ftt - c * s / r * Fr - (c * c - s * s) / (r * r) * Ft;
  return v;
}

}  // namespace plate

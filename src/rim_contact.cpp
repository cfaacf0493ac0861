// The rim-contact series: the line-load fields of (D15), the clamped-corner functions of (D16),
// Trefftz polynomials and the particular solution, fitted by least squares (D17).
//
// If the plate touches the cylinder along the rim Gamma (r = a about its centre) and nowhere else,
// the contact force is a line load q(theta) on Gamma and the problem is linear:
//   Lap^2 w = f + q delta_Gamma in the plate, w = dw/dn = 0 on its edge, w = R on Gamma.
// With q = sum_m q_m cos(m theta) (+ sines), w is a sum of known fields:
//   w = f p + sum_m q_m a^3 H_m(r / a) cos(m theta) + sum_j c_j T_j,
// p = rho^4 / 64 (Lap^2 p = 1), H_m the profile (D15) whose third derivative jumps by one at
// r = a (so that each field is the line load cos(m theta) per unit length and nothing else),
// and T_j biharmonic in the whole plate: Trefftz polynomials Re, Im zeta^n and |zeta|^2 zeta^n
// about the plate's centre (zeta scaled by the half-diagonal, |zeta| <= 1 on the plate), and the
// clamped-corner functions (D16). The unknowns q_m, c_j come from least squares on the clamped
// conditions at Chebyshev-Lobatto points of the edge and w = R at equally spaced rim points.
//
// Two choices differ from the simplest statement of the method, each for a measured reason:
// * H_m is two-sided, bounded inside and decaying outside, rather than zero inside and growing
//   like r^(m+2) outside. Both span the same fields once the Trefftz degree exceeds m + 2, but
//   the growing one is a large polynomial plus a small field, and after the columns are scaled
//   that small field, the one that carries q_m, is lost in rounding for large m.
// * The corners. The clamped right angle makes w ~ r^mu with complex mu (D16), which polynomials
//   approximate only algebraically and with oscillating errors: with Trefftz terms alone, max w on
//   the paper's scene stalls near 1e-11 relative and its changes from one truncation to the next
//   change sign. Adding r^mu Phi(phi) at the four corners (each satisfies the clamped conditions
//   exactly on both edges of its corner, and is biharmonic on the whole plate, which lies in the
//   corner's quarter plane) makes the convergence geometric: 1e-13 with about forty terms.
#include "rim_contact.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace plate {

namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884L;

// Value, gradient and Hessian of a scalar (V real) or of a complex-valued biharmonic function.
template <class V>
struct Jet {
  V v{}, x{}, y{}, xx{}, xy{}, yy{};
};

template <class V, class C>
void add_scaled(Jet<V>& to, const Jet<V>& from, C c) {
  to.v += c * from.v, to.x += c * from.x, to.y += c * from.y;
  to.xx += c * from.xx, to.xy += c * from.xy, to.yy += c * from.yy;
}

// u = F(r) Theta(angle) in Cartesian derivatives, from c = cos(angle), s = sin(angle), r > 0.
template <class V, class T>
Jet<V> polar_jet(T r, T c, T s, V F, V F1, V F2, V Th, V Th1, V Th2) {
  const V ur = F1 * Th, ut = F * Th1, urr = F2 * Th, urt = F1 * Th1, utt = F * Th2;
  const T r2 = r * r, cs = c * s, cc = c * c, ss = s * s;
  Jet<V> j;
  j.v = F * Th;
  j.x = c * ur - s / r * ut;
  j.y = s * ur + c / r * ut;
  j.xx = cc * urr + ss / r * ur + ss / r2 * utt - T(2) * cs / r * urt + T(2) * cs / r2 * ut;
  j.yy = ss * urr + cc / r * ur + cc / r2 * utt + T(2) * cs / r * urt - T(2) * cs / r2 * ut;
  j.xy = cs * urr - cs / r * ur - cs / r2 * utt + (cc - ss) / r * urt - (cc - ss) / r2 * ut;
  return j;
}

template <class T>
std::complex<T> power(std::complex<T> z, int k) {  // z^k, 0 for k < 0 (then its factor is 0 too)
  if (k < 0) return {};
  std::complex<T> p(1);
  for (int i = 0; i < k; ++i) p *= z;
  return p;
}

// zeta^n (bar = false) or |zeta|^2 zeta^n (bar = true) and derivatives in (Re zeta, Im zeta):
// d/dX z^n = n z^(n-1), d/dY z^n = i n z^(n-1). `pw` holds zeta^k, or is empty.
template <class T>
Jet<std::complex<T>> complex_power_jet(std::complex<T> z, int n, bool bar, const std::vector<std::complex<T>>& pw) {
  using C = std::complex<T>;
  auto zk = [&](int k) { return k < 0 ? C() : (k < int(pw.size()) ? pw[k] : power(z, k)); };
  const C I(0, 1), p0 = zk(n), p1 = T(n) * zk(n - 1), p2 = T(n) * T(n - 1) * zk(n - 2);
  Jet<C> j;
  if (!bar) {
    j.v = p0, j.x = p1, j.y = I * p1, j.xx = p2, j.yy = -p2, j.xy = I * p2;
    return j;
  }
  const T X = z.real(), Y = z.imag(), r2 = X * X + Y * Y;
  j.v = r2 * p0;
  j.x = T(2) * X * p0 + r2 * p1;
  j.y = T(2) * Y * p0 + I * r2 * p1;
  j.xx = T(2) * p0 + T(4) * X * p1 + r2 * p2;
  j.yy = T(2) * p0 + T(4) * Y * I * p1 - r2 * p2;
  j.xy = T(2) * X * I * p1 + T(2) * Y * p1 + I * r2 * p2;
  return j;
}

template <class T>
Jet<T> part(const Jet<std::complex<T>>& j, bool imag) {
  auto p = [imag](std::complex<T> z) { return imag ? z.imag() : z.real(); };
  return {p(j.v), p(j.x), p(j.y), p(j.xx), p(j.xy), p(j.yy)};
}

// Jet in physical units of f(zeta), zeta = (x - x0 + i (y - y0)) / L.
template <class V, class T>
Jet<V> rescale(Jet<V> j, T L) {
  j.x /= L, j.y /= L, j.xx /= L * L, j.xy /= L * L, j.yy /= L * L;
  return j;
}

// d^k/ds^k of s^p, k = 0..3.
template <class T>
void power_derivatives(T s, int p, T d[4]) {
  d[0] = std::pow(s, T(p));
  d[1] = p * std::pow(s, T(p - 1));
  d[2] = p * (p - 1) * std::pow(s, T(p - 2));
  d[3] = p * (p - 1) * (p - 2) * std::pow(s, T(p - 3));
}

// @region rim-profile
// Eq. (D15): H_m and three derivatives. The field that vanishes inside is, outside, the divided
// difference of p -> s^p on the exponents of the radial solutions, {m, -m, m+2, 2-m}:
//   G_m(s) = (s^(m+2) - s^-m) / (8 m (m+1)) + (s^(2-m) - s^m) / (8 m (m-1)),   m >= 2,
// since the divided difference of p^k is 0 for k < 3 and 1 for k = 3: G, G', G'' vanish at
// s = 1 and G''' = 1. We take away its part regular at the centre (s^m, s^(m+2)) on both sides:
// H_m = A s^m - B s^(m+2) inside, A s^(2-m) - B s^-m outside, A = 1/(8m(m-1)), B = 1/(8m(m+1)),
// with the same jumps. m = 0, 1 have repeated exponents, hence the logarithms, and fields that
// grow outside: the net force and the net moment of a load cannot be carried by a decaying field.
template <class T>
void profile(int m, T s, bool inside, T h[4]) {
  if (m == 0) {
    if (inside) {
      h[0] = (s * s - 1) / 4, h[1] = s / 2, h[2] = T(0.5), h[3] = 0;
    } else {
      const T L = std::log(s);
      h[0] = (s * s + 1) * L / 4, h[1] = (2 * s * L + s + 1 / s) / 4, h[2] = (2 * L + 3 - 1 / (s * s)) / 4;
      h[3] = (2 / s + 2 / (s * s * s)) / 4;
    }
  } else if (m == 1) {
    if (inside) {
      h[0] = -s * s * s / 16, h[1] = -3 * s * s / 16, h[2] = -6 * s / 16, h[3] = T(-6) / 16;
    } else {
      const T L = std::log(s);
      h[0] = -(1 / s + 4 * s * L) / 16, h[1] = -(-1 / (s * s) + 4 * L + 4) / 16;
      h[2] = -(2 / (s * s * s) + 4 / s) / 16, h[3] = (6 / (s * s * s * s) + 4 / (s * s)) / 16;
    }
  } else {
    const T A = T(1) / (8 * T(m) * (m - 1)), B = T(1) / (8 * T(m) * (m + 1));
    T a[4], b[4];
    power_derivatives(s, inside ? m : 2 - m, a);
    power_derivatives(s, inside ? m + 2 : -m, b);
    for (int k = 0; k < 4; ++k) h[k] = A * a[k] - B * b[k];
  }
}
// @end rim-profile

// Eq. (D15) in the plane: a^3 H_m(r / a) cos(m theta) (or sin) about (cx, cy). Inside the
// circle through the polynomials zeta^m, |zeta|^2 zeta^m, which stay regular at the centre.
template <class T>
Jet<T> rim_mode_jet(const PlateSeries& f, int m, bool sine, T x, T y) {
  using C = std::complex<T>;
  const T a = T(f.radius), dx = x - T(f.cx), dy = y - T(f.cy), r = std::sqrt(dx * dx + dy * dy);
  Jet<T> j;
  if (r < a) {
    const C z(dx / a, dy / a);
    const std::vector<C> none;
    Jet<C> c;
    if (m == 0) {
      add_scaled(c, complex_power_jet(z, 0, true, none), T(0.25));
      c.v -= T(0.25);
    } else if (m == 1) {
      add_scaled(c, complex_power_jet(z, 1, true, none), T(-1) / 16);
    } else {
      add_scaled(c, complex_power_jet(z, m, false, none), T(1) / (8 * T(m) * (m - 1)));
      add_scaled(c, complex_power_jet(z, m, true, none), T(-1) / (8 * T(m) * (m + 1)));
    }
    j = rescale(part(c, sine), a);
  } else {
    T h[4];
    profile(m, r / a, false, h);
    const T th = std::atan2(dy, dx), cm = std::cos(m * th), sm = std::sin(m * th);
    const T Th = sine ? sm : cm, Th1 = sine ? m * cm : -m * sm, Th2 = -T(m) * m * Th;
    j = rescale(polar_jet<T, T>(r / a, dx / r, dy / r, h[0], h[1], h[2], Th, Th1, Th2), a);
  }
  const T a3 = a * a * a;  // F = a^3 H: the jump of F''' is then a^3 / a^3 = 1
  j.v *= a3, j.x *= a3, j.y *= a3, j.xx *= a3, j.xy *= a3, j.yy *= a3;
  return j;
}

// Eq. (D16): the clamped-corner function r^mu Phi(psi), psi = phi - pi/4 measured from the
// bisector, in the corner's frame (xi along one edge, eta along the other; r scaled by L).
// Phi = A cos mu psi + C cos (mu-2) psi (symmetric) with A cos(mu pi/4) + C cos((mu-2) pi/4) = 0
// (w = 0 on both edges); the exponent equation (D16) is what makes dw/dn = 0 there too.
template <class T>
Jet<std::complex<T>> corner_local(std::complex<T> mu, bool symmetric, T xi, T eta, T L) {
  using C = std::complex<T>;
  const T r = std::sqrt(xi * xi + eta * eta);
  if (r <= 0) return {};  // Re mu > 2: value, slope and curvature vanish at the corner
  const C I(0, 1), m2 = mu - T(2);
  // cos and sin of mu pi/4 and of mu psi, and of (mu - 2) psi by a real rotation: three
  // exponentials instead of twelve trigonometric functions of complex arguments.
  const C Q = std::exp(I * mu * T(kPi / 4)), cq = (Q + T(1) / Q) / T(2), sq = (Q - T(1) / Q) / (T(2) * I);
  const T psi = std::atan2(eta, xi) - T(kPi / 4);
  const C E = std::exp(I * mu * psi), Ei = T(1) / E, R2(std::cos(2 * psi), -std::sin(2 * psi));
  const C E2 = E * R2, E2i = Ei * std::conj(R2);
  const C c1 = (E + Ei) / T(2), s1 = (E - Ei) / (T(2) * I), c2 = (E2 + E2i) / T(2), s2 = (E2 - E2i) / (T(2) * I);
  // cos((mu - 2) pi/4) = sin(mu pi/4), sin((mu - 2) pi/4) = -cos(mu pi/4)
  C Th, Th1, Th2;
  if (symmetric) {
    const C A = sq, B = -cq;
    Th = A * c1 + B * c2, Th1 = -A * mu * s1 - B * m2 * s2, Th2 = -A * mu * mu * c1 - B * m2 * m2 * c2;
  } else {
    const C A = -cq, B = -sq;
    Th = A * s1 + B * s2, Th1 = A * mu * c1 + B * m2 * c2, Th2 = -A * mu * mu * s1 - B * m2 * m2 * s2;
  }
  const T rho = r / L;
  const C F = std::exp(mu * std::log(rho)), F1 = mu * F / rho, F2 = mu * (mu - T(1)) * F / (rho * rho);
  return rescale(polar_jet<C, T>(rho, xi / r, eta / r, F, F1, F2, Th, Th1, Th2), L);
}

template <class T>
Jet<T> corner_jet(const PlateSeries& f, const SeriesTerm& t, T x, T y) {
  const T lx = T(f.lx), ly = T(f.ly), L = std::max(lx, ly);
  const std::complex<T> mu(T(t.mu.real()), T(t.mu.imag()));
  Jet<T> sum;
  // Corners counterclockwise from (0, 0); each frame has xi horizontal and eta vertical, both
  // inward, so the four frames are mirror images of one another and their sum has the mirrors.
  for (int c = 0; c < 4; ++c) {
    if (t.corner >= 0 && t.corner != c) continue;
    const T ex = (c == 0 || c == 3) ? T(1) : T(-1), ey = (c < 2) ? T(1) : T(-1);
    const T xi = (x - (c == 0 || c == 3 ? T(0) : lx)) * ex, eta = (y - (c < 2 ? T(0) : ly)) * ey;
    const Jet<T> l = part(corner_local(mu, t.symmetric, xi, eta, L), t.imag);
    sum.v += l.v, sum.x += ex * l.x, sum.y += ey * l.y;
    sum.xx += l.xx, sum.yy += l.yy, sum.xy += ex * ey * l.xy;
  }
  return sum;
}

template <class T>
T half_diagonal(const PlateSeries& f) {
  return std::sqrt(T(f.lx) * T(f.lx) + T(f.ly) * T(f.ly)) / 2;
}

template <class T>
std::complex<T> scaled_offset(const PlateSeries& f, T x, T y) {
  const T h = half_diagonal<T>(f);
  return {(x - T(f.lx) / 2) / h, (y - T(f.ly) / 2) / h};
}

template <class T>
Jet<T> term_jet(const PlateSeries& f, const SeriesTerm& t, T x, T y, const std::vector<std::complex<T>>& pw) {
  switch (t.kind) {
    case SeriesTerm::Kind::Power:
    case SeriesTerm::Kind::BarPower: {
      const Jet<std::complex<T>> c =
          complex_power_jet(scaled_offset(f, x, y), t.n, t.kind == SeriesTerm::Kind::BarPower, pw);
      return rescale(part(c, t.imag), half_diagonal<T>(f));
    }
    case SeriesTerm::Kind::RimMode: return rim_mode_jet(f, t.n, t.imag, x, y);
    case SeriesTerm::Kind::Corner: return corner_jet(f, t, x, y);
  }
  return {};
}

// Lap^2 p = 1: p = rho^4 / 64 about the plate's centre.
template <class T>
Jet<T> particular_jet(const PlateSeries& f, T x, T y) {
  const T dx = x - T(f.lx) / 2, dy = y - T(f.ly) / 2, r2 = dx * dx + dy * dy;
  return {r2 * r2 / 64, r2 * dx / 16, r2 * dy / 16, (r2 + 2 * dx * dx) / 16, dx * dy / 8, (r2 + 2 * dy * dy) / 16};
}

template <class T>
std::vector<std::complex<T>> powers_at(const PlateSeries& f, T x, T y) {
  int top = 0;
  for (const auto& t : f.terms)
    if (t.kind == SeriesTerm::Kind::Power || t.kind == SeriesTerm::Kind::BarPower) top = std::max(top, t.n);
  std::vector<std::complex<T>> pw(top + 1);
  const std::complex<T> z = scaled_offset(f, x, y);
  pw[0] = 1;
  for (int k = 1; k <= top; ++k) pw[k] = pw[k - 1] * z;
  return pw;
}

PointValues to_values(const Jet<double>& j) { return {j.v, j.x, j.y, j.xx, j.xy, j.yy}; }

bool near(double a, double b, double scale) { return std::abs(a - b) <= 4 * DBL_EPSILON * scale; }

// Eq. (D16) solved by Newton from the asymptotic root, lambda = mu - 1.
std::complex<long double> exponent(int k, bool symmetric) {
  using C = std::complex<long double>;
  const long double x0 = 4.0L * (k + 1) + (symmetric ? -1.2L : 0.8L), sign = symmetric ? 1 : -1;
  C l(x0, 2 / kPi * std::log(2 * x0));
  for (int it = 0; it < 100; ++it) {
    const C g = std::sin(l * kPi / 2.0L) + sign * l, dg = kPi / 2.0L * std::cos(l * kPi / 2.0L) + sign;
    const C d = g / dg;
    l -= d;
    if (std::abs(d) <= 1e-18L * std::abs(l)) break;
  }
  return l + 1.0L;
}

void check_options(const RimSeriesOptions& o) {
  if (o.harmonics < 0) throw std::invalid_argument("rim series: harmonics must be >= 0");
  if (o.degree < 2) throw std::invalid_argument("rim series: degree must be >= 2");
  if (o.corner_terms < 0) throw std::invalid_argument("rim series: corner_terms must be >= 0");
  if (!(std::isfinite(o.oversampling) && o.oversampling >= 1))
    throw std::invalid_argument("rim series: oversampling must be finite and >= 1");
}

SeriesTerm term(SeriesTerm::Kind kind, int n, bool imag) {
  SeriesTerm t;
  t.kind = kind, t.n = n, t.imag = imag;
  return t;
}

// The terms the symmetry allows: Trefftz Re/Im zeta^n (degree n) and |zeta|^2 zeta^n (degree
// n + 2) up to the degree; rim modes up to the harmonic; corner functions.
std::vector<SeriesTerm> basis(RimSymmetry sym, const RimSeriesOptions& o, bool rim) {
  using K = SeriesTerm::Kind;
  const int step = sym == RimSymmetry::Square ? 4 : sym == RimSymmetry::Mirrors ? 2 : 1;
  const bool both = sym == RimSymmetry::None;
  std::vector<SeriesTerm> t;
  for (int m = 0; rim && m <= o.harmonics; m += step) {
    t.push_back(term(K::RimMode, m, false));
    if (both && m > 0) t.push_back(term(K::RimMode, m, true));
  }
  for (int n = 0; n <= o.degree; n += step) {
    for (K kind : {K::Power, K::BarPower}) {
      if (kind == K::BarPower && n + 2 > o.degree) continue;
      t.push_back(term(kind, n, false));
      if (both && n > 0) t.push_back(term(kind, n, true));
    }
  }
  for (bool symmetric : {true, false}) {
    if (!symmetric && sym == RimSymmetry::Square) continue;  // odd under the diagonal mirror
    for (int k = 0; k < o.corner_terms; ++k) {
      const std::complex<double> mu(exponent(k, symmetric));
      for (int c = both ? 0 : -1; c < (both ? 4 : 0); ++c)
        for (bool imag : {false, true}) t.push_back({K::Corner, k, imag, symmetric, c, mu});
    }
  }
  return t;
}

struct EdgePoint {
  double x, y;
  bool vertical;  // on x = 0 or x = lx: the normal derivative is w_x
};

// Chebyshev-Lobatto points on each edge, n proportional to its length, kept in the part of the
// boundary the symmetry leaves (the right half-edge above the centre; and the top one's right half).
std::vector<EdgePoint> edge_points(double lx, double ly, RimSymmetry sym, int per_perimeter, bool halfway = false) {
  std::vector<EdgePoint> p;
  auto edge = [&](double L, auto place) {
    const int n = std::max(8, int(std::ceil(per_perimeter * L / (2 * (lx + ly)))));
    for (int i = 0; i <= n; ++i) {
      const double t = halfway ? (i < n ? (1 - std::cos(M_PI * (i + 0.5) / n)) / 2 : -1) : (1 - std::cos(M_PI * i / n)) / 2;
      if (t >= 0) place(t * L);
    }
  };
  const double tol = 1e-12;
  const bool right_only = sym != RimSymmetry::None;
  edge(ly, [&](double y) {
    if (!right_only || y >= ly / 2 - tol * ly) p.push_back({lx, y, true});
    if (!right_only) p.push_back({0, y, true});
  });
  if (sym == RimSymmetry::Square) return p;
  edge(lx, [&](double x) {
    if (!right_only || x >= lx / 2 - tol * lx) p.push_back({x, ly, false});
    if (!right_only) p.push_back({x, 0, false});
  });
  return p;
}

std::vector<double> rim_angles(RimSymmetry sym, int count, bool halfway = false) {
  const double top = sym == RimSymmetry::Square ? M_PI / 4 : sym == RimSymmetry::Mirrors ? M_PI / 2 : 2 * M_PI;
  std::vector<double> th;
  for (int j = 0; j < count; ++j) {
    const double t = 2 * M_PI * (j + (halfway ? 0.5 : 0.0)) / count;
    if (t <= top + 1e-12 && (sym != RimSymmetry::None || t < 2 * M_PI)) th.push_back(t);
  }
  return th;
}

// Eq. (D17): the least-squares problem, columns scaled to unit length, solved for the
// minimum-norm coefficients by a complete orthogonal decomposition in the precision T. High
// Trefftz degrees make some columns nearly dependent; the minimum norm keeps their coefficients
// small, so that w summed in double is as good as the fit. In long double the rank is cut at
// 1e-16: the data (points, exponents, R) are doubles, so a smaller singular value is noise.
template <class T>
std::vector<double> fit(const PlateSeries& f, const std::vector<EdgePoint>& edge, const std::vector<double>& rim,
                        double height) {
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  const int U = int(f.terms.size()), rows = int(2 * edge.size() + rim.size());
  const T h = half_diagonal<T>(f), load = T(f.load);
  Mat A(rows, U);
  Vec b(rows);
  std::vector<Jet<T>> jets(U);
  auto evaluate = [&](T x, T y) {
    const auto pw = powers_at(f, x, y);
    for (int j = 0; j < U; ++j) jets[j] = term_jet(f, f.terms[j], x, y, pw);
    return particular_jet(f, x, y);
  };
  int row = 0;
  for (const EdgePoint& e : edge) {
    const Jet<T> p = evaluate(T(e.x), T(e.y));
    // w = 0, and h dw/dn = 0: a slope in the units of w, so that both conditions weigh alike
    for (int j = 0; j < U; ++j) A(row, j) = jets[j].v, A(row + 1, j) = h * (e.vertical ? jets[j].x : jets[j].y);
    b(row) = -load * p.v, b(row + 1) = -load * h * (e.vertical ? p.x : p.y);
    row += 2;
  }
  for (double th : rim) {  // w = R
    const Jet<T> p = evaluate(T(f.cx) + T(f.radius) * std::cos(T(th)), T(f.cy) + T(f.radius) * std::sin(T(th)));
    for (int j = 0; j < U; ++j) A(row, j) = jets[j].v;
    b(row++) = T(height) - load * p.v;
  }
  Vec scale(U);
  for (int j = 0; j < U; ++j) {
    scale(j) = A.col(j).norm();
    if (scale(j) > 0) A.col(j) /= scale(j);
  }
  Eigen::CompleteOrthogonalDecomposition<Mat> cod;
  if (sizeof(T) > sizeof(double)) cod.setThreshold(T(1e-16));
  cod.compute(A);
  const Vec c = cod.solve(b);
  std::vector<double> coef(U);
  for (int j = 0; j < U; ++j) coef[j] = scale(j) > 0 ? double(c(j) / scale(j)) : 0.0;
  return coef;
}

// How many collocation points: per perimeter (before the symmetry keeps its part) and on the circle.
struct Collocation {
  int per_perimeter = 0, circle = 0, equations = 0;
};

PlateSeries solve_series(PlateSeries f, RimSymmetry sym, const RimSeriesOptions& o, double height, Collocation& c) {
  const bool rim = f.radius > 0;
  f.terms = basis(sym, o, rim);
  const int U = int(f.terms.size());
  // Two equations per edge point; the symmetry keeps 1/8, 1/4 or all of the perimeter.
  const double kept = sym == RimSymmetry::Square ? 0.125 : sym == RimSymmetry::Mirrors ? 0.25 : 1.0;
  c.per_perimeter = int(std::ceil(o.oversampling * U / (2 * kept)));
  c.circle = 8 * int(std::ceil(std::max(o.oversampling * (2 * o.harmonics + 1), 64.0) / 8));
  const auto edge = edge_points(f.lx, f.ly, sym, c.per_perimeter);
  const auto angles = rim ? rim_angles(sym, c.circle) : std::vector<double>{};
  f.coef = o.extended ? fit<long double>(f, edge, angles, height) : fit<double>(f, edge, angles, height);
  c.equations = int(2 * edge.size() + angles.size());
  return f;
}

RimSymmetry plate_symmetry(double lx, double ly) {
  return near(lx, ly, std::max(lx, ly)) ? RimSymmetry::Square : RimSymmetry::Mirrors;
}

}  // namespace

RimScene rim_scene(const Scene& scene) {
  if (!scene.cylinder) throw std::invalid_argument("--obstacle: the rim-contact series models the cylinder only, not '" + scene.obstacle_text + "'");
  if (!scene.uniform_load)
    throw std::invalid_argument("--load: the rim-contact series models a uniform load, a number, not '" + scene.load_text + "'");
  const Cylinder& c = *scene.cylinder;
  const RimScene s{scene.lx, scene.ly, c.cx, c.cy, c.radius, c.height, *scene.uniform_load};
  check(s);
  return s;
}

void check(const RimScene& s) {
  auto need = [](bool ok, const char* name, double v, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("rim scene: ") + name + " " + what + " (got " + std::to_string(v) + ")");
  };
  for (auto [name, v] : {std::pair{"lx", s.lx}, {"ly", s.ly}, {"cx", s.cx}, {"cy", s.cy}, {"radius", s.radius},
                         {"height", s.height}, {"load", s.load}})
    need(std::isfinite(v), name, v, "must be finite");
  need(s.lx > 0, "lx", s.lx, "must be positive");
  need(s.ly > 0, "ly", s.ly, "must be positive");
  need(s.radius > 0, "radius", s.radius, "must be positive");
  need(s.height > 0, "height", s.height, "must be positive (the cylinder must lift the plate)");
  auto inside = [&](double c, double l, const char* name, const char* side) {
    if (!(c - s.radius > 0 && c + s.radius < l))
      throw std::invalid_argument(std::string("rim scene: the disk must lie strictly inside the plate: need 0 < ") + name +
                                  " - radius and " + name + " + radius < " + side + " (got " + name + " = " +
                                  std::to_string(c) + ", radius = " + std::to_string(s.radius) + ", " + side + " = " +
                                  std::to_string(l) + ")");
  };
  inside(s.cx, s.lx, "cx", "lx");
  inside(s.cy, s.ly, "cy", "ly");
}

RimSymmetry symmetry_of(const RimScene& s) {
  if (!near(s.cx, s.lx / 2, s.lx) || !near(s.cy, s.ly / 2, s.ly)) return RimSymmetry::None;
  return plate_symmetry(s.lx, s.ly);
}

RadialProfile rim_mode_profile(int m, double s, bool inside) {
  if (m < 0 || !(s > 0)) throw std::invalid_argument("rim_mode_profile: need m >= 0 and s > 0");
  double h[4];
  profile(m, s, inside, h);
  return {h[0], h[1], h[2], h[3]};
}

std::complex<double> corner_exponent(int k, bool symmetric) {
  if (k < 0) throw std::invalid_argument("corner_exponent: k must be >= 0");
  return std::complex<double>(exponent(k, symmetric));
}

PointValues PlateSeries::at(double x, double y) const {
  const auto pw = powers_at(*this, x, y);
  Jet<double> sum = particular_jet(*this, x, y);
  sum.v *= load, sum.x *= load, sum.y *= load, sum.xx *= load, sum.xy *= load, sum.yy *= load;
  for (size_t j = 0; j < terms.size(); ++j) add_scaled(sum, term_jet(*this, terms[j], x, y, pw), coef[j]);
  return to_values(sum);
}

PointValues term_values(const PlateSeries& f, const SeriesTerm& t, double x, double y) {
  return to_values(term_jet(f, t, x, y, std::vector<std::complex<double>>{}));
}

// @region rim-clamped-plate
PlateSeries solve_clamped_plate(double lx, double ly, double load, const RimSeriesOptions& o) {
  if (!(std::isfinite(lx) && lx > 0)) throw std::invalid_argument("clamped plate: lx must be positive and finite");
  if (!(std::isfinite(ly) && ly > 0)) throw std::invalid_argument("clamped plate: ly must be positive and finite");
  if (!std::isfinite(load)) throw std::invalid_argument("clamped plate: load must be finite");
  check_options(o);
  PlateSeries f;
  f.lx = lx, f.ly = ly, f.cx = lx / 2, f.cy = ly / 2, f.radius = 0, f.load = load;
  Collocation c;
  return solve_series(f, o.use_symmetry ? plate_symmetry(lx, ly) : RimSymmetry::None, o, 0, c);
}
// @end rim-clamped-plate

RimSeries solve_rim_series(const Scene& scene, const RimSeriesOptions& o) {
  const RimScene s = rim_scene(scene);
  check_options(o);
  RimSeries r;
  r.scene = s, r.options = o;
  r.symmetry = o.use_symmetry ? symmetry_of(s) : RimSymmetry::None;
  PlateSeries f;
  f.lx = s.lx, f.ly = s.ly, f.cx = s.cx, f.cy = s.cy, f.radius = s.radius, f.load = s.load;
  Collocation c;
  r.field = solve_series(f, r.symmetry, o, s.height, c);
  r.unknowns = int(r.field.terms.size()), r.equations = c.equations;
  r.q_cos.assign(o.harmonics + 1, 0.0);
  r.q_sin.assign(o.harmonics + 1, 0.0);
  for (size_t j = 0; j < r.field.terms.size(); ++j) {
    const SeriesTerm& t = r.field.terms[j];
    if (t.kind == SeriesTerm::Kind::RimMode) (t.imag ? r.q_sin : r.q_cos)[t.n] = r.field.coef[j];
  }
  // Misfits halfway between the collocation points, on the whole boundary whatever the symmetry.
  const double h = std::hypot(s.lx, s.ly) / 2;
  for (const EdgePoint& e : edge_points(s.lx, s.ly, RimSymmetry::None, c.per_perimeter, true)) {
    const PointValues v = r.at(e.x, e.y);
    r.edge_residual = std::max({r.edge_residual, std::abs(v.w) / s.height, h * std::abs(e.vertical ? v.wx : v.wy) / s.height});
  }
  for (double th : rim_angles(RimSymmetry::None, c.circle, true))
    r.rim_residual = std::max(r.rim_residual, std::abs(r.w(s.cx + s.radius * std::cos(th), s.cy + s.radius * std::sin(th)) - s.height) / s.height);
  return r;
}

Moments RimSeries::moments(double x, double y, double nu) const {
  const PointValues v = at(x, y);
  return bending_moments(v.wxx, v.wxy, v.wyy, nu);
}

double RimSeries::q(double theta) const {
  double sum = 0;
  for (size_t m = 0; m < q_cos.size(); ++m) sum += q_cos[m] * std::cos(m * theta) + q_sin[m] * std::sin(m * theta);
  return sum;
}

double RimSeries::total_force() const { return 2 * M_PI * scene.radius * q_cos.at(0); }

RimPeak RimSeries::max_w() const {
  const RimScene& s = scene;
  const int n = 40;  // a coarse grid with the plate's and the disk's centres added
  std::vector<RimPeak> cand{{s.lx / 2, s.ly / 2, w(s.lx / 2, s.ly / 2)}, {s.cx, s.cy, w(s.cx, s.cy)}};
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) {
      const double x = s.lx * i / n, y = s.ly * j / n;
      cand.push_back({x, y, w(x, y)});
    }
  std::partial_sort(cand.begin(), cand.begin() + 4, cand.end(), [](const RimPeak& a, const RimPeak& b) { return a.w > b.w; });
  RimPeak best = cand[0];
  for (int c = 0; c < 4; ++c)
    if (const RimPeak p = max_w_from(cand[c].x, cand[c].y); p.w > best.w) best = p;
  return best;
}

RimPeak RimSeries::max_w_from(double x0, double y0) const {
  const RimScene& s = scene;
  const double L = std::max(s.lx, s.ly);
  RimPeak p{x0, y0, w(x0, y0)};
  for (int it = 0; it < 50; ++it) {
    const PointValues v = at(p.x, p.y);
    const double det = v.wxx * v.wyy - v.wxy * v.wxy;
    double dx, dy;
    if (v.wxx < 0 && det > 0) {  // Newton on grad w = 0 where the Hessian is negative definite
      dx = -(v.wyy * v.wx - v.wxy * v.wy) / det, dy = -(-v.wxy * v.wx + v.wxx * v.wy) / det;
    } else {  // otherwise a short uphill step
      const double g = std::hypot(v.wx, v.wy);
      if (g == 0) break;
      dx = 1e-3 * L * v.wx / g, dy = 1e-3 * L * v.wy / g;
    }
    const double step = std::hypot(dx, dy), cap = 0.05 * L;
    if (step > cap) dx *= cap / step, dy *= cap / step;
    const double x = std::clamp(p.x + dx, 0.0, s.lx), y = std::clamp(p.y + dy, 0.0, s.ly), wn = w(x, y);
    if (wn < p.w) break;
    p = {x, y, wn};
    if (step <= 1e-15 * L) break;
  }
  return p;
}

// @region rim-premise
RimPremise check_premise(const RimSeries& s, int angles, double tolerance) {
  if (angles < 8) throw std::invalid_argument("check_premise: angles must be >= 8");
  if (!(tolerance >= 0)) throw std::invalid_argument("check_premise: tolerance must be >= 0");
  const RimScene& sc = s.scene;
  RimPremise p;
  p.min_q = INFINITY;
  double max_q = 0;
  // A symmetric scene's series has the symmetry exactly (its basis is the symmetric one), so the
  // sector that the mirrors leave, the angles in it and its edges, sees every value once.
  // The basis's own symmetry, not the scene's: the circle falls into this many equal sectors.
  const int parts = s.symmetry == RimSymmetry::Square ? 8 : s.symmetry == RimSymmetry::Mirrors ? 4 : 1;
  const auto last_in_sector = [&](int around) { return parts == 1 ? around - 1 : (around + parts - 1) / parts; };
  for (int i = 0; i <= last_in_sector(angles); ++i) {
    const double th = 2 * M_PI * i / angles, q = s.q(th);
    max_q = std::max(max_q, std::abs(q));
    if (q < p.min_q) p.min_q = q, p.theta_min_q = th;
  }
  p.min_w_minus_R = INFINITY;
  std::vector<double> radii;
  for (int k = 0; k < 24; ++k) radii.push_back(sc.radius * k / 24);
  radii.push_back(sc.radius * (1 - 1e-3));  // the plate leaves the rim inward with w_r <= 0
  for (double r : radii)
    for (int i = 0; i <= (r == 0 ? 0 : last_in_sector(128)); ++i) {
      const double x = sc.cx + r * std::cos(2 * M_PI * i / 128), y = sc.cy + r * std::sin(2 * M_PI * i / 128);
      const double d = s.w(x, y) - sc.height;
      if (d < p.min_w_minus_R) p.min_w_minus_R = d, p.x_min = x, p.y_min = y;
    }
  const bool pushes = p.min_q >= -tolerance * max_q, above = p.min_w_minus_R >= -tolerance * sc.height;
  p.holds = pushes && above;
  if (!pushes) p.why += "q < 0 at theta = " + std::to_string(p.theta_min_q) + " (the plate would pull the cylinder)";
  if (!above) {
    if (!p.why.empty()) p.why += "; ";
    p.why += "w < R inside the disk at (" + std::to_string(p.x_min) + ", " + std::to_string(p.y_min) + ")";
  }
  if (p.holds) p.why = "q >= 0 on the rim and w >= R on the disk";
  return p;
}
// @end rim-premise

RimSeriesOptions rim_level(int level, bool extended) {
  if (level < 0) throw std::invalid_argument("rim_level: level must be >= 0");
  RimSeriesOptions o;
  o.harmonics = 8 + 4 * level, o.degree = 16 + 8 * level, o.corner_terms = 1 + level / 2, o.extended = extended;
  return o;
}

RimAnswer rim_answer(const Scene& s, int levels, bool extended, int first) {
  if (levels < 3) throw std::invalid_argument("rim_answer: levels must be >= 3 (a bar is claimed only once it has shrunk)");
  if (first < 0 || first > levels - 3) throw std::invalid_argument("rim_answer: first must leave three levels");
  RimAnswer a;
  // The finest level first: its peak, found by a search over the plate, starts the coarser levels'
  // Newton iterations, which then need no search of their own.
  std::vector<RimSeries> series;
  for (int l = first; l < levels; ++l) series.push_back(solve_rim_series(s, rim_level(l, extended)));
  const RimPeak top = series.back().max_w();
  for (int l = first; l < levels; ++l) {
    RimSeries& r = series[l - first];
    const RimSeriesOptions& o = r.options;
    const RimPeak p = l == levels - 1 ? top : r.max_w_from(top.x, top.y);
    a.rows.push_back({l, o.harmonics, o.degree, o.corner_terms, r.unknowns, p.w, p.x, p.y, r.total_force(), r.q(0),
                      r.q(M_PI / 4), r.edge_residual, r.rim_residual});
  }
  a.finest = std::move(series.back());
  // The bar of a quantity: the last change, floored at round-off (1000 u relative: q is a third
  // derivative, and its last digits move by more than u); settled if it shrank.
  a.settled = true;
  auto bar = [&](double RimConvergenceRow::*v) {
    const size_t n = a.rows.size();
    const double floor = 1000 * DBL_EPSILON * std::abs(a.rows[n - 1].*v);
    auto change = [&](size_t i) { return std::max(std::abs(a.rows[i].*v - a.rows[i - 1].*v), floor); };
    for (size_t i = 2; i < n; ++i)  // every change below the one before it, or at the floor
      if (!(change(i) < change(i - 1) || change(i) == floor)) a.settled = false;
    return change(n - 1);
  };
  a.bar_max_w = bar(&RimConvergenceRow::max_w);
  a.bar_force = bar(&RimConvergenceRow::total_force);
  a.bar_q0 = bar(&RimConvergenceRow::q0);
  a.bar_q45 = bar(&RimConvergenceRow::q45);
  a.premise = check_premise(a.finest);
  // Once the changes reach the double fit's round-off they scatter just above the floor and need not
  // shrink: the paper's scene in micrometres (lx = 1e-6) and the smallest disk of kink_study did not
  // settle, with max w right to 14 digits. The fit in long double takes that round-off away (the
  // three finest truncations: 0.03 s against 0.02 s).
  if (!extended && a.premise.holds && !a.settled) return rim_answer(s, levels, true, first);
  return a;
}

double rim_max_abs_m12(const RimSeries& s, double nu, int k) {
  double best = -1, bx = 0, by = 0;
  auto look = [&](double x, double y) {
    x = std::clamp(x, 0.0, s.scene.lx), y = std::clamp(y, 0.0, s.scene.ly);
    if (const double m = std::abs(s.moments(x, y, nu).m12); m > best) best = m, bx = x, by = y;
  };
  // |m12| is unchanged by a mirror of the scene (m12 changes sign), so a symmetric scene's lower
  // left quarter holds its largest value.
  const int last = s.symmetry == RimSymmetry::None ? k : k / 2;
  for (int i = 0; i <= last; ++i)
    for (int j = 0; j <= last; ++j) look(s.scene.lx * i / k, s.scene.ly * j / k);
  // Then about the best lattice point, on lattices five times finer each round (m12 is continuous,
  // its gradient may jump across the rim: the search closes in on the point, not on a zero slope).
  // Each axis steps by its own lattice spacing, so a round always reaches the neighbouring rows.
  for (double sx = s.scene.lx / k / 5, sy = s.scene.ly / k / 5; sx > 1e-9 * s.scene.lx; sx /= 5, sy /= 5) {
    const double x0 = bx, y0 = by;
    for (int i = -6; i <= 6; ++i)
      for (int j = -6; j <= 6; ++j) look(x0 + i * sx, y0 + j * sy);
  }
  return best;
}

LineForce rim_line_force(const RimSeries& s) {
  LineForce f;
  f.length = 2 * M_PI * s.scene.radius;
  f.total = s.total_force();
  f.mean = s.q_cos.empty() ? NAN : s.q_cos[0];
  f.min = INFINITY, f.max = -INFINITY;
  for (int k = 0; k < kLineLoadAngles; ++k) {
    const double t = 2 * M_PI * k / kLineLoadAngles, q = s.q(t);
    f.theta.push_back(t), f.q.push_back(q);
    if (q < f.min) f.min = q, f.theta_min = t;
    if (q > f.max) f.max = q, f.theta_max = t;
  }
  return f;
}

LineFigures rim_line_figures(const RimSeries& s, const LineForce& f) {
  LineFigures g;
  g.q0 = s.q(0), g.q45 = s.q(M_PI / 4);
  line_figures_circle(g, s.scene.cx, s.scene.cy, s.scene.radius);
  g.q = f.q;  // rim_line_force's values at the same angles
  return g;
}

}  // namespace plate

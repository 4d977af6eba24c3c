#include "subsurface_closed_forms.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <vector>

namespace dc::closed_form {

AxisStresses hertz_sphere_axis(double z, double a, double p0, double nu) {
  const double t = z / a, s = 1.0 / (1.0 + t * t);
  AxisStresses out;
  out.sigma_z = -p0 * s;
  // (z/a) atan(a/z) -> 1 - ... as z -> inf; 0 at z = 0.
  const double z_atan = t == 0.0 ? 0.0 : t * std::atan(1.0 / t);
  out.sigma_r = -p0 * ((1.0 + nu) * (1.0 - z_atan) - 0.5 * s);
  return out;
}

double hertz_sphere_surface_radial(double r, double a, double p0, double nu) {
  const double rho = std::abs(r) / a;
  if (rho >= 1.0) return (1.0 - 2.0 * nu) * p0 / (3.0 * rho * rho);
  if (rho == 0.0) return -0.5 * (1.0 + 2.0 * nu) * p0;
  // (1 - root^3) / rho^2 = (1 + root + root^2) / (1 + root), free of cancellation near r = 0.
  const double root = std::sqrt((1.0 - rho) * (1.0 + rho));
  return p0 * ((1.0 - 2.0 * nu) / 3.0 * (1.0 + root + root * root) / (1.0 + root) - root);
}

namespace {
/// McEwen's m and n ([J] 7.20): m^2, n^2 = ((A^2 + 4 x^2 z^2)^(1/2) +- A) / 2 with
/// A = a^2 - x^2 + z^2; m has the sign of z, n that of x. The smaller square from m^2 n^2 = x^2 z^2.
void mcewen_mn(double x, double z, double a, double& m, double& n) {
  const double A = a * a - x * x + z * z, root = std::sqrt(A * A + 4.0 * x * x * z * z);
  double m2, n2;
  if (A >= 0.0) {
    m2 = 0.5 * (root + A);
    n2 = m2 > 0.0 ? x * x * z * z / m2 : 0.0;
  } else {
    n2 = 0.5 * (root - A);
    m2 = n2 > 0.0 ? x * x * z * z / n2 : 0.0;
  }
  m = std::copysign(std::sqrt(m2), z);
  n = std::copysign(std::sqrt(n2), x);
  if (z == 0.0) m = std::abs(m);
}
}  // namespace

PlaneStresses mcewen_normal(double x, double z, double a, double p0) {
  double m, n;
  mcewen_mn(x, z, a, m, n);
  const double s = m * m + n * n, k = p0 / a;
  PlaneStresses out;
  if (s == 0.0) return out;  // the contact's edge on the surface: all terms vanish
  out.sigma_xx = -k * (m * (1.0 + (z * z + n * n) / s) - 2.0 * z);
  out.sigma_zz = -k * m * (1.0 - (z * z + n * n) / s);
  out.sigma_xz = -k * n * (m * m - z * z) / s;
  return out;
}

PlaneStresses mcewen_tangential(double x, double z, double a, double q0) {
  double m, n;
  mcewen_mn(x, z, a, m, n);
  const double s = m * m + n * n, k = q0 / a;
  PlaneStresses out;
  if (s == 0.0) {
    out.sigma_xx = -2.0 * k * x;
    return out;
  }
  out.sigma_xx = k * (n * (2.0 - (z * z - m * m) / s) - 2.0 * x);
  out.sigma_zz = -k * n * (m * m - z * z) / s;
  out.sigma_xz = -k * (m * (1.0 + (z * z + n * n) / s) - 2.0 * z);
  return out;
}

PlaneStresses line_contact_axis(double z, double a, double p0) {
  const double root = std::sqrt(a * a + z * z);
  PlaneStresses out;
  out.sigma_zz = -p0 * a / root;
  out.sigma_xx = -p0 * ((a * a + 2.0 * z * z) / (a * root) - 2.0 * z / a);
  return out;
}

namespace {
using JetValue = std::complex<double>;

/// A function of s = r^2 as its Taylor coefficients about one s to third order (complex).
struct RadialJet {
  std::array<JetValue, 4> c{};
};
RadialJet jet_add(const RadialJet& u, const RadialJet& v, JetValue cu = 1.0, JetValue cv = 1.0) {
  RadialJet w;
  for (int n = 0; n < 4; ++n) w.c[n] = cu * u.c[n] + cv * v.c[n];
  return w;
}
RadialJet jet_mul(const RadialJet& u, const RadialJet& v) {
  RadialJet w;
  for (int n = 0; n < 4; ++n)
    for (int k = 0; k <= n; ++k) w.c[n] += u.c[k] * v.c[n - k];
  return w;
}
RadialJet jet_sqrt(const RadialJet& u) {
  RadialJet w;
  w.c[0] = std::sqrt(u.c[0]);
  for (int n = 1; n < 4; ++n) {
    JetValue sum = u.c[n];
    for (int k = 1; k < n; ++k) sum -= w.c[k] * w.c[n - k];
    w.c[n] = sum / (2.0 * w.c[0]);
  }
  return w;
}
RadialJet jet_log(const RadialJet& u) {  // n w_n u_0 = n u_n - sum_k k w_k u_(n-k)
  RadialJet w;
  w.c[0] = std::log(u.c[0]);
  for (int n = 1; n < 4; ++n) {
    JetValue sum = static_cast<double>(n) * u.c[n];
    for (int k = 1; k < n; ++k) sum -= static_cast<double>(k) * w.c[k] * u.c[n - k];
    w.c[n] = sum / (static_cast<double>(n) * u.c[0]);
  }
  return w;
}
RadialJet jet_inverse(const RadialJet& u) {
  RadialJet w;
  w.c[0] = 1.0 / u.c[0];
  for (int n = 1; n < 4; ++n) {
    JetValue sum = 0.0;
    for (int k = 1; k <= n; ++k) sum += u.c[k] * w.c[n - k];
    w.c[n] = -sum / u.c[0];
  }
  return w;
}

/// G_k (header), k = -2 .. 3, at depth zeta (complex) and s = r^2, as jets in s.
struct OmegaAntiderivatives {
  std::array<RadialJet, 6> g;  ///< g[k + 2] = G_k
  const RadialJet& operator()(int k) const { return g[static_cast<std::size_t>(k + 2)]; }
};
OmegaAntiderivatives omega_antiderivatives(double s, JetValue zeta) {
  RadialJet sj, one;
  sj.c = {s, 1.0, 0.0, 0.0};
  one.c = {1.0, 0.0, 0.0, 0.0};
  const JetValue z2 = zeta * zeta, z3 = z2 * zeta, z4 = z3 * zeta;
  const RadialJet R = jet_sqrt(jet_add(sj, one, 1.0, z2));
  const RadialJet L = jet_log(jet_add(R, one, 1.0, zeta));
  const RadialJet s2 = jet_mul(sj, sj);
  OmegaAntiderivatives out;
  out.g[0] = jet_inverse(R);
  out.g[1] = L;
  out.g[2] = jet_add(L, R, zeta, -1.0);  // Omega = z L - R
  // G_1 = (z^2/2 - s/4) L - 3 z R / 4
  out.g[3] = jet_add(jet_mul(jet_add(one, sj, 0.5 * z2, -0.25), L), R, 1.0, -0.75 * zeta);
  // G_2 = (z^3/6 - s z/4) L - 11 z^2 R / 36 + s R / 9
  out.g[4] = jet_add(jet_add(jet_mul(jet_add(one, sj, z3 / 6.0, -0.25 * zeta), L), R, 1.0, -11.0 / 36.0 * z2),
                     jet_mul(sj, R), 1.0, 1.0 / 9.0);
  // G_3 = (z^4/24 - s z^2/8 + s^2/64) L - 25 z^3 R / 288 + 55 s z R / 576
  const RadialJet poly = jet_add(jet_add(one, sj, z4 / 24.0, -0.125 * z2), s2, 1.0, 1.0 / 64.0);
  out.g[5] = jet_add(jet_add(jet_mul(poly, L), R, 1.0, -25.0 / 288.0 * z3), jet_mul(sj, R), 1.0, 55.0 / 576.0 * zeta);
  return out;
}

/// d^(i+j) f / dx^i dy^j of f(x^2 + y^2), i + j <= 3, from the jet of f in s.
JetValue radial_derivative(const RadialJet& f, int i, int j, double x, double y) {
  const JetValue f1 = f.c[1], f2 = 2.0 * f.c[2], f3 = 6.0 * f.c[3];
  const auto d = [&](int p, int q, double u, double v) -> JetValue {  // derivative p in u, q in v
    switch (10 * p + q) {
      case 0: return f.c[0];
      case 10: return 2.0 * u * f1;
      case 20: return 2.0 * f1 + 4.0 * u * u * f2;
      case 11: return 4.0 * u * v * f2;
      case 30: return 12.0 * u * f2 + 8.0 * u * u * u * f3;
      case 21: return 4.0 * v * f2 + 8.0 * u * u * v * f3;
      default: return 0.0;
    }
  };
  return i >= j ? d(i, j, x, y) : d(j, i, y, x);
}

/// One term c d^(i+j+m) Omega / dx^i dy^j dz^m (times z if with_z) of a point load's 2 pi sigma.
struct KernelTerm {
  double c;
  int i, j, m;
  bool with_z;
};
using KernelTerms = std::vector<KernelTerm>;

/// The distribution's stress from its point-load kernel (header): (p0/a) sum of c (z) [Im Theta(z1) -
/// a Re Theta'(z1)], Theta = d^(i+j) G_(3-m) / dx^i dy^j.
double hertz_distribution_stress(const KernelTerms& terms, const OmegaAntiderivatives& g, double x, double y,
                                 double z, double a, double amplitude) {
  double sum = 0.0;
  for (const KernelTerm& t : terms) {
    if (t.with_z && z == 0.0) continue;
    const JetValue theta = radial_derivative(g(3 - t.m), t.i, t.j, x, y);
    const JetValue theta1 = radial_derivative(g(2 - t.m), t.i, t.j, x, y);
    sum += t.c * (t.with_z ? z : 1.0) * (theta.imag() - a * theta1.real());
  }
  return amplitude / a * sum;
}

/// Love's (pressure) and Cerruti's (shear along +x) point loads, 2 pi sigma in terms of Omega
/// (subsurface_influence.hpp), by component xx, yy, zz, yz, xz, xy.
std::array<KernelTerms, 6> pressure_kernel(double nu) {
  return {KernelTerms{{2.0 * nu, 0, 0, 3, false}, {-1.0, 2, 0, 2, true}, {-(1.0 - 2.0 * nu), 2, 0, 1, false}},
          KernelTerms{{2.0 * nu, 0, 0, 3, false}, {-1.0, 0, 2, 2, true}, {-(1.0 - 2.0 * nu), 0, 2, 1, false}},
          KernelTerms{{1.0, 0, 0, 3, false}, {-1.0, 0, 0, 4, true}},
          KernelTerms{{-1.0, 0, 1, 3, true}},
          KernelTerms{{-1.0, 1, 0, 3, true}},
          KernelTerms{{-(1.0 - 2.0 * nu), 1, 1, 1, false}, {-1.0, 1, 1, 2, true}}};
}
std::array<KernelTerms, 6> shear_x_kernel(double nu) {
  return {KernelTerms{{2.0 * (1.0 + nu), 1, 0, 2, false}, {2.0 * nu, 3, 0, 0, false}, {-1.0, 3, 0, 1, true}},
          KernelTerms{{2.0 * nu, 1, 0, 2, false}, {2.0 * nu, 1, 2, 0, false}, {-1.0, 1, 2, 1, true}},
          KernelTerms{{-1.0, 1, 0, 3, true}},
          KernelTerms{{-1.0, 1, 1, 2, true}},
          KernelTerms{{1.0, 0, 0, 3, false}, {-1.0, 2, 0, 2, true}},
          KernelTerms{{1.0, 0, 1, 2, false}, {2.0 * nu, 2, 1, 0, false}, {-1.0, 2, 1, 1, true}}};
}

SpatialStresses hertz_distribution_field(const std::array<KernelTerms, 6>& kernel, double x, double y, double z,
                                         double a, double amplitude) {
  const OmegaAntiderivatives g = omega_antiderivatives(x * x + y * y, JetValue(z, a));
  std::array<double, 6> v{};
  for (int c = 0; c < 6; ++c) v[c] = hertz_distribution_stress(kernel[c], g, x, y, z, a, amplitude);
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}
}  // namespace

SpatialStresses hertz_sphere_normal_field(double x, double y, double z, double a, double p0, double nu) {
  return hertz_distribution_field(pressure_kernel(nu), x, y, z, a, p0);
}

SpatialStresses hertz_sphere_shear_field(double x, double y, double z, double a, double q0, double nu) {
  return hertz_distribution_field(shear_x_kernel(nu), x, y, z, a, q0);
}

SpatialStresses hamilton_sliding_sphere(double x, double y, double z, double a, double p0, double mu, double nu) {
  const SpatialStresses n = hertz_sphere_normal_field(x, y, z, a, p0, nu);
  const SpatialStresses q = hertz_sphere_shear_field(x, y, z, a, mu * p0, nu);
  return {n.sigma_xx + q.sigma_xx, n.sigma_yy + q.sigma_yy, n.sigma_zz + q.sigma_zz,
          n.sigma_yz + q.sigma_yz, n.sigma_xz + q.sigma_xz, n.sigma_xy + q.sigma_xy};
}

}  // namespace dc::closed_form

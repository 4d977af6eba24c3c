// The closed forms of the flash temperature (core/thermal_closed_forms, core/moving_heat_source):
// the line source's antiderivative M(u) against a quadrature of e^-t K0(|t|), the scaled Bessel
// function's two branches, Jaeger's band (B1) against its low- and high-Peclet limits (B2), (B3)
// at the order their remainders vanish, Blok's Hertzian maximum (H1) against his 1.11 and the
// exact finite-Pe form (H2) against (H1). Measured errors are printed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "adaptive_quadrature.hpp"
#include "moving_heat_source.hpp"
#include "thermal_closed_forms.hpp"

namespace thermal_closed_form_tests {
constexpr double kPi = std::numbers::pi;

TEST(ThermalClosedForms, ScaledBesselBranchesAgree) {
  // Above x = 30 the asymptotic series; e^x K_nu(x) is still representable up to ~700 directly.
  for (double x : {30.0, 40.0, 100.0, 500.0})
    for (int nu : {0, 1}) {
      const double direct = std::exp(x) * std::cyl_bessel_k(static_cast<double>(nu), x);
      EXPECT_NEAR(dc::scaled_bessel_k(nu, x), direct, 1e-13 * direct) << "nu " << nu << " x " << x;
    }
}

TEST(ThermalClosedForms, LineSourceIntegralMatchesQuadrature) {
  // M(u) = int_0^u e^-t K0(|t|) dt; the logarithm at t = 0 is integrable, the adaptive rule
  // resolves it (t = u s^2 makes it s ln s, bounded).
  const auto quadrature = [](double u) {
    const auto f = [u](double s) {
      if (s == 0.0) return 0.0;
      const double t = u * s * s;
      return 2.0 * u * s * std::exp(-t - std::abs(t)) * dc::scaled_bessel_k(0, std::abs(t));
    };
    return dc::integrate_adaptive(f, 0.0, 1.0, {1e-14, 0.0, 2000});
  };
  double worst = 0.0;
  for (double u : {1e-4, 0.01, 0.5, 1.0, 3.0, 29.0, 31.0, 200.0}) {
    for (double sign : {1.0, -1.0}) {
      const double exact = quadrature(sign * u), m = dc::moving_line_source_integral(sign * u);
      worst = std::max(worst, std::abs(m - exact) / std::abs(exact));
      EXPECT_NEAR(m, exact, 1e-11 * std::abs(exact)) << "u = " << sign * u;
    }
  }
  std::printf("M(u) against quadrature: worst relative %.2e\n", worst);
  EXPECT_NEAR(dc::moving_line_source_integral(1e4), 1.0, 1e-12);  // int_0^inf e^-t K0 = 1
}

TEST(ThermalClosedForms, BandApproachesJaegerLowPeclet) {
  // (B2): the remainder of the expansion is O(Pe^2 ln^2 Pe) (the first odd term drops out of the
  // centre and the mean; the next even ones carry Pe^2 and a logarithm); bound with constant 1.
  for (double pe : {1e-2, 1e-3}) {
    const double bound = pe * pe * std::log(pe) * std::log(pe);
    const double mean = dc::thermal::band_mean(pe), centre = dc::thermal::band_temperature(0.0, pe);
    std::printf("band Pe %g: mean %.9f (low-Pe %.9f), centre %.9f (low-Pe %.9f), bound %.1e\n", pe, mean,
                dc::thermal::band_mean_low_peclet(pe), centre, dc::thermal::band_centre_low_peclet(pe), bound);
    EXPECT_NEAR(mean, dc::thermal::band_mean_low_peclet(pe), bound);
    EXPECT_NEAR(centre, dc::thermal::band_centre_low_peclet(pe), bound);
    // The maximum lies off the centre by O(Pe ln Pe) only: within the same bound of it.
    EXPECT_NEAR(dc::thermal::band_max(pe), centre, bound);
  }
}

TEST(ThermalClosedForms, BandApproachesJaegerHighPeclet) {
  // (B3): conduction along the surface, dropped by the 1-D limit, is O(1/Pe) relative.
  for (double pe : {100.0, 1000.0}) {
    const double mean = dc::thermal::band_mean(pe), max = dc::thermal::band_max(pe);
    const double mean_1d = dc::thermal::one_dimensional_mean(pe), max_1d = dc::thermal::one_dimensional_max(pe);
    std::printf("band Pe %g: mean %.9f (1-D %.9f, %.2e), max %.9f (1-D %.9f, %.2e)\n", pe, mean, mean_1d,
                mean / mean_1d - 1.0, max, max_1d, max / max_1d - 1.0);
    EXPECT_NEAR(mean / mean_1d, 1.0, 1.0 / pe);
    EXPECT_NEAR(max / max_1d, 1.0, 1.0 / pe);
    // Jaeger's constants in units q b / (K sqrt(V b / kappa)) = q b / (K sqrt(2 Pe)).
    EXPECT_NEAR(mean_1d * std::sqrt(2.0 * pe), 1.064, 5e-4);
    EXPECT_NEAR(max_1d * std::sqrt(2.0 * pe), 1.596, 5e-4);
  }
}

TEST(ThermalClosedForms, BlokHertzianMaximum) {
  const dc::thermal::BlokMaximum m = dc::thermal::blok_line_maximum();
  std::printf("Blok: theta_max sqrt(Pe) = %.8f q0 b/K at x = %.6f b; %.6f in the mean flux\n", m.coefficient, m.xi,
              m.coefficient * 4.0 / kPi);
  // Blok's 1.11 (mean flux pi q0 / 4) is given to three digits.
  EXPECT_NEAR(m.coefficient * 4.0 / kPi, 1.11, 0.005);
  EXPECT_GT(m.xi, -1.0);
  EXPECT_LT(m.xi, 0.0);
  // The exact finite-Pe temperature (H2) at Blok's point tends to (H1) at O(1/Pe) relative.
  for (double pe : {100.0, 1000.0}) {
    const double exact = dc::thermal::hertz_line_temperature(m.xi, pe), limit = m.coefficient / std::sqrt(pe);
    std::printf("Hertzian flux Pe %g at Blok's point: %.9f (1-D %.9f, %.2e)\n", pe, exact, limit, exact / limit - 1.0);
    EXPECT_NEAR(exact / limit, 1.0, 1.0 / pe);
  }
}

TEST(ThermalClosedForms, StationaryAndHighPecletConstants) {
  // Tian & Kennedy 1994 quote the stationary square's 1.122 and 0.946 (q a / K, half-side a).
  EXPECT_NEAR(dc::thermal::square_centre_stationary(), 1.122, 5e-4);
  EXPECT_NEAR(dc::thermal::square_mean_stationary(), 0.946, 5e-4);
  // The circle's high-Pe mean in Archard's form 0.31 Q / (a K) sqrt(kappa / (V a)), Q = pi a^2 q.
  EXPECT_NEAR(dc::thermal::circle_mean_high_peclet(1.0) * std::sqrt(2.0) / kPi, 0.31, 5e-3);
  // (C2)'s integral by quadrature: (2 / sqrt(pi)) (1 / (pi a^2)) int (2/3) (2c)^(3/2) dy / sqrt(2), a = 1.
  const double chords = dc::integrate_adaptive(
      [](double y) { return (2.0 / 3.0) * std::pow(2.0 * std::sqrt(std::max(0.0, 1.0 - y * y)), 1.5); }, -1.0, 1.0,
      {1e-13, 0.0, 400});
  EXPECT_NEAR(dc::thermal::circle_mean_high_peclet(1.0), 2.0 / std::sqrt(kPi) * chords / (kPi * std::sqrt(2.0)),
              1e-10);
}

TEST(ThermalClosedForms, HertzianCircleMean) {
  // (H3)'s J = 32 sqrt(2) / 15 against a quadrature of (H1) over the band, and the disc's mean
  // against a quadrature over the chords (each chord (H1) scaled by c^(3/2), a = 1).
  const double J = dc::integrate_adaptive([](double xi) { return dc::thermal::hertz_line_high_peclet(xi, 1.0); },
                                          -1.0, 1.0, {1e-11, 0.0, 400}) *
                   std::sqrt(2.0 * kPi);
  EXPECT_NEAR(J, 32.0 * std::sqrt(2.0) / 15.0, 1e-9);
  const double chords = dc::integrate_adaptive(
      [J](double y) { return std::pow(std::max(0.0, 1.0 - y * y), 1.25) * J; }, -1.0, 1.0, {1e-12, 0.0, 400});
  const double mean = chords / (kPi * std::sqrt(2.0 * kPi));  // (1 / pi) int c^(5/2) J dy / sqrt(2 pi), Pe = 1
  std::printf("Hertzian circle, high Pe: mean %.6f q0 a / (K sqrt(Pe)); Archard's form %.4f\n", mean,
              mean * 3.0 / (2.0 * kPi) * std::sqrt(2.0));
  EXPECT_NEAR(dc::thermal::hertz_circle_mean_high_peclet(1.0), mean, 1e-9);
}

}  // namespace thermal_closed_form_tests

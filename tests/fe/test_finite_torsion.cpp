// Torsion of a finite body. The sign convention of angle and moment is the local torsion
// problem's (tangential_problem.hpp; the paper's tau+ is the traction ON THE BODY): a twist
// +beta of the body meets a twisting moment M_z < 0, and a prescribed M_z > 0 turns it by
// beta < 0, as a prescribed F_x > 0 shifts it by s_x < 0.
// Reissner-Sagoci: a rigid flat punch of radius a bonded to the half-space and twisted by beta
// meets M = 16 G a^3 beta / 3 (G of the half-space); here a flat-ended cylinder 1000 times
// stiffer than the half-space in full stick (mu = 10), on two grids.
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "fe_test_bodies.hpp"
#include "finite_contact.hpp"

namespace dc {
namespace {

constexpr double kE = 2.1e11, kNu = 0.3;

double reissner_sagoci_moment(double a, double beta) {
  const double G = kE / (2.0 * (1.0 + kNu));
  return 16.0 * G * a * a * a * beta / 3.0;
}

/// The cylinder (radius and height a, 1000 times stiffer than the half-space) under a normal
/// force P on an n x n grid over +-1.25 a. The tangential resultant is held at zero (no net
/// shear, as for Reissner-Sagoci's punch); the twist is given by angle or by moment.
class StiffPunch {
 public:
  StiffPunch(double a, int n, double P = 1e5) : P_(P) {
    const FeBodySpec s = fe::testing::stiff_flat_cylinder(a, kE, kNu);
    const Grid g = Grid::make(3, n, n, -1.25 * a, 1.25 * a, -1.25 * a, 1.25 * a);
    contact_ = std::make_unique<FiniteContact>(s, g, Elastic::from_E_nu(kE, kNu));
    solver_.backend = Backend::native;
    solver_.tol = 1e-10;
  }

  /// Twisted by the angle beta (rad) from the unloaded state.
  TangentialSolution twist(double beta) { return solve({ModeControl::Kind::amplitude, beta}); }
  /// Turned by the twisting moment M (N m, of the tractions on the body) from the unloaded state.
  TangentialSolution turn(double M) { return solve({ModeControl::Kind::resultant, M}); }

 private:
  TangentialSolution solve(ModeControl rotation) {
    TangentialProblem& problem = contact_->tangential_problem(FrictionLaw::coulomb(10.0));
    problem.reset();
    TangentialLoad load;
    load.normal = {Control::force, P_};
    load.modes = {ModeControl{ModeControl::Kind::resultant, 0.0}, ModeControl{ModeControl::Kind::resultant, 0.0},
                  rotation};
    return problem.step(load, solver_);
  }

  double P_;
  std::unique_ptr<FiniteContact> contact_;
  SolverOptions solver_;
};

TEST(FiniteTorsion, AngleAndMomentHaveTheLocalProblemsSigns) {
  // A coarse grid (the signs do not depend on it; the accuracy is the next test's).
  const double a = 0.005, beta = 1e-4;
  StiffPunch punch(a, 12);
  const TangentialSolution twisted = punch.twist(beta);
  ASSERT_EQ(twisted.report.status, SolveStatus::converged) << twisted.report.message;
  EXPECT_EQ(twisted.n_slip, 0) << "mu = 10 holds the punch in full stick";
  EXPECT_DOUBLE_EQ(twisted.amplitudes[2], beta);
  const double M = twisted.resultants[2];
  EXPECT_LT(M, 0.0) << "a twist +beta of the body meets a moment on it of the opposite sense";
  EXPECT_NEAR(-M / reissner_sagoci_moment(a, beta), 1.0, 0.25);

  // That moment prescribed turns the body by -beta: the moment on the body and its rotation
  // have opposite signs both ways. Full stick is linear: the same angle, up to the tolerance.
  const TangentialSolution turned = punch.turn(M);
  ASSERT_EQ(turned.report.status, SolveStatus::converged) << turned.report.message;
  EXPECT_NEAR(turned.resultants[2], M, 1e-6 * std::abs(M));
  EXPECT_NEAR(turned.amplitudes[2], beta, 1e-4 * beta);
  const TangentialSolution back = punch.turn(-M);
  ASSERT_EQ(back.report.status, SolveStatus::converged) << back.report.message;
  EXPECT_NEAR(back.amplitudes[2], -beta, 1e-4 * beta);
}

/// |M| / M_RS - 1 on an n x n grid over +-1.25 a.
double moment_error(int n) {
  const double a = 0.005, beta = 1e-4;
  StiffPunch punch(a, n);
  const TangentialSolution s = punch.twist(beta);
  EXPECT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
  EXPECT_EQ(s.n_slip, 0);
  const double M = -s.resultants[2];  // a twist +beta meets -M on the body
  const double err = M / reissner_sagoci_moment(a, beta) - 1.0;
  std::printf("[ Reissner-Sagoci ] %d^2 (h = %.4f a): M / M_RS - 1 = %+.4f, net force / (M/a) = %.2e\n", n,
              2.5 / n, err, std::hypot(s.resultants[0], s.resultants[1]) * a / std::abs(M));
  return err;
}

TEST(FiniteTorsionValidation, ReissnerSagociMomentConvergesWithTheGrid) {
  // Piecewise-constant tractions on a staircase disk miss the edge's (a^2 - r^2)^(-1/2)
  // singularity over the outer row of elements: an error of the order of h / a, too stiff
  // nowhere (the moment comes out low). h = 0.104 a on 24^2, 0.0625 a on 40^2.
  const double coarse = moment_error(24), fine = moment_error(40);
  EXPECT_LT(coarse, 0.0);
  EXPECT_LT(fine, 0.0);
  // The error falls at least as fast as h (24 / 40 = 0.6) ...
  EXPECT_LT(std::abs(fine), 0.6 * std::abs(coarse));
  // ... and on the finer grid it is within h / a (6.25 %).
  EXPECT_LT(std::abs(fine), 2.5 / 40);
}

}  // namespace
}  // namespace dc

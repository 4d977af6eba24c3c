// A tangential step whose normal solve fails (every backend made to fail by a test's fault
// source, nlp/fault_injection.hpp) throws SolverFailure; the failure is not kept: the same step
// after reset(), the backend recovered, is solved again and converges to the step of a fresh
// problem (the normal cache of nlp/tangential_coupling.cpp kept the failed solve and threw again).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "errors.hpp"
#include "fault_injection.hpp"
#include "tangential_problem.hpp"

namespace dc {
namespace {

TEST(TangentialFailure, AFailedNormalSolveIsNotKeptForTheSameStep) {
  const Grid g = Grid::make(3, 16, 16, -2.6e-4, 2.6e-4, -2.6e-4, 2.6e-4);
  std::vector<double> h(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) h[g.index(i, j)] = (g.xc(i) * g.xc(i) + g.yc(j) * g.yc(j)) / 0.02;
  const MaterialPair steel{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)};
  TangentialLoad load;
  load.normal = {Control::force, 100.0};
  load.modes[0] = {ModeControl::Kind::resultant, -15.0};
  SolverOptions native;
  native.backend = Backend::native;
  TangentialProblem failing(g, steel, h, FrictionLaw::coulomb(0.3));
  set_fault_source([](const std::string& target) { return target == "outer" ? Fault::none : Fault::fail; });
  EXPECT_THROW(failing.step(load, native), SolverFailure);
  set_fault_source(nullptr);
  failing.reset();
  const TangentialSolution again = failing.step(load, native);
  TangentialProblem fresh(g, steel, h, FrictionLaw::coulomb(0.3));
  const TangentialSolution reference = fresh.step(load, native);
  ASSERT_EQ(again.report.status, SolveStatus::converged) << again.report.message;
  EXPECT_NEAR(again.amplitudes[0], reference.amplitudes[0], 1e-12 * std::abs(reference.amplitudes[0]));
  EXPECT_NEAR(again.normal.approach, reference.normal.approach, 1e-12 * reference.normal.approach);
}

}  // namespace
}  // namespace dc

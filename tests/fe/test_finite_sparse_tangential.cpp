// The sparse saddle form (a) of the tangential problem against the condensed program (b) on a
// tiny body (seconds): Ipopt's saddle point over (tau, v, a), with the friction disks
// |tau| <= f(p) for the sparse form's own pressure, gives the condensed program's tractions and
// rigid shift, certified with the condensed operators (friction law (2.4)-(2.5), gap function
// (4.24)); partial slip, so the disks are active. NLopt takes the body's rows densely on such a
// body, and is the fallback of `auto` when Ipopt fails. Larger bodies: slow_finite_saddle.
#include <cstdlib>

#include <gtest/gtest.h>

#include "errors.hpp"
#include "saddle_form.hpp"
#include "sparse_tangential_pair.hpp"

namespace dc {
namespace {

using fe::testing::expect_same_point;
using fe::testing::shift_by_force;
using fe::testing::solve_both;

constexpr std::array<int, 3> kTiny{2, 2, 1};

TEST(FiniteSparseTangential, ShiftByForceAgreesWithTheCondensedProgram) {
  const fe::testing::Pair r = solve_both(shift_by_force(0.6), 8, kTiny, "ipopt");
  expect_same_point(r);
  EXPECT_EQ(r.sparse.report.backend, "ipopt");
  EXPECT_LT(r.sparse.amplitudes[0], 0.0) << "a force +F_x on the body meets a shift -s_x";
}

}  // namespace
}  // namespace dc

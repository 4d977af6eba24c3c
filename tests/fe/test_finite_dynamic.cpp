// Finite contact in every time step (problem "dynamic" with an fe_body), the fast checks:
// momentum step by step (bdf1: m (V_{K+1} - V_K) = dt (F_loads + F_contact) at every accepted
// step, to the step's Newton tolerance) and bad input naming its key. The Hertz impacts are in
// slow_finite_dynamic.
#include <gtest/gtest.h>

#include "errors.hpp"
#include "finite_drop.hpp"

namespace dc::dynamics {
namespace {

using namespace dc::dynamics::test;

TEST(FiniteDynamic, MomentumBalancesStepByStep) {
  // bdf1: m dV = dt F exactly at the converged step; the step's residual is relative 1e-9 of
  // the speed (stepper tolerance 10 x solver.tol), so the error per step is below 1e-7 m v0.
  nlohmann::json doc = drop_case(1000.0 * kE, "bdf1", 20);
  doc["loads"] = {{"force", {{"z", {{"value", -2.0}}}, {"x", {{"value", 0.5}}}}}};
  doc["time"]["t_end"] = 0.6 * doc["time"]["t_end"].get<double>();
  const Drop d = run_drop(doc);
  ASSERT_TRUE(d.result.completed) << d.result.status;
  // The run's mass is the mesh's: a hemisphere of kR and kRho less its faceting (straight-edged
  // tetrahedra of size h ~ R/4 away from the contact inscribe the sphere: ~3 h^2 / (8 R^2) = 2 %).
  EXPECT_NEAR(d.mass / (kRho * 2.0 / 3.0 * M_PI * kR * kR * kR), 0.98, 0.02);
  EXPECT_LT(d.mass, kRho * 2.0 / 3.0 * M_PI * kR * kR * kR);
  EXPECT_GT(d.peak, 0.0);
  EXPECT_LT(d.max_momentum_error, 1e-7 * d.mass * kV0) << "impulse over the run " << d.impulse;
  EXPECT_LT(d.result.momentum_imbalance, 1e-8);
}

std::string input_error_key(const nlohmann::json& doc) {
  try {
    const Case c = build_case(doc);
    DynamicSimulation sim(c, make_finite_body(c));
  } catch (const InputError& e) {
    return e.key();
  }
  return "(no error)";
}

TEST(FiniteDynamic, BadInputNamesItsKey) {
  const nlohmann::json good = drop_case(1000.0 * kE, "bdf2", 40);
  nlohmann::json doc = good;
  doc["body"]["initial"]["omega"] = {0.0, 5.0, 0.0};  // rolling
  EXPECT_EQ(input_error_key(doc), "body.initial.omega");
  doc = good;
  doc["contact_model"] = "steady";
  EXPECT_EQ(input_error_key(doc), "contact_model");
  doc = good;
  doc["loads"] = {{"moment", {{"y", {{"value", 1.0}}}}}};
  EXPECT_EQ(input_error_key(doc), "loads.moment.y");
  doc = good;
  doc["fe_body"].erase("density");
  EXPECT_EQ(input_error_key(doc), "fe_body.density");
  doc = good;
  doc["profile"] = {{"type", "sphere"}, {"radius", kR}};
  EXPECT_EQ(input_error_key(doc), "profile");
  doc = good;
  doc["body"]["mass"] = 1.0;  // the mesh's is 16 g
  EXPECT_EQ(input_error_key(doc), "body.mass");
  doc = good;
  doc["grid"] = {{"nx", 24}, {"ny", 24}, {"extent", 1.5}};
  EXPECT_EQ(input_error_key(doc), "grid.extent");
}

}  // namespace
}  // namespace dc::dynamics

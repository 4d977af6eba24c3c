#pragma once
// Dynamic case documents for the tests: a steel-on-steel 3-D case for the contact-wrench tests
// (the profile, the grid and the body given, a vertical load, the normal model), and the
// bundled bowling ball rolling freely.
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {

inline nlohmann::json steel_dynamic_case(const std::string& name, const nlohmann::json& profile,
                                         const nlohmann::json& grid, const nlohmann::json& body, double load,
                                         double dt, const std::string& normal_model) {
  return {{"schema", "dyncontact/1"},
          {"name", name},
          {"problem", "dynamic"},
          {"dimension", 3},
          {"materials", {{"body", {{"E", 2.1e11}, {"nu", 0.3}}}, {"base", {{"E", 2.1e11}, {"nu", 0.3}}}}},
          {"profile", profile},
          {"grid", grid},
          {"body", body},
          {"loads", {{"force", {{"z", {{"value", -load}}}}}}},
          {"time", {{"dt", dt}, {"t_end", 10.0 * dt}}},
          {"normal_model", normal_model}};
}

/// examples/bowling-ball on an n x n grid rolling freely at 3 m/s from t = 0 (omega = V / R,
/// not yet the contact's creepage), the transient model, BDF2, dt = 1e-4 s: kappa != 0, the
/// body's tangential contact mode decaying to steady rolling (test_dynamic_free_rolling).
inline nlohmann::json free_rolling_bowling_ball(int n, double t_end) {
  nlohmann::json doc = example_json("bowling-ball");
  doc["grid"]["nx"] = doc["grid"]["ny"] = n;
  doc["time"] = {{"dt", 1e-4}, {"t_end", t_end}, {"scheme", "bdf2"}};
  doc["contact_model"] = "transient";
  const double V = 3.0, R = doc["body"]["radius"].get<double>();
  doc["body"]["initial"]["velocity"] = {V, 0, 0};
  doc["body"]["initial"]["omega"] = {0, V / R, 0};
  return doc;
}

}  // namespace dc::test

#pragma once
// A steel-on-steel 3-D dynamic case document for the contact-wrench tests: the profile, the
// grid and the body given, a vertical load, the normal model.
#include <string>

#include <nlohmann/json.hpp>

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

}  // namespace dc::test

// The "materials" block (CASES.md): the body's and the half-space's elastic constants (E or G with
// nu, or rigid), into MaterialPair (core/material.hpp).
#include "case_readers.hpp"

#include <string>

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

Elastic read_elastic(const json& j, const std::string& path) {
  JsonBlock o(j, path);
  o.allow({"E", "G", "nu", "rigid", "yield", "fatigue", "thermal"});
  for (const char* k : {"yield", "fatigue"})
    if (o.has(k) && o.boolean_or("rigid", false)) throw InputError(o.key(k), "a rigid body has no stresses");
  if (o.boolean_or("rigid", false)) {
    for (const char* k : {"E", "G", "nu"})
      if (o.has(k)) throw InputError(o.key(k), "a rigid body takes no elastic constants");
    return Elastic::make_rigid();
  }
  const bool hasE = o.has("E"), hasG = o.has("G");
  if (hasE && hasG) throw InputError(o.key("G"), "give either E or G, not both");
  if (!hasE && !hasG)
    throw InputError(o.key("E"), "missing required key (give E or G with nu, or \"rigid\": true)");
  const double nu = o.number("nu");
  return hasE ? Elastic::from_E_nu(o.number("E"), nu, path) : Elastic::from_G_nu(o.number("G"), nu, path);
}

/// materials.<body>.<key> when the case gives it (the block's shape checked by read_materials).
const json* body_entry(const json& materials, const char* body, const char* key) {
  if (!materials.is_object() || !materials.contains(body) || !materials[body].is_object()) return nullptr;
  return materials[body].contains(key) ? &materials[body][key] : nullptr;
}

std::optional<YieldSpec> read_yield(const json& materials, const char* body) {
  const json* entry = body_entry(materials, body, "yield");
  if (!entry) return std::nullopt;
  const std::string path = std::string("materials.") + body + ".yield";
  JsonBlock o(*entry, path);
  o.allow({"von_mises", "tresca_k"});
  if (o.has("von_mises") == o.has("tresca_k"))
    throw InputError(path, "give one of von_mises (the yield stress Y, Pa) or tresca_k (the shear yield k, Pa)");
  YieldSpec y;
  y.von_mises = o.has("von_mises");
  y.strength = o.positive(y.von_mises ? "von_mises" : "tresca_k");
  return y;
}

std::optional<FatigueSpec> read_fatigue(const json& materials, const char* body) {
  const json* entry = body_entry(materials, body, "fatigue");
  if (!entry) return std::nullopt;
  const std::string path = std::string("materials.") + body + ".fatigue";
  JsonBlock o(*entry, path);
  o.allow({"dang_van"});
  JsonBlock d(o.at("dang_van"), path + ".dang_van");
  d.allow({"alpha", "beta"});
  FatigueSpec f;
  f.alpha = d.number("alpha");
  f.beta = d.positive("beta");
  return f;
}

}  // namespace

BodyFatigue read_fatigue_limits(const json& materials) {
  return {read_fatigue(materials, "body"), read_fatigue(materials, "base")};
}

BodyYields read_yields(const json& materials) {
  return {read_yield(materials, "body"), read_yield(materials, "base")};
}

/// `body_from_mesh` (problem finite): the body's elasticity is its mesh's (fe_body), so the
/// block gives the half-space ("base") only and the pair's body is rigid.
MaterialPair read_materials(const json& j, bool body_from_mesh) {
  JsonBlock o(j, "materials");
  if (body_from_mesh) {
    o.allow({"base", "allow_large_strain"});
    return MaterialPair{Elastic::make_rigid(), read_elastic(o.at("base"), "materials.base")};
  }
  o.allow({"body", "base", "allow_large_strain"});
  (void)o.boolean_or("allow_large_strain", false);  // read into Case by build_case
  MaterialPair m;
  m.body = read_elastic(o.at("body"), "materials.body");
  m.base = read_elastic(o.at("base"), "materials.base");
  if (m.body.rigid && m.base.rigid)
    throw InputError("materials", "both bodies are rigid: at least one must be elastic");
  return m;
}

}  // namespace dc

// materials.<body>.thermal and the "temperature" block (CASES.md) into ThermalSpec.
#include "case_readers.hpp"

#include <string>

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

std::optional<ThermalProperties> read_surface(const json& materials, const char* body) {
  if (!materials.is_object() || !materials.contains(body) || !materials[body].is_object() ||
      !materials[body].contains("thermal"))
    return std::nullopt;
  const std::string path = std::string("materials.") + body + ".thermal";
  JsonBlock o(materials[body]["thermal"], path);
  o.allow({"conductivity", "diffusivity"});
  return ThermalProperties::make(o.positive("conductivity"), o.positive("diffusivity"), path);
}

ThermalSpec::Model read_model(const json& block) {
  JsonBlock o(block, "temperature");
  return o.has("model") && o.choice("model", "quasi_steady", {"quasi_steady", "transient"}) == "transient"
             ? ThermalSpec::Model::transient
             : ThermalSpec::Model::quasi_steady;
}

HeatPartition read_partition(const json& block) {
  JsonBlock o(block, "temperature");
  o.allow({"partition", "model"});
  HeatPartition p;
  if (!o.has("partition")) return p;
  const json& v = o.at("partition");
  if (v.is_number()) {
    const double f = o.number("partition");
    if (!(f >= 0.0 && f <= 1.0))
      throw InputError("temperature.partition", "a fraction of the heat into the base must be in [0, 1], got " +
                                                    std::to_string(f));
    p.rule = HeatPartition::Rule::fixed;
    p.base_fraction = f;
    return p;
  }
  const std::string rule = o.choice("partition", "auto", {"auto", "equal_mean", "equal_max", "pointwise"});
  p.rule = rule == "equal_max"   ? HeatPartition::Rule::equal_max
           : rule == "pointwise" ? HeatPartition::Rule::pointwise
                                 : HeatPartition::Rule::equal_mean;
  return p;
}

}  // namespace

ThermalSpec read_thermal(const json& materials, const json* temperature) {
  ThermalSpec t;
  t.body = read_surface(materials, "body");
  t.base = read_surface(materials, "base");
  if (temperature) {
    t.partition = read_partition(*temperature);
    t.model = read_model(*temperature);
  }
  return t;
}

}  // namespace dc

// The names of the dynamic models (summary.json, stdout).
#include "dynamic_spec.hpp"

namespace dc {

const char* to_string(NormalModel model) { return model == NormalModel::dynamic ? "dynamic" : "quasi_static"; }

const char* to_string(ContactModel model) {
  switch (model) {
    case ContactModel::transient: return "transient";
    case ContactModel::steady: return "steady";
    case ContactModel::automatic: return "auto";
  }
  return "unknown";
}

}  // namespace dc

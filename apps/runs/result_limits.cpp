#include "result_limits.hpp"
#include "summary_entries.hpp"

#include <iostream>

namespace dc::runs {

ContactSize measured_contact_size(const Case& c, const nlohmann::json& s) {
  ContactSize size;
  const bool two_d = c.dimension == 2;
  size.half_width_x = s.value(two_d ? "contact_half_width" : "contact_half_width_x", 0.0);
  size.half_width_y = two_d ? 0.0 : s.value("contact_half_width_y", 0.0);
  size.edge_fraction = s.value("contact_edge_fraction", 0.0);
  size.face_element_size = s.value("contact_face_element_size", 0.0);
  if (s.value("n_contact", 0) > 0 && s.contains("elements_across_contact")) {
    const auto& n = s["elements_across_contact"];
    size.across_x = n.is_array() ? n[0].get<int>() : n.get<int>();
    size.across_y = n.is_array() ? n[1].get<int>() : size.across_x;
  }
  return size;
}

bool report_limits(const std::vector<ResultLimit>& limits, const std::string& dir) {
  bool known_wrong = false;
  for (const ResultLimit& l : limits) {
    std::cerr << (l.error ? "error: " : "warning: ") << l.key << ": " << l.message
              << (l.error ? " (results written to " + dir + " for inspection)" : "") << '\n';
    known_wrong = known_wrong || l.error;
  }
  return known_wrong;
}

std::vector<ResultLimit> attach_result_limits(const Case& c, nlohmann::json& summary) {
  std::vector<ResultLimit> limits = result_limits(c, measured_contact_size(c, summary));
  summary["limits"] = output::limits_json(limits);
  return limits;
}

}  // namespace dc::runs

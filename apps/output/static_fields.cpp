#include "static_fields.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dc::output {

StaticFields normal_fields(const std::vector<double>& pressure, double relative_threshold) {
  StaticFields f;
  f.p = pressure;
  double p_max = 0.0;
  for (double v : pressure)
    if (std::isfinite(v)) p_max = std::max(p_max, v);
  f.contact_threshold = relative_threshold * p_max;
  f.state.resize(pressure.size());
  for (std::size_t i = 0; i < pressure.size(); ++i)
    f.state[i] = (p_max > 0.0 && pressure[i] > f.contact_threshold) ? kStick : kFree;
  return f;
}

ContactMeasures contact_measures(const Grid& grid, const StaticFields& fields) {
  ContactMeasures m;
  bool first = true;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      if (e < fields.p.size() && std::isfinite(fields.p[e])) m.max_pressure = std::max(m.max_pressure, fields.p[e]);
      const bool on_edge = i == 0 || i == grid.nx - 1 || (grid.dimension == 3 && (j == 0 || j == grid.ny - 1));
      m.n_edge += on_edge;
      if (e >= fields.state.size() || fields.state[e] == kFree) continue;
      m.n_edge_contact += on_edge;
      ++m.n_contact;
      const double xl = grid.x0 + i * grid.dx, yl = grid.y0 + j * grid.dy;
      if (first) {
        m.x_min = xl;
        m.x_max = xl + grid.dx;
        m.y_min = yl;
        m.y_max = yl + grid.dy;
        first = false;
      }
      m.x_min = std::min(m.x_min, xl);
      m.x_max = std::max(m.x_max, xl + grid.dx);
      m.y_min = std::min(m.y_min, yl);
      m.y_max = std::max(m.y_max, yl + grid.dy);
      if (i == 0 || i == grid.nx - 1 || (grid.dimension == 3 && (j == 0 || j == grid.ny - 1)))
        m.touches_boundary = true;
    }
  m.contact_area = m.n_contact * grid.area();
  auto in_contact = [&](int i, int j) {
    if (i < 0 || i >= grid.nx || j < 0 || j >= grid.ny) return false;
    const std::size_t e = grid.index(i, j);
    return e < fields.state.size() && fields.state[e] != kFree;
  };
  double rim_pressure = 0.0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      if (!in_contact(i, j)) continue;
      const bool rim = !in_contact(i - 1, j) || !in_contact(i + 1, j) ||
                       (grid.dimension == 3 && (!in_contact(i, j - 1) || !in_contact(i, j + 1)));
      if (rim && std::isfinite(fields.p[grid.index(i, j)])) rim_pressure = std::max(rim_pressure, fields.p[grid.index(i, j)]);
    }
  m.rim_pressure_ratio = m.max_pressure > 0.0 ? rim_pressure / m.max_pressure : 0.0;
  if (m.n_contact > 0) {
    m.n_across_x = static_cast<int>(std::lround((m.x_max - m.x_min) / grid.dx));
    m.n_across_y = grid.dimension == 3 ? static_cast<int>(std::lround((m.y_max - m.y_min) / grid.dy)) : 0;
  }
  return m;
}

void add_contact_measures(nlohmann::json& s, const Grid& grid, const StaticFields& fields) {
  const ContactMeasures m = contact_measures(grid, fields);
  s["contact_area"] = m.contact_area;
  s["max_pressure"] = m.max_pressure;
  s["n_contact"] = m.n_contact;
  const double half_x = m.n_contact > 0 ? 0.5 * (m.x_max - m.x_min) : 0.0;
  if (grid.dimension == 2) {
    s["contact_half_width"] = half_x;
    s["contact_extent"] = {{"x", {m.x_min, m.x_max}}};
  } else {
    s["contact_half_width_x"] = half_x;
    s["contact_half_width_y"] = m.n_contact > 0 ? 0.5 * (m.y_max - m.y_min) : 0.0;
    s["equivalent_radius"] = std::sqrt(m.contact_area / std::numbers::pi);
    s["contact_extent"] = {{"x", {m.x_min, m.x_max}}, {"y", {m.y_min, m.y_max}}};
  }
  s["contact_pressure_threshold"] = fields.contact_threshold;
  s["contact_touches_boundary"] = m.touches_boundary;
  // The fraction of the grid's edge elements in contact (0: the contact lies inside the grid).
  s["contact_edge_fraction"] = m.n_edge > 0 ? static_cast<double>(m.n_edge_contact) / m.n_edge : 0.0;
  s["contact_rim_pressure_ratio"] = m.rim_pressure_ratio;
  s["elements_across_contact"] =
      grid.dimension == 3 ? nlohmann::json::array({m.n_across_x, m.n_across_y}) : nlohmann::json(m.n_across_x);
}

}  // namespace dc::output

#include "dynamic_series.hpp"

#include <charconv>
#include <cstdio>
#include <sstream>

namespace dc::output {

namespace {

/// Appends `value` as printf's %.{precision}g would, and `separator` (std::to_chars: no locale,
/// no allocation; glibc's printf takes heap scratch space for some doubles).
char* put(char* at, char* end, double value, int precision, char separator) {
  at = std::to_chars(at, end, value, std::chars_format::general, precision).ptr;
  *at++ = separator;
  return at;
}

char* put(char* at, char* end, int value, char separator) {
  at = std::to_chars(at, end, value).ptr;
  *at++ = separator;
  return at;
}

}  // namespace

void append_timeseries_row(std::ostream& out, const dynamics::DynamicSample& s) {
  const auto& st = s.state;
  const auto& cs = s.contact_state;
  char line[1024];
  char* const end = line + sizeof line;
  char* at = line;
  for (double v : {st.time, st.position.x(), st.position.y(), st.position.z(), st.velocity.x(), st.velocity.y(),
                   st.velocity.z(), st.omega.x(), st.omega.y(), st.omega.z()})
    at = put(at, end, v, 10, ',');
  for (double v : {s.contact.force.x(), s.contact.force.y(), s.contact.force.z(), s.contact.moment.x(),
                   s.contact.moment.y(), s.contact.moment.z(), cs.creepage})
    at = put(at, end, v, 8, ',');
  at = put(at, end, cs.stick_fraction, 6, ',');
  at = put(at, end, cs.in_contact ? cs.approach : 0.0, 8, ',');
  at = put(at, end, cs.contact_area, 8, ',');
  at = put(at, end, cs.n_contact, ',');
  at = put(at, end, cs.n_stick, ',');
  at = put(at, end, cs.n_slip, ',');
  at = put(at, end, s.kinetic_energy, 10, ',');
  at = put(at, end, cs.certificate, 3, ',');
  at = put(at, end, s.newton_iterations, ',');
  at = put(at, end, s.contact_solves, ',');
  at = put(at, end, s.alternations, '\n');
  out.write(line, at - line);
}

std::vector<DynamicPlotSeries> dynamic_plot_series(int dimension) {
  return {
      {"position", "position (m)", {{2, "x"}, {3, "y"}, {4, "z"}}},
      {"velocity", "velocity (m/s)", {{5, "vx"}, {6, "vy"}, {7, "vz"}}},
      {"omega", "angular velocity (rad/s)", {{8, "wx"}, {9, "wy"}, {10, "wz"}}},
      {"force", "contact force (N)", {{11, "Fx"}, {12, "Fy"}, {13, "Fz"}}},
      {"moment", "contact moment about the centre of mass (N m)", {{14, "Mx"}, {15, "My"}, {16, "Mz"}}},
      {"creepage", "creepage (-)", {{17, "creepage"}}},
      {"stick", "stick fraction of the contact", {{18, "stick_fraction"}}},
      {"approach", "approach (m)", {{19, "approach"}}},
      {"contact_area", dimension == 2 ? "contact length (m)" : "contact area (m^2)", {{20, "contact area"}}},
      {"energy", "kinetic energy (J)", {{24, "kinetic energy"}}},
  };
}

std::vector<GnuplotFigure> timeseries_figures(const Case& c, const std::vector<std::pair<std::string, std::string>>& runs) {
  std::vector<GnuplotFigure> out;
  for (const DynamicPlotSeries& s : dynamic_plot_series(c.dimension)) {
    std::ostringstream b;
    b << "set datafile separator \",\"\nset key top right noenhanced\nset grid\nset xlabel \"time (s)\"\n"
      << "set ylabel \"" << s.ylabel << "\"\nset title \"" << c.name << "\" noenhanced\nplot ";
    // A sweep: a colour per run, a dash pattern per column.
    for (std::size_t r = 0; r < runs.size(); ++r)
      for (std::size_t k = 0; k < s.columns.size(); ++k) {
        const auto& [file, label] = runs[r];
        b << (r + k == 0 ? "" : ", ") << "\"" << file << "\" using 1:" << s.columns[k].first
          << " skip 1 with lines lw 2";
        if (runs.size() > 1) b << " lc " << r + 1 << " dt " << k + 1;
        b << " title \"" << (label.empty() ? s.columns[k].second : label + ": " + s.columns[k].second) << "\"";
      }
    b << "\n";
    out.push_back({s.stem, b.str()});
  }
  return out;
}

}  // namespace dc::output

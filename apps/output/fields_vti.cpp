#include "fields_vti.hpp"

#include <filesystem>

#include "output_files.hpp"
#include "vti_image.hpp"

namespace dc::output {
namespace {

std::vector<float> as_floats(const std::vector<double>& v, std::size_t n) {
  std::vector<float> out(n, 0.0f);
  for (std::size_t e = 0; e < n && e < v.size(); ++e) out[e] = static_cast<float>(v[e]);
  return out;
}

/// (a, b, 0) per element; an empty component is 0.
std::vector<float> in_plane(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  std::vector<float> out(3 * n, 0.0f);
  for (std::size_t e = 0; e < n; ++e) {
    if (e < a.size()) out[3 * e] = static_cast<float>(a[e]);
    if (e < b.size()) out[3 * e + 1] = static_cast<float>(b[e]);
  }
  return out;
}

}  // namespace

std::string write_fields_vti(const std::string& dir, const Grid& g, const StaticFields& f, const std::string& file,
                             const std::vector<NamedMap>& extra) {
  const std::size_t n = g.size();
  VtiImage image = surface_image(g);
  image.add("pressure", 1, as_floats(f.p, n));
  image.add("traction", 3, in_plane(f.tx, f.ty, n));
  image.add("slip", 3, in_plane(f.sx, f.sy, n));
  std::vector<float> state(n, 0.0f);
  for (std::size_t e = 0; e < n && e < f.state.size(); ++e) state[e] = static_cast<float>(f.state[e]);
  image.add("state", 1, state);
  if (!f.bound.empty()) image.add("friction_bound", 1, as_floats(f.bound, n));
  if (!f.dissipation.empty()) {  // fields.csv's name: a power density where there is a rate
    std::vector<double> density = f.dissipation;
    if (f.dissipation_rate > 0.0)
      for (double& d : density) d *= f.dissipation_rate;
    image.add(f.dissipation_rate > 0.0 ? "power" : "dissipation", 1, as_floats(density, n));
  }
  if (!f.temperature_base.empty()) image.add("temperature_base", 1, as_floats(f.temperature_base, n));
  if (!f.temperature_body.empty()) image.add("temperature_body", 1, as_floats(f.temperature_body, n));
  for (const auto& [name, map] : extra)
    if (map != nullptr && !map->empty()) image.add(name, 1, as_floats(*map, n));
  write_file_whole((std::filesystem::path(dir) / file).string(), image.text());
  return file;
}

std::string FieldsSnapshots::write(const Grid& grid, const StaticFields& fields, int step, double time,
                                   const std::vector<NamedMap>& extra) {
  const std::string name = write_fields_vti(dir_, grid, fields, "fields_" + std::to_string(step) + ".vti", extra);
  files_.push_back({time, name});
  write_pvd((std::filesystem::path(dir_) / collection()).string(), files_);
  return name;
}

}  // namespace dc::output

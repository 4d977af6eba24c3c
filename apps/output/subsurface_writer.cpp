#include "subsurface_writer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "output_files.hpp"
#include "vti_image.hpp"

namespace dc::output {
namespace {

/// One point's row of the planes' CSV after its coordinate and depth.
void append_row(std::string& out, double along, double depth, const SubsurfaceResult& f, std::size_t k,
                std::size_t e, const SubsurfaceMeasures& m) {
  char buf[320];
  const std::size_t n = f.grid.size();
  const int len = std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", along, depth,
                                f.component(k, kSxx)[e], f.component(k, kSyy)[e], f.component(k, kSzz)[e],
                                f.component(k, kSyz)[e], f.component(k, kSxz)[e], f.component(k, kSxy)[e],
                                m.von_mises[k * n + e], m.tresca[k * n + e]);
  out.append(buf, static_cast<std::size_t>(len));
}

}  // namespace

bool evenly_spaced(const std::vector<double>& depths) {
  if (depths.size() < 2) return !depths.empty();
  const double step = (depths.back() - depths.front()) / static_cast<double>(depths.size() - 1);
  for (std::size_t k = 0; k < depths.size(); ++k)
    if (std::abs(depths[k] - (depths.front() + step * static_cast<double>(k))) > 1e-9 * std::abs(depths.back()))
      return false;
  return step > 0.0;
}

std::string write_subsurface_vti(const std::string& dir, const std::vector<SubsurfaceBody>& bodies,
                                 const std::string& name) {
  const SubsurfaceResult& first = *bodies.front().field;
  const Grid& g = first.grid;
  const std::vector<double>& d = first.depths;
  const double dz = d.size() > 1 ? (d.back() - d.front()) / static_cast<double>(d.size() - 1) : g.dx;
  const std::size_t n = g.size();
  VtiImage image({g.nx, g.ny, static_cast<int>(d.size())}, {g.xc(0), g.yc(0), d.front()},
                 {g.dx, g.dimension == 3 ? g.dy : g.dx, dz});
  // Voigt order (voigt_stress.hpp) from the field's components.
  const int voigt[6] = {kSxx, kSyy, kSzz, kSyz, kSxz, kSxy};
  std::vector<float> values;
  for (const SubsurfaceBody& b : bodies) {
    const SubsurfaceResult& f = *b.field;
    values.clear();
    for (std::size_t k = 0; k < d.size(); ++k)
      for (std::size_t e = 0; e < n; ++e)
        for (int c : voigt) values.push_back(static_cast<float>(f.component(k, c)[e]));
    image.add(b.name + "_stress", 6, values);
    values.clear();
    for (std::size_t k = 0; k < d.size(); ++k)
      for (std::size_t e = 0; e < n; ++e)
        for (int c : {kUx, kUy, kUz}) values.push_back(static_cast<float>(f.component(k, c)[e]));
    image.add(b.name + "_displacement", 3, values);
    for (const auto& [label, measure] : {std::pair{"_von_mises", &b.measures->von_mises}, {"_tresca", &b.measures->tresca}}) {
      values.assign(measure->begin(), measure->end());
      image.add(b.name + label, 1, values);
    }
  }
  write_file_whole((std::filesystem::path(dir) / name).string(), image.text());
  return name;
}

std::string SubsurfaceSnapshots::write(const std::vector<SubsurfaceBody>& bodies, int step, double time) {
  const std::string name = write_subsurface_vti(dir_, bodies, "subsurface_" + std::to_string(step) + ".vti");
  files_.push_back({time, name});
  write_pvd((std::filesystem::path(dir_) / collection()).string(), files_);
  return name;
}

std::vector<std::string> write_subsurface_planes(const std::string& dir, const std::vector<SubsurfaceBody>& bodies) {
  std::vector<std::string> names;
  for (const SubsurfaceBody& b : bodies) {
    const SubsurfaceResult& f = *b.field;
    const Grid& g = f.grid;
    const FieldExtreme& worst = b.measures->max_von_mises;
    std::string xz = "x,depth,sxx,syy,szz,syz,sxz,sxy,von_mises,tresca\n";
    for (std::size_t k = 0; k < f.depths.size(); ++k)
      for (int i = 0; i < g.nx; ++i) append_row(xz, g.xc(i), f.depths[k], f, k, g.index(i, worst.j), *b.measures);
    names.push_back("subsurface_" + b.name + "_xz.csv");
    write_file_whole((std::filesystem::path(dir) / names.back()).string(), xz);
    if (g.dimension != 3) continue;
    std::string yz = "y,depth,sxx,syy,szz,syz,sxz,sxy,von_mises,tresca\n";
    for (std::size_t k = 0; k < f.depths.size(); ++k)
      for (int j = 0; j < g.ny; ++j) append_row(yz, g.yc(j), f.depths[k], f, k, g.index(worst.i, j), *b.measures);
    names.push_back("subsurface_" + b.name + "_yz.csv");
    write_file_whole((std::filesystem::path(dir) / names.back()).string(), yz);
  }
  return names;
}

}  // namespace dc::output

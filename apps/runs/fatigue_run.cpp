#include "fatigue_run.hpp"

#include <algorithm>
#include <vector>

#include "dang_van.hpp"

namespace dc::runs {

nlohmann::json fatigue_json(const Case& c, const SubsurfaceRun& field) {
  nlohmann::json out = nlohmann::json::object();
  for (const BodySubsurface& b : field.bodies) {
    const std::optional<FatigueSpec>& f = b.name == "base" ? c.fatigue.base : c.fatigue.body;
    if (!f) continue;
    const Grid& g = b.field.grid;
    DangVanParameters p;
    p.alpha = f->alpha;
    p.beta = f->beta;
    double worst = -1.0, range = -1.0;
    nlohmann::json at, at_range;
    std::vector<Voigt> path(static_cast<std::size_t>(g.nx));
    for (std::size_t k = 0; k < field.depths.size(); ++k)
      for (int j = 0; j < g.ny; ++j) {
        double lo = 0.0, hi = 0.0;
        for (int i = 0; i < g.nx; ++i) {
          path[static_cast<std::size_t>(i)] = voigt_stress(b.field.point(k, i, j));
          const double sxz = b.field.at(k, kSxz, i, j);
          lo = i == 0 ? sxz : std::min(lo, sxz);
          hi = i == 0 ? sxz : std::max(hi, sxz);
        }
        auto place = [&](int i) {
          return g.dimension == 3 ? nlohmann::json::array({g.xc(i), g.yc(j), field.depths[k]})
                                  : nlohmann::json::array({g.xc(i), field.depths[k]});
        };
        const DangVanResult r = dang_van(path, p);
        if (r.index > worst) {
          worst = r.index;
          at = place(r.critical_instant);
        }
        if (hi - lo > range) {
          range = hi - lo;
          at_range = place(0);
          at_range[0] = nullptr;  // the whole passage
        }
      }
    out[b.name] = {{"dang_van_max", worst}, {"at", at}, {"alpha", f->alpha}, {"beta", f->beta},
                   {"orthogonal_shear_range", range}, {"at_orthogonal_range", at_range}};
  }
  return out;
}

}  // namespace dc::runs

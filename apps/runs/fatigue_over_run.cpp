#include "fatigue_over_run.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dang_van.hpp"

namespace dc::runs {
namespace {

/// Bilinear weights of `u` between the element centres origin + (i + 1/2) step, i < n: the
/// lower index and the upper's weight; false off the centres' span.
bool centre_weights(double u, double origin, double step, int n, int& i, double& w) {
  const double s = (u - origin) / step - 0.5;
  if (n == 1) {
    i = 0;
    w = 0.0;
    return std::abs(s) <= 0.5;
  }
  if (s < 0.0 || s > n - 1) return false;
  i = std::min(static_cast<int>(std::floor(s)), n - 2);
  w = s - i;
  return true;
}

}  // namespace

FatigueOverRun::FatigueOverRun(std::string body, const FatigueSpec& spec, const Grid& grid,
                               const std::vector<double>& depths, const std::vector<SubsurfaceState>& states)
    : body_(std::move(body)), spec_(spec), grid_(grid), depths_(depths) {
  double x_lo = 0.0, x_hi = 0.0, y_lo = 0.0, y_hi = 0.0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const SubsurfaceState& s = states[k];
    x_lo = k == 0 ? s.x_offset : std::min(x_lo, s.x_offset);
    x_hi = k == 0 ? s.x_offset : std::max(x_hi, s.x_offset);
    y_lo = k == 0 ? s.y_offset : std::min(y_lo, s.y_offset);
    y_hi = k == 0 ? s.y_offset : std::max(y_hi, s.y_offset);
  }
  auto axis = [](double lo, double hi, double first_centre, int n, double step, std::vector<double>& out) {
    const int count = n + static_cast<int>(std::ceil((hi - lo) / step));
    for (int i = 0; i < count; ++i) out.push_back(lo + first_centre + i * step);
  };
  axis(x_lo, x_hi, grid.xc(0), grid.nx, grid.dx, xs_);
  if (grid.dimension == 3)
    axis(y_lo, y_hi, grid.yc(0), grid.ny, grid.dy, ys_);
  else
    ys_ = {0.0};
  const std::size_t points = depths.size() * xs_.size() * ys_.size();
  if (points * states.size() > kMaxPathEntries) {
    note_ = "not computed: " + std::to_string(points) + " material points x " + std::to_string(states.size()) +
            " snapshots exceed " + std::to_string(kMaxPathEntries) +
            " path entries (raise output.snapshot_every or give fewer subsurface.depths)";
    return;
  }
  paths_.assign(points, {});
  for (auto& p : paths_) p.reserve(states.size());
}

void FatigueOverRun::add(const SubsurfaceState& s, const SubsurfaceRun& run) {
  if (!note_.empty()) return;
  const BodySubsurface* field = nullptr;
  for (const BodySubsurface& b : run.bodies)
    if (b.name == body_) field = &b;
  if (!field) return;
  const SubsurfaceResult& f = field->field;
  const Grid& g = grid_;
  std::size_t point = 0;
  for (std::size_t k = 0; k < depths_.size(); ++k)
    for (double Y : ys_)
      for (double X : xs_) {
        Voigt v{};
        int i = 0, j = 0;
        double wx = 0.0, wy = 0.0;
        const bool in_x = centre_weights(X - s.x_offset, g.x0, g.dx, g.nx, i, wx);
        const bool in_y = g.dimension != 3 || centre_weights(Y - s.y_offset, g.y0, g.dy, g.ny, j, wy);
        if (in_x && in_y) {
          const int i1 = g.nx > 1 ? i + 1 : i, j1 = g.dimension == 3 && g.ny > 1 ? j + 1 : j;
          const Voigt a = voigt_stress(f.point(k, i, j)), b = voigt_stress(f.point(k, i1, j)),
                      cc = voigt_stress(f.point(k, i, j1)), d = voigt_stress(f.point(k, i1, j1));
          for (int m = 0; m < 6; ++m)
            v[m] = (1.0 - wy) * ((1.0 - wx) * a[m] + wx * b[m]) + wy * ((1.0 - wx) * cc[m] + wx * d[m]);
        }
        paths_[point++].push_back(v);
      }
}

nlohmann::json FatigueOverRun::to_json() const {
  nlohmann::json base = {{"alpha", spec_.alpha}, {"beta", spec_.beta}};
  if (!note_.empty() || paths_.empty() || paths_.front().empty()) {
    base["dang_van_max"] = nullptr;
    base["note"] = note_.empty() ? "no snapshot" : note_;
    return base;
  }
  DangVanParameters p;
  p.alpha = spec_.alpha;
  p.beta = spec_.beta;
  const bool three_d = grid_.dimension == 3;
  double worst = -1.0, range = -1.0;
  nlohmann::json at, at_range;
  std::size_t point = 0;
  for (std::size_t k = 0; k < depths_.size(); ++k)
    for (double Y : ys_)
      for (double X : xs_) {
        const std::vector<Voigt>& path = paths_[point++];
        const DangVanResult r = dang_van(path, p);
        auto place = [&] {
          return three_d ? nlohmann::json::array({X, Y, depths_[k]}) : nlohmann::json::array({X, depths_[k]});
        };
        if (r.index > worst) {
          worst = r.index;
          at = place();
        }
        double lo = path.front()[index_of(VoigtComponent::xz)], hi = lo;
        for (const Voigt& v : path) {
          lo = std::min(lo, v[index_of(VoigtComponent::xz)]);
          hi = std::max(hi, v[index_of(VoigtComponent::xz)]);
        }
        if (hi - lo > range) {
          range = hi - lo;
          at_range = place();
        }
      }
  base["dang_van_max"] = worst;
  base["at"] = at;
  base["orthogonal_shear_range"] = range;
  base["at_orthogonal_range"] = at_range;
  base["snapshots"] = paths_.front().size();
  base["points"] = xs_.size() * ys_.size();
  base["frame"] = "world (the " + body_ + "'s material points)";
  return base;
}

}  // namespace dc::runs

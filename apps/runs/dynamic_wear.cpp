#include "dynamic_wear.hpp"

#include <algorithm>
#include <cmath>

#include "tangential_problem.hpp"

namespace dc::runs {

double WornStrip::max_depth() const { return depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end()); }

double WornStrip::volume() const {
  double v = 0.0;
  for (double d : depth) v += d;
  return v * grid.area();
}

namespace {

/// The most cells a map holds along the track or the circumference: beyond, the track's cells
/// double (the map coarser than the grid), the circumference's are 2 pi R / this.
constexpr long long kMaxCells = 16384;

long long floor_half(long long k) { return k >= 0 ? k / 2 : -((-k + 1) / 2); }

}  // namespace

DynamicWear::DynamicWear(const Case& c) : case_(c) {
  if (!c.wear || !c.dynamic) return;
  grid_ = c.grid;
  x_start_ = x_end_ = c.dynamic->position[0];
  base_.width = c.grid.dx;
  const double circumference = 2.0 * M_PI * c.dynamic->radius;
  body_.wrap = body_.count = std::clamp(std::llround(circumference / c.grid.dx), 3LL, kMaxCells);
  body_.width = circumference / static_cast<double>(body_.wrap);
  body_.depth.assign(static_cast<std::size_t>(body_.count * c.grid.ny), 0.0);
}

double& DynamicWear::Cells::at(long long k, int j, int ny) {
  if (wrap > 0) {
    k = ((k % wrap) + wrap) % wrap;
  } else if (count == 0) {
    first = k;
    count = 1;
    depth.assign(static_cast<std::size_t>(ny), 0.0);
  } else if (k < first) {  // grow the track backwards
    depth.insert(depth.begin(), static_cast<std::size_t>((first - k) * ny), 0.0);
    count += first - k;
    first = k;
  } else if (k >= first + count) {
    count = k - first + 1;
    depth.resize(static_cast<std::size_t>(count * ny), 0.0);
  }
  return depth[static_cast<std::size_t>((k - first) * ny + j)];
}

void DynamicWear::Cells::coarsen(int ny) {
  // Cell K of width 2w holds the old cells 2K and 2K + 1: their mean depth keeps the volume.
  const long long new_first = floor_half(first), new_count = floor_half(first + count - 1) - new_first + 1;
  std::vector<double> merged(static_cast<std::size_t>(new_count * ny), 0.0);
  for (long long k = first; k < first + count; ++k)
    for (int j = 0; j < ny; ++j)
      merged[static_cast<std::size_t>((floor_half(k) - new_first) * ny + j)] +=
          0.5 * depth[static_cast<std::size_t>((k - first) * ny + j)];
  depth = std::move(merged);
  first = new_first;
  count = new_count;
  width *= 2.0;
}

void DynamicWear::deposit(Cells& cells, double a, double b, int j, double volume) {
  const double w = cells.width, lo = std::min(a, b), hi = std::max(a, b), L = hi - lo;
  const int ny = grid_.ny;
  if (L < 1e-9 * w) {  // in place: the two cells around the centre (cell k's centre at (k + 1/2) w)
    const double u = lo / w - 0.5, k0 = std::floor(u), f = u - k0;
    cells.at(static_cast<long long>(k0), j, ny) += (1.0 - f) * volume / w;
    cells.at(static_cast<long long>(k0) + 1, j, ny) += f * volume / w;
    return;
  }
  // The track beyond kMaxCells cells: coarser cells first.
  while (cells.wrap == 0 && cells.count > 0 &&
         std::max(cells.first + cells.count, static_cast<long long>(std::floor(hi / w)) + 2) -
                 std::min(cells.first, static_cast<long long>(std::floor(lo / w)) - 1) > kMaxCells) {
    cells.coarsen(ny);
    return deposit(cells, a, b, j, volume);
  }
  // A uniform line density volume / L over [lo, hi], binned by overlap.
  const long long k_lo = static_cast<long long>(std::floor(lo / w)), k_hi = static_cast<long long>(std::floor(hi / w));
  for (long long k = k_lo; k <= k_hi; ++k) {
    const double overlap = std::min(hi, static_cast<double>(k + 1) * w) - std::max(lo, static_cast<double>(k) * w);
    if (overlap > 0.0) cells.at(k, j, ny) += volume * overlap / (L * w);
  }
}

void DynamicWear::observe(const Grid& grid, const dynamics::DynamicSample& s) {
  if (!wanted()) return;
  grid_ = grid;
  // The step's start (the last step's end) and end: the body's x and its rotation about y
  // (q = cos(phi/2) + sin(phi/2) e_y for a pure y turn, unwrapped).
  const double x0 = x_end_, phi0 = phi_;
  const Eigen::Quaterniond& q = s.state.orientation;
  const double angle = 2.0 * std::atan2(q.y(), q.w());
  phi_ += std::remainder(angle - last_angle_, 2.0 * M_PI);
  last_angle_ = angle;
  x_end_ = s.state.position.x();
  const dynamics::ContactState& cs = s.contact_state;
  if (!cs.in_contact || !cs.fields || !(cs.frictional_work > 0.0)) return;
  const TangentialSolution& t = *cs.fields;
  // The step's slip: the solution's scaled so that its work is the audit's (a steady-rolling
  // step's slip is per dx of travel, ContactWrench::audit_energy).
  const double own = frictional_work(t, grid.area());
  if (!(own > 0.0)) return;
  const double scale = cs.frictional_work / own;
  const WearSpec& w = *case_.wear;
  const std::vector<double>& p = cs.pressure ? *cs.pressure : t.normal.pressure;
  const double R = case_.dynamic->radius;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      const double d = w.law.depth(p[e], t.tx[e], e < t.ty.size() ? t.ty[e] : 0.0, scale * t.sx[e],
                                   e < t.sy.size() ? scale * t.sy[e] : 0.0);
      if (d == 0.0) continue;
      const double x = grid.xc(i), volume = d * grid.dx;  // per unit y
      if (w.base) deposit(base_, x0 + x, x_end_ + x, j, volume);
      if (w.body) deposit(body_, R * phi0 + x, R * phi_ + x, j, volume);
    }
}

double DynamicWear::sample(const Cells& cells, double at, int j, int ny) {
  if (cells.count == 0) return 0.0;
  const double u = at / cells.width - 0.5, k0 = std::floor(u), f = u - k0;
  auto depth = [&](long long k) {
    if (cells.wrap > 0) k = ((k % cells.wrap) + cells.wrap) % cells.wrap;
    else if (k < cells.first || k >= cells.first + cells.count) return 0.0;
    return cells.depth[static_cast<std::size_t>((k - cells.first) * ny + j)];
  };
  const long long k = static_cast<long long>(k0);
  return (1.0 - f) * depth(k) + f * depth(k + 1);
}

void DynamicWear::worn_depth(const dynamics::StepKinematics& k, std::vector<double>& depth) const {
  depth.assign(grid_.size(), 0.0);
  if (!wanted()) return;
  const WearSpec& w = *case_.wear;
  // The trial's rotation about y from the last accepted one (as observe unwraps it).
  const double angle = 2.0 * std::atan2(k.orientation.y(), k.orientation.w());
  const double phi = phi_ + std::remainder(angle - last_angle_, 2.0 * M_PI), R = case_.dynamic->radius;
  const double xc = k.position.x();
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      const double x = grid_.xc(i);
      double d = 0.0;
      if (w.base) d += sample(base_, xc + x, j, grid_.ny);
      if (w.body) d += sample(body_, R * phi + x, j, grid_.ny);
      depth[grid_.index(i, j)] = d;
    }
}

WornStrip DynamicWear::strip(const Cells& cells) const {
  WornStrip out;
  if (cells.count == 0) return out;
  out.grid = grid_;
  out.grid.nx = static_cast<int>(cells.count);
  out.grid.dx = cells.width;
  out.grid.x0 = static_cast<double>(cells.first) * cells.width;
  out.depth.assign(out.grid.size(), 0.0);
  for (long long k = 0; k < cells.count; ++k)
    for (int j = 0; j < grid_.ny; ++j)
      out.depth[out.grid.index(static_cast<int>(k), j)] = cells.depth[static_cast<std::size_t>(k * grid_.ny + j)];
  return out;
}

WornStrip DynamicWear::base() const { return wanted() && case_.wear->base ? strip(base_) : WornStrip{}; }

WornStrip DynamicWear::body() const { return wanted() && case_.wear->body ? strip(body_) : WornStrip{}; }

void DynamicWear::add_entries(nlohmann::json& summary) const {
  if (!wanted()) return;
  const WearSpec& w = *case_.wear;
  nlohmann::json j = {{"law", to_string(w.law.kind)},
                      {"cycles", std::abs(phi_) / (2.0 * M_PI)},  // the body's revolutions
                      {"travel", x_end_ - x_start_},
                      {"rolling_radius", case_.dynamic->radius},
                      {"gap_feedback", w.gap_feedback}};
  if (w.base) {
    const WornStrip b = base();
    j["base"] = {{"max_depth", b.max_depth()}, {"volume", b.volume()}, {"frame", "world x along the track"},
                 {"cell", base_.width}};
  }
  if (w.body) {
    const WornStrip b = body();
    j["body"] = {{"max_depth", b.max_depth()}, {"volume", b.volume()}, {"frame", "arc length along the circumference"},
                 {"cells", body_.wrap}, {"cell", body_.width}};
  }
  summary["wear"] = j;
}

}  // namespace dc::runs

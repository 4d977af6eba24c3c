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

/// u = l + f with l = floor(u), f in [0, 1): within 1e-9 of a row centre, that row alone.
void split_row(double u, long long& l, double& f) {
  const double nearest = std::round(u);
  if (std::abs(u - nearest) < 1e-9) {
    l = static_cast<long long>(nearest);
    f = 0.0;
    return;
  }
  const double below = std::floor(u);
  l = static_cast<long long>(below);
  f = u - below;
}

}  // namespace

DynamicWear::DynamicWear(const Case& c, long long max_map_cells) : case_(c), max_map_cells_(max_map_cells) {
  if (!c.wear || !c.dynamic) return;
  grid_ = c.grid;
  x_start_ = x_end_ = c.dynamic->position[0];
  y_end_ = c.grid.dimension == 3 ? c.dynamic->position[1] : 0.0;
  y_reference_ = y_end_ + (c.grid.dimension == 3 ? c.grid.y0 : 0.0);
  base_.width = c.grid.dx;
  base_.height = c.grid.dy;
  base_.fixed_rows = c.grid.dimension == 2;  // a line contact has no lateral motion
  if (base_.fixed_rows) base_.rows = c.grid.ny;
  const double circumference = 2.0 * M_PI * c.dynamic->radius;
  body_.wrap = body_.count = std::clamp(std::llround(circumference / c.grid.dx), 3LL, kMaxCells);
  body_.width = circumference / static_cast<double>(body_.wrap);
  body_.height = c.grid.dy;
  body_.rows = c.grid.ny;
  body_.fixed_rows = true;
  body_.depth.assign(static_cast<std::size_t>(body_.count * body_.rows), 0.0);
}

double& DynamicWear::Cells::at(long long k, long long l) {
  if (wrap > 0) k = ((k % wrap) + wrap) % wrap;
  if (count == 0) {
    first = k;
    count = 1;
    if (!fixed_rows) {
      row_first = l;
      rows = 1;
    }
    depth.assign(static_cast<std::size_t>(rows), 0.0);
  }
  if (!fixed_rows && (l < row_first || l >= row_first + rows)) {
    // New rows: by at least half the rows there are (the map's layout copied seldom).
    const long long slack = std::max(1LL, rows / 2);
    const long long lo = l < row_first ? std::min(l, row_first - slack) : row_first;
    const long long hi = l >= row_first + rows ? std::max(l + 1, row_first + rows + slack) : row_first + rows;
    std::vector<double> grown(static_cast<std::size_t>(count * (hi - lo)), 0.0);
    for (long long c = 0; c < count; ++c)
      std::copy_n(depth.begin() + c * rows, rows, grown.begin() + c * (hi - lo) + (row_first - lo));
    depth = std::move(grown);
    row_first = lo;
    rows = hi - lo;
  }
  if (k < first) {  // grow the track backwards
    depth.insert(depth.begin(), static_cast<std::size_t>((first - k) * rows), 0.0);
    count += first - k;
    first = k;
  } else if (k >= first + count) {
    count = k - first + 1;
    depth.resize(static_cast<std::size_t>(count * rows), 0.0);
  }
  return depth[static_cast<std::size_t>((k - first) * rows + (l - row_first))];
}

double DynamicWear::Cells::value(long long k, long long l) const {
  if (count == 0) return 0.0;
  if (wrap > 0) k = ((k % wrap) + wrap) % wrap;
  if (k < first || k >= first + count || l < row_first || l >= row_first + rows) return 0.0;
  return depth[static_cast<std::size_t>((k - first) * rows + (l - row_first))];
}

void DynamicWear::Cells::coarsen() {
  // Cell K of width 2w holds the old cells 2K and 2K + 1: their mean depth keeps the volume.
  const long long new_first = floor_half(first), new_count = floor_half(first + count - 1) - new_first + 1;
  std::vector<double> merged(static_cast<std::size_t>(new_count * rows), 0.0);
  for (long long k = first; k < first + count; ++k)
    for (long long j = 0; j < rows; ++j)
      merged[static_cast<std::size_t>((floor_half(k) - new_first) * rows + j)] +=
          0.5 * depth[static_cast<std::size_t>((k - first) * rows + j)];
  depth = std::move(merged);
  first = new_first;
  count = new_count;
  width *= 2.0;
}

void DynamicWear::Cells::coarsen_rows() {
  // Row L of height 2h holds the old rows 2L and 2L + 1 (row 0's lower edge stays where it was).
  const long long new_first = floor_half(row_first), new_rows = floor_half(row_first + rows - 1) - new_first + 1;
  std::vector<double> merged(static_cast<std::size_t>(count * new_rows), 0.0);
  for (long long k = 0; k < count; ++k)
    for (long long l = row_first; l < row_first + rows; ++l)
      merged[static_cast<std::size_t>(k * new_rows + (floor_half(l) - new_first))] +=
          0.5 * depth[static_cast<std::size_t>(k * rows + (l - row_first))];
  depth = std::move(merged);
  row_first = new_first;
  rows = new_rows;
  height *= 2.0;
}

double DynamicWear::base_row(double Y) const { return (Y - y_reference_) / base_.height - 0.5; }

void DynamicWear::deposit(Cells& cells, double a, double b, double u_a, double u_b, double volume) {
  // The map beyond its budget: the smaller cells doubled (the direction with more of them when
  // square); doubled rows halve the row coordinate.
  if (!cells.fixed_rows && cells.count * cells.rows > max_map_cells_) {
    const bool rows = cells.rows > 1 && (cells.height < cells.width ||
                                         (cells.height == cells.width && cells.rows >= cells.count));
    if (rows) {
      cells.coarsen_rows();
      return deposit(cells, a, b, 0.5 * (u_a + 0.5) - 0.5, 0.5 * (u_b + 0.5) - 0.5, volume);
    }
    cells.coarsen();
    return deposit(cells, a, b, u_a, u_b, volume);
  }
  // The path in parts between row centres (u integer): in each, the element's share of its two
  // rows is linear along the path, its mean the share at the part's middle.
  const double lo = std::min(u_a, u_b), hi = std::max(u_a, u_b), v = volume * (grid_.dy / cells.height);
  auto part = [&](double u_lo, double u_hi, double share) {
    long long l;
    double f;
    split_row(0.5 * (u_lo + u_hi), l, f);
    const double t_lo = hi > lo ? (u_lo - u_a) / (u_b - u_a) : 0.0, t_hi = hi > lo ? (u_hi - u_a) / (u_b - u_a) : 1.0;
    const double x_lo = a + t_lo * (b - a), x_hi = a + t_hi * (b - a);
    deposit_in_row(cells, x_lo, x_hi, l, (1.0 - f) * share * v);
    if (f > 0.0) deposit_in_row(cells, x_lo, x_hi, l + 1, f * share * v);
  };
  if (!(hi - lo > 1e-9)) return part(lo, hi, 1.0);
  for (double u = lo; u < hi;) {
    const double next = std::floor(u) + 1.0, end = next < hi - 1e-9 ? next : hi;
    part(u, end, (end - u) / (hi - lo));
    u = end;
  }
}

void DynamicWear::deposit_in_row(Cells& cells, double a, double b, long long l, double volume) {
  const double w = cells.width, lo = std::min(a, b), hi = std::max(a, b), L = hi - lo;
  if (L < 1e-9 * w) {  // in place: the two cells around the centre (cell k's centre at (k + 1/2) w)
    const double u = lo / w - 0.5, k0 = std::floor(u), f = u - k0;
    cells.at(static_cast<long long>(k0), l) += (1.0 - f) * volume / w;
    cells.at(static_cast<long long>(k0) + 1, l) += f * volume / w;
    return;
  }
  // The track beyond kMaxCells cells: coarser cells first.
  while (cells.wrap == 0 && cells.count > 0 &&
         std::max(cells.first + cells.count, static_cast<long long>(std::floor(hi / w)) + 2) -
                 std::min(cells.first, static_cast<long long>(std::floor(lo / w)) - 1) > kMaxCells) {
    cells.coarsen();
    return deposit_in_row(cells, a, b, l, volume);
  }
  // A uniform line density volume / L over [lo, hi], binned by overlap.
  const long long k_lo = static_cast<long long>(std::floor(lo / w)), k_hi = static_cast<long long>(std::floor(hi / w));
  for (long long k = k_lo; k <= k_hi; ++k) {
    const double overlap = std::min(hi, static_cast<double>(k + 1) * w) - std::max(lo, static_cast<double>(k) * w);
    if (overlap > 0.0) cells.at(k, l) += volume * overlap / (L * w);
  }
}

void DynamicWear::observe(const Grid& grid, const dynamics::DynamicSample& s) {
  if (!wanted()) return;
  grid_ = grid;
  // The step's start (the last step's end) and end: the body's x, y and its rotation about y
  // (q = cos(phi/2) + sin(phi/2) e_y for a pure y turn, unwrapped).
  const double x0 = x_end_, y0 = y_end_, phi0 = phi_;
  const Eigen::Quaterniond& q = s.state.orientation;
  const double angle = 2.0 * std::atan2(q.y(), q.w());
  phi_ += std::remainder(angle - last_angle_, 2.0 * M_PI);
  last_angle_ = angle;
  x_end_ = s.state.position.x();
  if (grid.dimension == 3) y_end_ = s.state.position.y();
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
  for (int j = 0; j < grid.ny; ++j) {
    const double y = grid.yc(j);
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      const double d = w.law.depth(p[e], t.tx[e], e < t.ty.size() ? t.ty[e] : 0.0, scale * t.sx[e],
                                   e < t.sy.size() ? scale * t.sy[e] : 0.0);
      if (d == 0.0) continue;
      const double x = grid.xc(i), volume = d * grid.dx;  // per unit y of a row
      if (w.base) {  // (the rows' coordinate after each deposit: the rows may have doubled)
        const double u_start = base_.fixed_rows ? j : base_row(y0 + y), u_end = base_.fixed_rows ? j : base_row(y_end_ + y);
        deposit(base_, x0 + x, x_end_ + x, u_start, u_end, volume);
      }
      if (w.body) deposit(body_, R * phi0 + x, R * phi_ + x, j, j, volume);
    }
  }
}

double DynamicWear::sample(const Cells& cells, double at, double u) {
  if (cells.count == 0) return 0.0;
  long long l;
  double g;
  split_row(u, l, g);
  const double v = at / cells.width - 0.5, k0 = std::floor(v), f = v - k0;
  const long long k = static_cast<long long>(k0);
  auto along = [&](long long row) { return (1.0 - f) * cells.value(k, row) + f * cells.value(k + 1, row); };
  return g > 0.0 ? (1.0 - g) * along(l) + g * along(l + 1) : along(l);
}

void DynamicWear::worn_depth(const dynamics::StepKinematics& k, std::vector<double>& depth) const {
  depth.assign(grid_.size(), 0.0);
  if (!wanted()) return;
  const WearSpec& w = *case_.wear;
  // The trial's rotation about y from the last accepted one (as observe unwraps it).
  const double angle = 2.0 * std::atan2(k.orientation.y(), k.orientation.w());
  const double phi = phi_ + std::remainder(angle - last_angle_, 2.0 * M_PI), R = case_.dynamic->radius;
  const double xc = k.position.x(), yc = grid_.dimension == 3 ? k.position.y() : 0.0;
  for (int j = 0; j < grid_.ny; ++j) {
    const double u = base_.fixed_rows ? j : base_row(yc + grid_.yc(j));
    for (int i = 0; i < grid_.nx; ++i) {
      const double x = grid_.xc(i);
      double d = 0.0;
      if (w.base) d += sample(base_, xc + x, u);
      if (w.body) d += sample(body_, R * phi + x, j);
      depth[grid_.index(i, j)] = d;
    }
  }
}

WornStrip DynamicWear::strip(const Cells& cells) const {
  WornStrip out;
  if (cells.count == 0) return out;
  out.grid = grid_;
  out.grid.nx = static_cast<int>(cells.count);
  out.grid.dx = cells.width;
  out.grid.x0 = static_cast<double>(cells.first) * cells.width;
  // Rows: the body's are the grid's; the track's the grid's rows where the body started and any
  // others the wear reached (the growth's slack left out).
  long long lo = cells.row_first, hi = cells.row_first + cells.rows;
  if (!cells.fixed_rows) {
    auto row_worn = [&](long long l) {
      for (long long k = 0; k < cells.count; ++k)
        if (cells.depth[static_cast<std::size_t>(k * cells.rows + (l - cells.row_first))] != 0.0) return true;
      return false;
    };
    while (lo < hi && !row_worn(lo)) ++lo;
    while (hi > lo && !row_worn(hi - 1)) --hi;
    const long long start_rows = std::max(1LL, std::llround(grid_.ny * grid_.dy / cells.height));
    lo = std::min(lo, 0LL);
    hi = std::max(hi, start_rows);
    out.grid.dy = cells.height;
    out.grid.y0 = y_reference_ + static_cast<double>(lo) * cells.height;
  }
  out.grid.ny = static_cast<int>(hi - lo);
  out.depth.assign(out.grid.size(), 0.0);
  for (long long k = 0; k < cells.count; ++k)
    for (long long l = lo; l < hi; ++l)
      out.depth[out.grid.index(static_cast<int>(k), static_cast<int>(l - lo))] = cells.value(cells.first + k, l);
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
    j["base"] = {{"max_depth", b.max_depth()}, {"volume", b.volume()}, {"frame", "world x, y on the track"},
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

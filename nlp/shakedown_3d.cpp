#include "shakedown_3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "shakedown_samples.hpp"
#include "shakedown_stations.hpp"

namespace dc {

namespace {

std::string increasing_or_why(const std::vector<double>& v, const char* key, bool non_negative) {
  if (v.empty()) return std::string(key) + ": at least one value needed";
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (!std::isfinite(v[k])) return std::string(key) + ": non-finite value";
    if (non_negative && v[k] < 0.0) return std::string(key) + ": must be >= 0 (into the solid)";
    if (k > 0 && !(v[k] > v[k - 1])) return std::string(key) + ": must increase strictly";
  }
  return "";
}

/// The breakpoints of the box (shakedown_3d.hpp): one spacing beyond each end of the lines.
std::vector<double> line_breakpoints(const std::vector<double>& lines) {
  std::vector<double> b;
  b.push_back(lines.front() - (lines[1] - lines[0]));
  b.insert(b.end(), lines.begin(), lines.end());
  b.push_back(lines.back() + (lines.back() - lines[lines.size() - 2]));
  return b;
}

/// The surface, the depths, and one depth step below the deepest.
std::vector<double> depth_breakpoints(const std::vector<double>& depths) {
  std::vector<double> b;
  if (depths.front() > 0.0) b.push_back(0.0);
  b.insert(b.end(), depths.begin(), depths.end());
  b.push_back(b.back() + (b.back() - b[b.size() - 2]));
  return b;
}

}  // namespace

std::string StressHistory3d::validate() const {
  if (const std::string why = increasing_or_why(depths, "depths", true); !why.empty()) return why;
  if (const std::string why = increasing_or_why(lines, "lines", false); !why.empty()) return why;
  if (positions.empty()) return "positions: at least one position needed";
  const std::size_t n = depths.size() * lines.size() * positions.size();
  if (stress.size() != n)
    return "stress: " + std::to_string(n) + " samples needed (depths x lines x positions), got " +
           std::to_string(stress.size());
  for (std::size_t k = 0; k < stress.size(); ++k)
    for (const double v : stress[k])
      if (!std::isfinite(v)) return "stress: non-finite value at sample " + std::to_string(k);
  return "";
}

ResidualBasis3d::ResidualBasis3d(const std::vector<double>& depths, const std::vector<double>& lines,
                                 const ResidualModel3d& model)
    : depths_(static_cast<int>(depths.size())), lines_(static_cast<int>(lines.size())) {
  if (const std::string why = increasing_or_why(depths, "depths", true); !why.empty())
    throw std::invalid_argument("shakedown: " + why);
  if (const std::string why = increasing_or_why(lines, "lines", false); !why.empty())
    throw std::invalid_argument("shakedown: " + why);
  const int nodes = depths_ * lines_;
  // Unknowns: rho_xx (per node, or per depth), rho_yy(z), rho_xy(z), then phi's and psi's.
  const int xx_count = model.vary_across ? nodes : depths_;
  const int yy_first = xx_count, xy_first = xx_count + depths_;
  unknowns_ = xx_count + 2 * depths_;
  // The stress functions need two lines and a depth below the surface.
  splines_ = model.vary_across && lines_ >= 2 && !(depths_ == 1 && depths.front() == 0.0);
  if (splines_) {
    y_basis_.emplace_back(line_breakpoints(lines));
    z_basis_.emplace_back(depth_breakpoints(depths));
    const int ny = y_basis_[0].size(), nz = z_basis_[0].size();
    phi_first_ = unknowns_;
    phi_nb_ = std::max(nz - 4, 0);
    phi_count_ = std::max(ny - 4, 0) * phi_nb_;
    psi_first_ = phi_first_ + phi_count_;
    psi_nb_ = nz - 2;
    psi_count_ = (ny - 2) * psi_nb_;
    unknowns_ = psi_first_ + psi_count_;
  }

  // Each node's unknowns and their (unscaled) stresses.
  std::vector<std::vector<int>> ids(static_cast<std::size_t>(nodes));
  std::vector<std::vector<Voigt>> cols(static_cast<std::size_t>(nodes));
  for (int k = 0; k < depths_; ++k)
    for (int j = 0; j < lines_; ++j) {
      auto& id = ids[node(k, j)];
      auto& col = cols[node(k, j)];
      const auto unit = [](VoigtComponent c) {
        Voigt v{};
        v[static_cast<std::size_t>(index_of(c))] = 1.0;
        return v;
      };
      id.push_back(model.vary_across ? static_cast<int>(node(k, j)) : k);
      col.push_back(unit(VoigtComponent::xx));
      id.push_back(yy_first + k);
      col.push_back(unit(VoigtComponent::yy));
      id.push_back(xy_first + k);
      col.push_back(unit(VoigtComponent::xy));
      if (splines_) stress_function_columns(lines[static_cast<std::size_t>(j)], depths[static_cast<std::size_t>(k)], id, col);
    }
  // Scale each unknown so that its largest stress over the nodes is 1 (the B-splines' second
  // derivatives are of order 1 / h^2): Ipopt's unknowns of order 1.
  scale_.assign(static_cast<std::size_t>(unknowns_), 0.0);
  for (std::size_t nd = 0; nd < ids.size(); ++nd)
    for (std::size_t c = 0; c < ids[nd].size(); ++c)
      for (const double v : cols[nd][c]) {
        double& s = scale_[static_cast<std::size_t>(ids[nd][c])];
        s = std::max(s, std::abs(v));
      }
  for (double& s : scale_) s = s > 0.0 ? 1.0 / s : 1.0;
  index_.resize(static_cast<std::size_t>(nodes));
  columns_.resize(static_cast<std::size_t>(nodes));
  for (std::size_t nd = 0; nd < ids.size(); ++nd) {
    std::vector<std::size_t> order(ids[nd].size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ids[nd][a] < ids[nd][b]; });
    columns_[nd].resize(6, static_cast<Eigen::Index>(order.size()));
    for (std::size_t c = 0; c < order.size(); ++c) {
      const int id = ids[nd][order[c]];
      index_[nd].push_back(id);
      for (int r = 0; r < 6; ++r)
        columns_[nd](r, static_cast<Eigen::Index>(c)) =
            cols[nd][order[c]][static_cast<std::size_t>(r)] * scale_[static_cast<std::size_t>(id)];
    }
  }
}

void ResidualBasis3d::stress_function_columns(double y, double z, std::vector<int>& ids,
                                              std::vector<Voigt>& cols) const {
  const CubicBSplineBasis& by = y_basis_[0];
  const CubicBSplineBasis& bz = z_basis_[0];
  if (y < by.breakpoints().front() || y > by.breakpoints().back() || z < 0.0 || z > bz.breakpoints().back()) return;
  const CubicBSplineBasis::Local ly = by.evaluate(y), lz = bz.evaluate(z);
  const int ny = by.size(), nz = bz.size();
  constexpr std::size_t yy = 1, zz = 2, yz = 3, xz = 4, xy = 5;
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t t = 0; t < 4; ++t) {
      const int a = ly.first + static_cast<int>(r), b = lz.first + static_cast<int>(t);
      const double y0 = ly.derivative[0][r], y1 = ly.derivative[1][r], y2 = ly.derivative[2][r];
      const double z0 = lz.derivative[0][t], z1 = lz.derivative[1][t], z2 = lz.derivative[2][t];
      if (a >= 2 && a <= ny - 3 && b >= 2 && b <= nz - 3) {  // phi: (4), phi = grad phi = 0 on the box
        Voigt v{};
        v[yy] = y0 * z2;
        v[zz] = y2 * z0;
        v[yz] = -y1 * z1;
        if (v[yy] != 0.0 || v[zz] != 0.0 || v[yz] != 0.0) {
          ids.push_back(phi_first_ + (a - 2) * phi_nb_ + (b - 2));
          cols.push_back(v);
        }
      }
      if (a >= 1 && a <= ny - 2 && b >= 1 && b <= nz - 2) {  // psi: (4), psi = 0 on the box
        Voigt v{};
        v[xy] = y0 * z1;
        v[xz] = -y1 * z0;
        if (v[xy] != 0.0 || v[xz] != 0.0) {
          ids.push_back(psi_first_ + (a - 1) * psi_nb_ + (b - 1));
          cols.push_back(v);
        }
      }
    }
}

Voigt ResidualBasis3d::at_node(const std::vector<double>& theta, int k, int j) const {
  Voigt rho{};
  const std::vector<int>& id = index(k, j);
  const auto& a = columns(k, j);
  for (std::size_t c = 0; c < id.size(); ++c)
    for (int r = 0; r < 6; ++r)
      rho[static_cast<std::size_t>(r)] += a(r, static_cast<Eigen::Index>(c)) * theta[static_cast<std::size_t>(id[c])];
  return rho;
}

Voigt ResidualBasis3d::stress_function_part(const std::vector<double>& theta, double y, double z) const {
  Voigt rho{};
  if (!splines_) return rho;
  std::vector<int> ids;
  std::vector<Voigt> cols;
  stress_function_columns(y, z, ids, cols);
  for (std::size_t c = 0; c < ids.size(); ++c) {
    const double t = theta[static_cast<std::size_t>(ids[c])] * scale_[static_cast<std::size_t>(ids[c])];
    for (std::size_t r = 0; r < 6; ++r) rho[r] += cols[c][r] * t;
  }
  return rho;
}

ShakedownResult solve_shakedown_3d(const StressHistory3d& history, const YieldCriterion& criterion,
                                   const ResidualModel3d& model, const ShakedownOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string why = options.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  if (const std::string why = history.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  if (const std::string why = criterion.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  if (criterion.kind == YieldKind::tresca_plane_xz)
    throw std::invalid_argument("shakedown: criterion: tresca_plane_xz checks the x-z plane only; in 3-D use "
                                "von_mises or tresca_inscribed");
  const ResidualBasis3d basis(history.depths, history.lines, model);
  const int nk = history.n_depths(), nj = history.n_lines(), ni = history.n_positions();
  const Eigen::MatrixXd l = criterion.factor();
  const double k_shear = criterion.shear_yield();

  // Stations: one per node (k, j) with its nx positions, or one per depth with every line's.
  ShakedownStations s;
  s.stations = model.vary_across ? nk * nj : nk;
  s.positions = model.vary_across ? ni : nj * ni;
  s.unknowns = basis.unknowns();
  s.u.resize(l.rows(), static_cast<Eigen::Index>(history.stress.size()));
  for (std::size_t c = 0; c < history.stress.size(); ++c)
    s.u.col(static_cast<Eigen::Index>(c)) = l * Eigen::Map<const Eigen::Matrix<double, 6, 1>>(history.stress[c].data());
  for (int st = 0; st < s.stations; ++st) {
    const int k = model.vary_across ? st / nj : st, j = model.vary_across ? st % nj : 0;
    s.index.push_back(basis.index(k, j));
    s.w.push_back(k_shear * l * basis.columns(k, j));
  }

  std::vector<double> theta;
  ShakedownResult out = solve_shakedown_stations(s, options, theta);
  // Stations and samples back to (depth, line, position); the sample order is the history's.
  const auto split = [&](int station, int& depth, int& line) {
    depth = model.vary_across ? station / nj : station;
    line = model.vary_across ? station % nj : -1;
  };
  if (criterion.outer_factor() != 1.0) {
    std::size_t worst = 0;
    out.elastic_limit = exact_elastic_limit(history.stress, criterion, worst);
    out.elastic_limit_depth = static_cast<int>(worst / static_cast<std::size_t>(nj * ni));
    out.elastic_limit_line = static_cast<int>(worst / static_cast<std::size_t>(ni) % static_cast<std::size_t>(nj));
    out.elastic_limit_position = static_cast<int>(worst % static_cast<std::size_t>(ni));
  } else if (out.elastic_limit_depth >= 0) {
    const std::size_t sample = static_cast<std::size_t>(out.elastic_limit_depth) * static_cast<std::size_t>(s.positions) +
                               static_cast<std::size_t>(out.elastic_limit_position);
    out.elastic_limit_depth = static_cast<int>(sample / static_cast<std::size_t>(nj * ni));
    out.elastic_limit_line = static_cast<int>(sample / static_cast<std::size_t>(ni) % static_cast<std::size_t>(nj));
    out.elastic_limit_position = static_cast<int>(sample % static_cast<std::size_t>(ni));
  }
  if (out.critical_depth >= 0) split(out.critical_depth, out.critical_depth, out.critical_line);
  out.residual.assign(static_cast<std::size_t>(nk * nj), Voigt{});
  if (out.status != ShakedownStatus::unbounded && out.status != ShakedownStatus::failed)
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j < nj; ++j) {
        Voigt rho = basis.at_node(theta, k, j);
        for (double& v : rho) v *= k_shear;
        out.residual[static_cast<std::size_t>(k * nj + j)] = rho;
      }
  out.limit_upper_bound = out.certificate.upper_bound * criterion.outer_factor();
  set_shakedown_verdict(out);
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace dc

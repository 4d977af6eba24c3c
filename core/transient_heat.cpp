#include "transient_heat.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "errors.hpp"
#include "fft_planning.hpp"
#include "number_text.hpp"

namespace dc {
namespace {
constexpr double kTransientPi = std::numbers::pi;

/// The periodic distance (in elements) of box index `i` from the grid's indices [0, n).
double transient_grid_distance(int i, int n, int m) {
  return i < n ? 0.0 : static_cast<double>(std::min(i - (n - 1), m - i));
}

/// The fringe's rise s(d): 0 up to a quarter of the padding, 1 from its middle (C1 smoothstep).
double transient_fringe_rise(double d, int padding) {
  if (padding <= 0) return 0.0;
  const double quarter = 0.25 * padding;
  const double u = std::clamp((d - quarter) / quarter, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

/// Periodic wave number of DFT index j of m points of spacing d.
double transient_wave(int j, int m, double d) {
  const int signed_j = j <= m / 2 ? j : j - m;
  return 2.0 * kTransientPi * signed_j / (m * d);
}
}  // namespace

TransientHeat::TransientHeat(const Grid& grid, const ThermalProperties& properties, double step, double duration,
                             const TransientHeatOptions& options, const std::string& key)
    : grid_(grid),
      properties_(ThermalProperties::make(properties.conductivity, properties.diffusivity, key)),
      mx_(fft_good_size(std::max(2, options.padding) * grid.nx)),
      my_(grid.dimension == 3 ? fft_good_size(std::max(2, options.padding) * grid.ny) : 1),
      nz_(0),
      modes_(static_cast<std::size_t>(mx_ / 2 + 1) * static_cast<std::size_t>(my_)),
      depth_(0.0),
      surface_fft_(grid.nx, grid.dimension == 3 ? grid.ny : 1, mx_, my_),
      box_fft_(mx_, my_, mx_, my_) {
  if (!(std::isfinite(step) && step > 0.0 && std::isfinite(duration) && duration >= step))
    throw std::invalid_argument("transient heat: the step (" + six_digits(step) + " s) must be > 0 and the duration (" +
                                six_digits(duration) + " s) at least the step");
  if (!(options.first_cell > 0.0 && options.depth_ratio > 1.0 && options.depth_lengths > 0.0))
    throw std::invalid_argument("transient heat: the depth grid needs first_cell > 0, depth_ratio > 1, depth_lengths > 0");
  const double kappa = properties_.diffusivity;
  // The depth grid resolves the step's diffusion length and the shortest wave's decay length.
  const double k_max = grid.dimension == 3 ? kTransientPi * std::hypot(1.0 / grid.dx, 1.0 / grid.dy)
                                           : kTransientPi / grid.dx;
  const double resolved = std::min(std::sqrt(kappa * step), 1.0 / k_max);
  const double target = std::max(options.depth_lengths * std::sqrt(kappa * duration), 20.0 * resolved);
  for (double dz = options.first_cell * resolved; depth_ < target; dz *= options.depth_ratio) {
    dz_.push_back(dz);
    depth_ += dz;
  }
  nz_ = static_cast<int>(dz_.size());
  cell_.resize(dz_.size());
  for (int l = 0; l < nz_; ++l) cell_[l] = 0.5 * ((l > 0 ? dz_[l - 1] : 0.0) + dz_[l]);

  wave_x_.resize(modes_);
  wave2_.resize(modes_);
  const double dy = grid.dimension == 3 ? grid.dy : 1.0;
  for (int i = 0; i <= mx_ / 2; ++i)
    for (int j = 0; j < my_; ++j) {
      const std::size_t m = static_cast<std::size_t>(i) * my_ + j;
      const double kx = transient_wave(i, mx_, grid.dx), ky = my_ > 1 ? transient_wave(j, my_, dy) : 0.0;
      // A real field's Nyquist column cannot be translated (its phase is lost): it stays.
      wave_x_[m] = 2 * i == mx_ ? 0.0 : kx;
      wave2_[m] = kx * kx + ky * ky;
    }
  // The fringe factor per box point, with the inverse DFT's 1/(mx my).
  fringe_.resize(static_cast<std::size_t>(mx_) * my_);
  const int ny = grid.dimension == 3 ? grid.ny : 1;
  for (int j = 0; j < my_; ++j)
    for (int i = 0; i < mx_; ++i) {
      const double sx = transient_fringe_rise(transient_grid_distance(i, grid.nx, mx_), mx_ - grid.nx);
      const double sy = my_ > 1 ? transient_fringe_rise(transient_grid_distance(j, ny, my_), my_ - ny) : 0.0;
      fringe_[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx_) * j] =
          (1.0 - std::max(sx, sy)) / (static_cast<double>(mx_) * my_);
    }
  state_.assign(modes_ * nz_, 0.0);
  response_.assign(modes_ * nz_, 0.0);
  unit_.assign(modes_ * nz_, 0.0);
  flux_.assign(modes_, 0.0);
  work_.resize(nz_);
  real_work_.resize(nz_);
  box_.resize(static_cast<std::size_t>(mx_) * my_);
}

void TransientHeat::solve_shifted(std::complex<double> shift, std::complex<double>* b) {
  const double kappa = properties_.diffusivity;
  std::complex<double> previous_c = 0.0;
  for (int l = 0; l < nz_; ++l) {
    const double lower = l > 0 ? -kappa / dz_[l - 1] : 0.0, upper = -kappa / dz_[l];
    const std::complex<double> pivot = shift * cell_[l] - lower - upper - lower * previous_c;
    const std::complex<double> inverse = std::conj(pivot) / std::norm(pivot);  // no libgcc complex division
    b[l] = (b[l] - lower * (l > 0 ? b[l - 1] : 0.0)) * inverse;
    previous_c = upper * inverse;
    work_[l] = previous_c;
  }
  for (int l = nz_ - 2; l >= 0; --l) b[l] -= work_[l] * b[l + 1];
}

void TransientHeat::solve_real_shifted(double shift, std::complex<double>* b1, std::complex<double>* b2) {
  const double kappa = properties_.diffusivity;
  double previous_c = 0.0;
  for (int l = 0; l < nz_; ++l) {
    const double lower = l > 0 ? -kappa / dz_[l - 1] : 0.0, upper = -kappa / dz_[l];
    const double inverse = 1.0 / (shift * cell_[l] - lower - upper - lower * previous_c);
    if (l > 0) {
      b1[l] -= lower * b1[l - 1];
      b2[l] -= lower * b2[l - 1];
    }
    b1[l] *= inverse;
    b2[l] *= inverse;
    previous_c = upper * inverse;
    real_work_[l] = previous_c;
  }
  for (int l = nz_ - 2; l >= 0; --l) {
    b1[l] -= real_work_[l] * b1[l + 1];
    b2[l] -= real_work_[l] * b2[l + 1];
  }
}

void TransientHeat::apply_fringe(std::vector<std::complex<double>>& field) {
  const int nz = nz_;
  auto* spectrum = reinterpret_cast<std::complex<double>*>(box_fft_.spectrum());
  for (int l = 0; l < nz; ++l) {
    for (std::size_t m = 0; m < modes_; ++m) spectrum[m] = field[m * nz + l];
    box_fft_.inverse(box_.data());
    for (std::size_t p = 0; p < box_.size(); ++p) box_[p] *= fringe_[p];
    box_fft_.forward(box_.data());
    for (std::size_t m = 0; m < modes_; ++m) field[m * nz + l] = spectrum[m];
  }
}

void TransientHeat::prepare(double h, double speed, const double* flux, double* free, double* response) {
  if (prepared_) throw std::logic_error("transient heat: prepare() twice without commit()");
  if (!(std::isfinite(h) && h > 0.0 && std::isfinite(speed)))
    throw std::invalid_argument("transient heat: a step needs h > 0 and a finite speed, got h = " + six_digits(h) +
                                " s, speed " + six_digits(speed) + " m/s");
  const double source = properties_.diffusivity / properties_.conductivity;
  const int nz = nz_;
  // Sub-steps: the heat of one travels at most an eighth of the padding (5).
  const double reach = 0.125 * (mx_ - grid_.nx) * grid_.dx;
  const int subs = std::max(1, static_cast<int>(std::ceil(std::abs(speed) * h / reach)));
  const double hs = h / subs;
  last_substeps_ = subs;
  surface_fft_.forward(flux);
  const auto* spectrum = reinterpret_cast<const std::complex<double>*>(surface_fft_.spectrum());
  std::copy(spectrum, spectrum + modes_, flux_.begin());
  // The unit flux's sub-step u_k of (4) per mode (kept while the sub-step and the speed are).
  const bool unit_kept = hs == unit_step_ && speed == unit_speed_;
  unit_step_ = hs;
  unit_speed_ = speed;
  for (std::size_t m = 0; m < modes_ && !unit_kept; ++m) {
    const double mu = properties_.diffusivity * wave2_[m];
    const std::complex<double> turn = std::polar(1.0, wave_x_[m] * speed * hs);
    std::complex<double>* u = &unit_[m * nz];
    std::fill(u, u + nz, 0.0);
    u[0] = 1.0 / hs;
    solve_shifted(mu + 1.0 / hs, u);  // y = (W + hs A)^-1 e_0
    for (int l = 0; l < nz; ++l) u[l] = turn * cell_[l] * u[l] - (l == 0 ? 1.0 : 0.0);
    solve_shifted(std::complex<double>(mu, -wave_x_[m] * speed), u);
    for (int l = 0; l < nz; ++l) u[l] *= -source;
  }
  std::fill(response_.begin(), response_.end(), 0.0);
  for (int sub = 0; sub < subs; ++sub) {
    for (std::size_t m = 0; m < modes_; ++m) {
      const double mu = properties_.diffusivity * wave2_[m];
      const std::complex<double> turn = std::polar(1.0, wave_x_[m] * speed * hs);
      std::complex<double>* theta = &state_[m * nz];
      std::complex<double>* rho = &response_[m * nz];
      for (int l = 0; l < nz; ++l) {
        theta[l] *= cell_[l] / hs;
        rho[l] *= cell_[l] / hs;
      }
      solve_real_shifted(mu + 1.0 / hs, theta, rho);
      const std::complex<double>* u = &unit_[m * nz];
      for (int l = 0; l < nz; ++l) {
        theta[l] *= turn;
        rho[l] = turn * rho[l] + flux_[m] * u[l];
      }
    }
    if (sub + 1 < subs) {  // the last sub-step's fringe: commit's, on the sum (the grid's values are the same)
      apply_fringe(state_);
      apply_fringe(response_);
    }
  }
  const double scale = 1.0 / (static_cast<double>(mx_) * my_);
  auto* out = reinterpret_cast<std::complex<double>*>(surface_fft_.spectrum());
  for (std::size_t m = 0; m < modes_; ++m) out[m] = state_[m * nz];
  surface_fft_.inverse(free);
  for (std::size_t m = 0; m < modes_; ++m) out[m] = response_[m * nz];
  surface_fft_.inverse(response);
  for (std::size_t e = 0; e < grid_.size(); ++e) {
    free[e] *= scale;
    response[e] *= scale;
  }
  prepared_ = true;
}

void TransientHeat::commit(double share) {
  if (!prepared_) throw std::logic_error("transient heat: commit() without prepare()");
  for (std::size_t p = 0; p < state_.size(); ++p) state_[p] += share * response_[p];
  apply_fringe(state_);
  prepared_ = false;
}

double TransientHeat::heat_content() const {
  double sum = 0.0;
  for (int l = 0; l < nz_; ++l) sum += cell_[l] * state_[l].real();  // mode (0, 0): the sum over the box
  return properties_.conductivity / properties_.diffusivity * sum * grid_.area();
}

void TransientHeat::step(double h, double speed, const double* flux, double* temperature) {
  std::vector<double>& free = box_;  // box_ holds at least grid.size() values
  prepare(h, speed, flux, free.data(), temperature);
  for (std::size_t e = 0; e < grid_.size(); ++e) temperature[e] += free[e];
  commit(1.0);
}

}  // namespace dc

#include "tangential_preconditioner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fft_planning.hpp"
#include "periodic_kernel.hpp"

namespace dc {

TangentialPreconditioner::TangentialPreconditioner(const LinearOperator& compliance, const Grid& grid)
    : n_(grid.size()),
      comps_(grid.dimension == 2 ? 1 : 2),
      fft_(grid.nx, grid.ny, fft_good_size(grid.nx), grid.ny == 1 ? 1 : fft_good_size(grid.ny)) {
  if (compliance.rows() != comps_ * n_ || compliance.cols() != comps_ * n_)
    throw std::invalid_argument("tangential preconditioner: operator and grid sizes differ");
  const int ic = grid.nx / 2, jc = grid.ny / 2, mx = fft_.mx(), my = fft_.my();
  const std::size_t ncplx = fft_.spectrum_size();
  // spectra[out * comps + in]: the periodic kernel of component `in` -> `out`
  // (periodic_kernel.hpp). The diagonal of M^-1 is the same at every element (translation
  // invariance): kept from M^-1 applied to the centre's unit load, once the symbol is known.
  std::vector<std::vector<double>> spectra(static_cast<std::size_t>(comps_ * comps_));
  std::vector<double> unit(comps_ * n_, 0.0), response;
  for (int in = 0; in < comps_; ++in) {
    std::fill(unit.begin(), unit.end(), 0.0);
    unit[in * n_ + grid.index(ic, jc)] = 1.0;
    compliance.apply(unit, response);
    for (int out = 0; out < comps_; ++out)
      fft_.periodic_forward(periodic_kernel_box(response, out * n_, grid, mx, my),
                            spectra[static_cast<std::size_t>(out * comps_ + in)]);
  }
  // The kernels are even, so the symbols are real: per wavenumber a symmetric 2 x 2 matrix,
  // inverted through its eigenvalues bounded below (truncation can leave tiny or negative
  // values far in the tail).
  const auto sym = [&](int out, int in, std::size_t k) {
    return spectra[static_cast<std::size_t>(out * comps_ + in)][2 * k];
  };
  double s_max = 0.0;
  for (std::size_t k = 0; k < ncplx; ++k) s_max = std::max(s_max, sym(0, 0, k));
  if (!(s_max > 0.0)) throw std::invalid_argument("tangential preconditioner: the kernel's spectrum is not positive");
  const double floor = 1e-6 * s_max, norm = static_cast<double>(mx) * my;
  ixx_.resize(ncplx);
  ixy_.assign(ncplx, 0.0);
  iyy_.assign(ncplx, 0.0);
  for (std::size_t k = 0; k < ncplx; ++k) {
    if (comps_ == 1) {
      ixx_[k] = 1.0 / (std::max(sym(0, 0, k), floor) * norm);
      continue;
    }
    const double a = sym(0, 0, k), d = sym(1, 1, k), b = 0.5 * (sym(0, 1, k) + sym(1, 0, k));
    // Eigen-decomposition of [[a, b], [b, d]]: l1,2 = m +- h, the first eigenvector at angle t.
    const double m = 0.5 * (a + d), h = std::hypot(0.5 * (a - d), b), t = 0.5 * std::atan2(2.0 * b, a - d);
    const double c = std::cos(t), s = std::sin(t);
    const double i1 = 1.0 / (std::max(m + h, floor) * norm), i2 = 1.0 / (std::max(m - h, floor) * norm);
    ixx_[k] = c * c * i1 + s * s * i2;
    iyy_[k] = s * s * i1 + c * c * i2;
    ixy_[k] = c * s * (i1 - i2);
  }
  if (comps_ == 2) spectrum_x_.resize(2 * ncplx);
  for (int c = 0; c < comps_; ++c) {
    std::fill(unit.begin(), unit.end(), 0.0);
    unit[c * n_ + grid.index(ic, jc)] = 1.0;
    apply(unit, response);
    diagonal_[c] = response[c * n_ + grid.index(ic, jc)];
  }
}

void TangentialPreconditioner::apply(const double* x, double* y) const {
  const std::size_t ncplx = fft_.spectrum_size();
  double* s = fft_.spectrum();
  if (comps_ == 1) {
    fft_.forward(x);
    for (std::size_t k = 0; k < ncplx; ++k) {
      s[2 * k] *= ixx_[k];
      s[2 * k + 1] *= ixx_[k];
    }
    fft_.inverse(y);
    return;
  }
  fft_.forward(x);
  std::copy(s, s + 2 * ncplx, spectrum_x_.begin());
  fft_.forward(x + n_);
  // (zx, zy) = S^-1 (rx, ry) per wavenumber; zx kept in spectrum_x_, zy in the transform's buffer.
  for (std::size_t k = 0; k < ncplx; ++k)
    for (int part = 0; part < 2; ++part) {
      const double rx = spectrum_x_[2 * k + part], ry = s[2 * k + part];
      spectrum_x_[2 * k + part] = ixx_[k] * rx + ixy_[k] * ry;
      s[2 * k + part] = ixy_[k] * rx + iyy_[k] * ry;
    }
  fft_.inverse(y + n_);
  std::copy(spectrum_x_.begin(), spectrum_x_.end(), s);
  fft_.inverse(y);
}

double TangentialPreconditioner::diagonal(std::size_t i) const { return diagonal_[i / n_]; }

Eigen::MatrixXd TangentialPreconditioner::to_dense(std::size_t max_entries) const {
  return dense_by_columns(*this, max_entries, "tangential preconditioner");
}

}  // namespace dc

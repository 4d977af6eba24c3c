#include "normal_preconditioner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fft_planning.hpp"
#include "interrupt.hpp"
#include "periodic_kernel.hpp"

namespace dc {

NormalPreconditioner::NormalPreconditioner(const LinearOperator& compliance, const Grid& grid)
    : n_(grid.size()),
      fft_(grid.nx, grid.ny, fft_good_size(grid.nx), grid.ny == 1 ? 1 : fft_good_size(grid.ny)),
      work_(grid.size()) {
  if (compliance.rows() != n_ || compliance.cols() != n_)
    throw std::invalid_argument("normal preconditioner: operator and grid sizes differ");
  // The kernel K(di, dj) = response at offset (di, dj) of a unit load at the centre (ic, jc).
  const int ic = grid.nx / 2, jc = grid.ny / 2;
  std::vector<double> unit(n_, 0.0), response;
  unit[grid.index(ic, jc)] = 1.0;
  throw_if_interrupted();  // each step below takes a large grid a few tenths of a second
  compliance.apply(unit, response);
  throw_if_interrupted();
  const int mx = fft_.mx(), my = fft_.my();
  const std::vector<double> box = periodic_kernel_box(response, 0, grid, mx, my);
  std::vector<double> spectrum;
  fft_.periodic_forward(box, spectrum);
  throw_if_interrupted();
  // The kernel is even, so its spectrum is real; truncation can leave a few tiny or negative
  // values far in the tail: bound them below by a small fraction of the largest.
  const std::size_t ncplx = fft_.spectrum_size();
  double s_max = 0.0;
  for (std::size_t k = 0; k < ncplx; ++k) s_max = std::max(s_max, spectrum[2 * k]);
  if (!(s_max > 0.0)) throw std::invalid_argument("normal preconditioner: the kernel's spectrum is not positive");
  double s_min_positive = s_max;
  for (std::size_t k = 0; k < ncplx; ++k)
    if (spectrum[2 * k] > 0.0) s_min_positive = std::min(s_min_positive, spectrum[2 * k]);
  const double floor = std::max(s_min_positive, 1e-6 * s_max);
  inverse_symbol_.resize(ncplx);
  const double norm = static_cast<double>(mx) * my;
  for (std::size_t k = 0; k < ncplx; ++k) inverse_symbol_[k] = 1.0 / (std::max(spectrum[2 * k], floor) * norm);
}

void NormalPreconditioner::apply(const double* r, const char* active, double scale, double* z) const {
  for (std::size_t i = 0; i < n_; ++i) work_[i] = active[i] ? r[i] : 0.0;
  fft_.forward(work_.data());
  double* s = fft_.spectrum();
  const std::size_t ncplx = fft_.spectrum_size();
  for (std::size_t k = 0; k < ncplx; ++k) {
    s[2 * k] *= inverse_symbol_[k];
    s[2 * k + 1] *= inverse_symbol_[k];
  }
  fft_.inverse(z);
  for (std::size_t i = 0; i < n_; ++i) z[i] = active[i] ? scale * z[i] : 0.0;
}

}  // namespace dc

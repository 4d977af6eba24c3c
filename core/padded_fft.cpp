#include "padded_fft.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fftw3.h>

#include "fft_planning.hpp"

namespace dc {
namespace {
fftw_plan as_plan(void* p) { return static_cast<fftw_plan>(p); }
fftw_complex* as_complex(double* p) { return reinterpret_cast<fftw_complex*>(p); }
}  // namespace

PaddedFft::PaddedFft(int nx, int ny, int mx, int my)
    : nx_(nx), ny_(ny), mx_(mx), my_(my), mxc_(mx / 2 + 1) {
  if (nx < 1 || ny < 1 || mx < nx || my < ny) throw std::invalid_argument("padded FFT: box smaller than the field");
  const std::size_t row_values = static_cast<std::size_t>(mx_) * ny_;
  input_ = fftw_alloc_real(row_values);
  output_ = fftw_alloc_real(row_values);
  spectrum_ = reinterpret_cast<double*>(fftw_alloc_complex(spectrum_size()));
  if (!input_ || !output_ || !spectrum_) throw std::bad_alloc();
  std::fill(input_, input_ + row_values, 0.0);
  std::fill(spectrum_, spectrum_ + 2 * spectrum_size(), 0.0);
  {
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    fftw_plan_with_nthreads(fft_threads_for(static_cast<std::size_t>(mx_) * my_));
    const unsigned flags = FFTW_ESTIMATE;
    // Along x: ny real rows of length mx <-> ny complex rows of length mxc.
    rows_forward_ = fftw_plan_many_dft_r2c(1, &mx_, ny_, input_, nullptr, 1, mx_, as_complex(spectrum_), nullptr, 1,
                                           mxc_, flags | FFTW_PRESERVE_INPUT);
    rows_inverse_ = fftw_plan_many_dft_c2r(1, &mx_, ny_, as_complex(spectrum_), nullptr, 1, mxc_, output_, nullptr, 1,
                                           mx_, flags);
    // Along y, in place: mxc columns of length my (stride mxc).
    if (my_ > 1) {
      columns_forward_ = fftw_plan_many_dft(1, &my_, mxc_, as_complex(spectrum_), nullptr, mxc_, 1,
                                            as_complex(spectrum_), nullptr, mxc_, 1, FFTW_FORWARD, flags);
      columns_inverse_ = fftw_plan_many_dft(1, &my_, mxc_, as_complex(spectrum_), nullptr, mxc_, 1,
                                            as_complex(spectrum_), nullptr, mxc_, 1, FFTW_BACKWARD, flags);
    }
  }
  if (!rows_forward_ || !rows_inverse_ || (my_ > 1 && (!columns_forward_ || !columns_inverse_)))
    throw std::runtime_error("FFTW could not plan a padded transform");
}

PaddedFft::~PaddedFft() {
  {
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    for (void* p : {rows_forward_, rows_inverse_, columns_forward_, columns_inverse_})
      if (p) fftw_destroy_plan(as_plan(p));
  }
  fftw_free(input_);
  fftw_free(output_);
  fftw_free(spectrum_);
}

void PaddedFft::forward(const double* field) {
  for (int j = 0; j < ny_; ++j)
    std::memcpy(input_ + static_cast<std::size_t>(mx_) * j, field + static_cast<std::size_t>(nx_) * j,
                sizeof(double) * nx_);
  fftw_execute(as_plan(rows_forward_));
  if (my_ > 1) {
    // The padding rows are zero in space, so zero after the x transform too.
    const std::size_t filled = 2 * static_cast<std::size_t>(mxc_) * ny_;
    std::fill(spectrum_ + filled, spectrum_ + 2 * spectrum_size(), 0.0);
    fftw_execute(as_plan(columns_forward_));
  }
}

void PaddedFft::inverse(double* field) {
  if (my_ > 1) fftw_execute(as_plan(columns_inverse_));
  fftw_execute(as_plan(rows_inverse_));
  for (int j = 0; j < ny_; ++j)
    std::memcpy(field + static_cast<std::size_t>(nx_) * j, output_ + static_cast<std::size_t>(mx_) * j,
                sizeof(double) * nx_);
}

void PaddedFft::periodic_forward(const std::vector<double>& box, std::vector<double>& out) const {
  if (box.size() != static_cast<std::size_t>(mx_) * my_) throw std::invalid_argument("padded FFT: box size");
  // FFTW's own (SIMD-aligned) buffers: planned on a std::vector's storage, the transform's
  // codelets, hence its round-off, would depend on where the heap happened to place it (a
  // process under mpirun gave other last digits than the same run without).
  const std::size_t complex_values = spectrum_size();
  double* in = fftw_alloc_real(box.size());
  fftw_complex* spectrum = fftw_alloc_complex(complex_values);
  if (!in || !spectrum) {
    fftw_free(in);
    fftw_free(spectrum);
    throw std::bad_alloc();
  }
  std::copy(box.begin(), box.end(), in);
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    fftw_plan_with_nthreads(1);
    plan = my_ > 1 ? fftw_plan_dft_r2c_2d(my_, mx_, in, spectrum, FFTW_ESTIMATE)
                   : fftw_plan_dft_r2c_1d(mx_, in, spectrum, FFTW_ESTIMATE);
  }
  if (plan) {
    fftw_execute(plan);
    const double* values = reinterpret_cast<const double*>(spectrum);
    out.assign(values, values + 2 * complex_values);
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    fftw_destroy_plan(plan);
  }
  fftw_free(in);
  fftw_free(spectrum);
  if (!plan) throw std::runtime_error("FFTW could not plan a periodic transform");
}

}  // namespace dc

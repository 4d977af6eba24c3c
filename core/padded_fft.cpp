#include "padded_fft.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fftw3.h>

#include "fft_planning.hpp"
#include "huge_pages.hpp"

namespace dc {
namespace {
fftw_plan as_plan(void* p) { return static_cast<fftw_plan>(p); }
fftw_complex* as_complex(double* p) { return reinterpret_cast<fftw_complex*>(p); }

/// Row length (complex entries) of the row buffer: at least mxc, and not within 4 entries of a
/// multiple of 256 (4 KiB), where the entries of one column would map to the same cache sets.
int padded_row_length(int mxc) {
  int s = mxc;
  while (s % 256 < 4 || s % 256 > 252) ++s;
  return s;
}
}  // namespace

PaddedFft::PaddedFft(int nx, int ny, int mx, int my, int stored_spectra)
    : nx_(nx), ny_(ny), mx_(mx), my_(my), mxc_(mx / 2 + 1) {
  if (nx < 1 || ny < 1 || mx < nx || my < ny || (my == 1 && ny != 1) || stored_spectra < 0)
    throw std::invalid_argument("padded FFT: box smaller than the field");
  row_stride_ = my_ > 1 ? padded_row_length(mxc_) : mxc_;
  // Whole multiples of 8 complex entries (128 bytes): every slot keeps the alignment of the
  // buffer the plans were made for (fftw_execute_dft requires it).
  slot_stride_ = 2 * ((spectrum_size() + 7) / 8 * 8);
  const std::size_t real_values = static_cast<std::size_t>(mx_) * ny_;
  const std::size_t row_values = static_cast<std::size_t>(row_stride_) * my_;
  real_ = fftw_alloc_real(real_values);
  spectrum_ = reinterpret_cast<double*>(fftw_alloc_complex(spectrum_size()));
  if (my_ > 1) rows_ = reinterpret_cast<double*>(fftw_alloc_complex(row_values));
  if (stored_spectra > 0) stored_ = fftw_alloc_real(slot_stride_ * stored_spectra);
  if (!real_ || !spectrum_ || (my_ > 1 && !rows_) || (stored_spectra > 0 && !stored_)) {
    fftw_free(real_);
    fftw_free(spectrum_);
    fftw_free(rows_);
    fftw_free(stored_);
    throw std::bad_alloc();
  }
  // Their first touch (the fills below) on 2 MiB pages where the kernel allows (huge_pages.hpp).
  advise_huge_pages(real_, sizeof(double) * real_values);
  advise_huge_pages(spectrum_, 2 * sizeof(double) * spectrum_size());
  if (rows_) advise_huge_pages(rows_, 2 * sizeof(double) * row_values);
  if (stored_) advise_huge_pages(stored_, sizeof(double) * slot_stride_ * stored_spectra);
  std::fill(real_, real_ + real_values, 0.0);
  std::fill(spectrum_, spectrum_ + 2 * spectrum_size(), 0.0);
  if (rows_) std::fill(rows_, rows_ + 2 * row_values, 0.0);
  if (stored_) std::fill(stored_, stored_ + slot_stride_ * stored_spectra, 0.0);
  {
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    fftw_plan_with_nthreads(fft_threads_for(static_cast<std::size_t>(mx_) * my_));
    const unsigned flags = FFTW_ESTIMATE;
    // Along x: ny real rows of length mx <-> ny complex rows of length mxc (straight into the
    // spectrum for one-dimensional fields).
    double* row_spectra = my_ > 1 ? rows_ : spectrum_;
    rows_forward_ = fftw_plan_many_dft_r2c(1, &mx_, ny_, real_, nullptr, 1, mx_, as_complex(row_spectra), nullptr, 1,
                                           row_stride_, flags);
    rows_inverse_ = fftw_plan_many_dft_c2r(1, &mx_, ny_, as_complex(row_spectra), nullptr, 1, row_stride_, real_,
                                           nullptr, 1, mx_, flags);
    // Along y: mxc columns of length my, strided in the row buffer, contiguous in the spectrum.
    if (my_ > 1) {
      columns_forward_ = fftw_plan_many_dft(1, &my_, mxc_, as_complex(rows_), nullptr, row_stride_, 1,
                                            as_complex(spectrum_), nullptr, 1, my_, FFTW_FORWARD, flags);
      columns_inverse_ = fftw_plan_many_dft(1, &my_, mxc_, as_complex(spectrum_), nullptr, 1, my_,
                                            as_complex(rows_), nullptr, row_stride_, 1, FFTW_BACKWARD,
                                            flags | FFTW_DESTROY_INPUT);
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
  fftw_free(real_);
  fftw_free(rows_);
  fftw_free(spectrum_);
  fftw_free(stored_);
}

void PaddedFft::transform_rows(const double* field) {
  for (int j = 0; j < ny_; ++j)
    std::memcpy(real_ + static_cast<std::size_t>(mx_) * j, field + static_cast<std::size_t>(nx_) * j,
                sizeof(double) * nx_);
  if (my_ > 1) fftw_execute(as_plan(rows_forward_));
}

void PaddedFft::forward(const double* field) {
  transform_rows(field);
  fftw_execute(as_plan(my_ > 1 ? columns_forward_ : rows_forward_));
}

void PaddedFft::forward_into(const double* field, int slot) {
  double* out = stored_ + slot * slot_stride_;
  transform_rows(field);
  if (my_ > 1)
    fftw_execute_dft(as_plan(columns_forward_), as_complex(rows_), as_complex(out));
  else
    fftw_execute_dft_r2c(as_plan(rows_forward_), real_, as_complex(out));
}

void PaddedFft::inverse(double* field) {
  if (my_ > 1) fftw_execute(as_plan(columns_inverse_));
  fftw_execute(as_plan(rows_inverse_));
  for (int j = 0; j < ny_; ++j) {
    double* row = real_ + static_cast<std::size_t>(mx_) * j;
    std::memcpy(field + static_cast<std::size_t>(nx_) * j, row, sizeof(double) * nx_);
    std::fill(row + nx_, row + mx_, 0.0);  // the padding of the next forward x pass
  }
  // The y pass filled the padding rows; the next forward y pass needs them zero.
  if (my_ > 1)
    std::fill(rows_ + 2 * static_cast<std::size_t>(row_stride_) * ny_,
              rows_ + 2 * static_cast<std::size_t>(row_stride_) * my_, 0.0);
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
    // FFTW's layout is x fastest (ky * mxc + kx); spectrum() is y fastest.
    const double* values = reinterpret_cast<const double*>(spectrum);
    out.resize(2 * complex_values);
    for (int ky = 0; ky < my_; ++ky)
      for (int kx = 0; kx < mxc_; ++kx) {
        const std::size_t from = 2 * (static_cast<std::size_t>(ky) * mxc_ + kx);
        const std::size_t to = 2 * (static_cast<std::size_t>(kx) * my_ + ky);
        out[to] = values[from];
        out[to + 1] = values[from + 1];
      }
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    fftw_destroy_plan(plan);
  }
  fftw_free(in);
  fftw_free(spectrum);
  if (!plan) throw std::runtime_error("FFTW could not plan a periodic transform");
}

}  // namespace dc

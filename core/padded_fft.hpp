#pragma once
// Real 2-D transforms of an nx x ny grid field embedded in a larger mx x my periodic box
// (zero padding for linear convolution). The transform is pruned: along x only the ny rows that
// hold data are transformed (forward) or wanted (inverse); along y every column. That skips
// the rows of zeros a full 2-D transform would process (about a quarter of the work when
// my = 2 ny).
//
// Layout: the x pass writes the ny row spectra into a row buffer whose rows ny..my-1 stay zero;
// the y pass reads its columns (stride: the row length) and writes them contiguous, so the
// spectrum is stored transposed, y fastest: entry (kx, ky) at kx * my + ky. Both passes are
// out of place: in place, FFTW_ESTIMATE plans the strided column pass with a buffering copy
// (fftw_cpy2d, 7 % of a load history) and runs it 20-30 % slower (docs/solvers.md). The row
// length is padded off multiples of 4 KiB so that a column's entries do not share cache sets.
// Plans and buffers are made once (FFTW_ESTIMATE, threads by fft_threads_for); forward() and
// inverse() allocate nothing. Not thread-safe (one set of buffers).
#include <cstddef>
#include <vector>

namespace dc {

class PaddedFft {
 public:
  /// nx <= mx, ny <= my; my == 1 for one-dimensional fields. `stored_spectra`: slots for
  /// spectra kept between transforms (forward_into), e.g. the inputs of a block convolution.
  PaddedFft(int nx, int ny, int mx, int my, int stored_spectra = 0);
  ~PaddedFft();
  PaddedFft(const PaddedFft&) = delete;
  PaddedFft& operator=(const PaddedFft&) = delete;

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int mx() const { return mx_; }
  int my() const { return my_; }
  /// Complex entries of the spectrum: (mx / 2 + 1) * my, y fastest (entry (kx, ky) at kx * my + ky).
  std::size_t spectrum_size() const { return static_cast<std::size_t>(mxc_) * my_; }
  /// The spectrum buffer, interleaved re/im (2 * spectrum_size() doubles).
  double* spectrum() { return spectrum_; }
  const double* spectrum() const { return spectrum_; }
  /// Stored spectrum `slot` (< stored_spectra), the same layout.
  const double* stored(int slot) const { return stored_ + slot * slot_stride_; }

  /// spectrum() = DFT of the field (nx * ny values, x fastest; zero elsewhere in the box).
  void forward(const double* field);
  /// stored(slot) = DFT of the field; spectrum() is left alone.
  void forward_into(const double* field, int slot);
  /// field = inverse DFT of spectrum() on the nx x ny block, unnormalised (a forward and an
  /// inverse multiply by mx * my). spectrum() is overwritten.
  void inverse(double* field);

  /// DFT of a whole mx x my periodic array (x fastest) into `out` (interleaved re/im,
  /// spectrum_size() complex entries, the layout of spectrum()), e.g. a wrapped convolution
  /// kernel. Not for hot loops.
  void periodic_forward(const std::vector<double>& box, std::vector<double>& out) const;

 private:
  void transform_rows(const double* field);  ///< field -> rows_ (the x pass)

  int nx_, ny_, mx_, my_, mxc_;
  int row_stride_;             ///< complex entries per row of rows_ (>= mxc)
  std::size_t slot_stride_;    ///< doubles per stored spectrum (keeps FFTW's alignment)
  double* real_ = nullptr;     ///< ny rows of mx reals; columns nx.. are zero before a forward x pass
  double* rows_ = nullptr;     ///< my rows of row_stride_ complex; rows ny.. are zero before a forward y pass
  double* spectrum_ = nullptr; ///< mxc columns of my complex
  double* stored_ = nullptr;   ///< stored spectra
  void* rows_forward_ = nullptr;
  void* rows_inverse_ = nullptr;
  void* columns_forward_ = nullptr;
  void* columns_inverse_ = nullptr;
};

}  // namespace dc

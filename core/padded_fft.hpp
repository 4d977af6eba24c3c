#pragma once
// Real 2-D transforms of an nx x ny grid field embedded in a larger mx x my periodic box
// (zero padding for linear convolution). The transform is pruned: along x only the ny rows that
// hold data are transformed (forward) or wanted (inverse); along y every column. That skips
// the rows of zeros a full 2-D transform would process (about a quarter of the work when
// my = 2 ny). Plans and buffers are made once (FFTW_ESTIMATE, threads by fft_threads_for);
// forward() and inverse() allocate nothing. Not thread-safe (one set of buffers).
#include <cstddef>
#include <vector>

namespace dc {

class PaddedFft {
 public:
  /// nx <= mx, ny <= my; my == 1 for one-dimensional fields.
  PaddedFft(int nx, int ny, int mx, int my);
  ~PaddedFft();
  PaddedFft(const PaddedFft&) = delete;
  PaddedFft& operator=(const PaddedFft&) = delete;

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int mx() const { return mx_; }
  int my() const { return my_; }
  /// Complex entries of the spectrum: (mx / 2 + 1) * my, x fastest.
  std::size_t spectrum_size() const { return static_cast<std::size_t>(mxc_) * my_; }
  /// The spectrum buffer, interleaved re/im (2 * spectrum_size() doubles).
  double* spectrum() { return spectrum_; }
  const double* spectrum() const { return spectrum_; }

  /// spectrum() = DFT of the field (nx * ny values, x fastest; zero elsewhere in the box).
  void forward(const double* field);
  /// field = inverse DFT of spectrum() on the nx x ny block, unnormalised (a forward and an
  /// inverse multiply by mx * my). spectrum() is overwritten.
  void inverse(double* field);

  /// DFT of a whole mx x my periodic array (x fastest) into `out` (interleaved re/im,
  /// spectrum_size() complex entries), e.g. a wrapped convolution kernel. Not for hot loops.
  void periodic_forward(const std::vector<double>& box, std::vector<double>& out) const;

 private:
  int nx_, ny_, mx_, my_, mxc_;
  double* input_ = nullptr;    ///< ny rows of mx; columns nx.. stay zero
  double* output_ = nullptr;   ///< ny rows of mx
  double* spectrum_ = nullptr; ///< my rows of mxc complex
  void* rows_forward_ = nullptr;
  void* rows_inverse_ = nullptr;
  void* columns_forward_ = nullptr;
  void* columns_inverse_ = nullptr;
};

}  // namespace dc

// The pruned zero-padded transform (core/padded_fft) gives linear convolutions equal to the
// direct sum, in 2-D and 1-D, for box sizes with and without padding; the block convolution
// operator (stored input spectra, products summed per output) equals its dense matrix.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "fft_planning.hpp"
#include "grid.hpp"
#include "linear_operator.hpp"
#include "padded_fft.hpp"

namespace dc {
namespace {

/// y = K * x (linear convolution), K given on offsets |di| < nx, |dj| < ny.
void check_convolution(int nx, int ny, int mx, int my) {
  std::mt19937 rng(7 + nx * 31 + ny);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int kx = 2 * nx - 1, ky = 2 * ny - 1;
  std::vector<double> kernel(static_cast<std::size_t>(kx) * ky), x(static_cast<std::size_t>(nx) * ny);
  for (double& v : kernel) v = u(rng);
  for (double& v : x) v = u(rng);
  auto K = [&](int di, int dj) { return kernel[(di + nx - 1) + static_cast<std::size_t>(kx) * (dj + ny - 1)]; };

  PaddedFft fft(nx, ny, mx, my, 1);
  std::vector<double> box(static_cast<std::size_t>(mx) * my, 0.0), spectrum;
  for (int dj = -(ny - 1); dj <= ny - 1; ++dj)
    for (int di = -(nx - 1); di <= nx - 1; ++di)
      box[(di < 0 ? di + mx : di) + static_cast<std::size_t>(mx) * (dj < 0 ? dj + my : dj)] = K(di, dj);
  fft.periodic_forward(box, spectrum);
  fft.forward_into(x.data(), 0);  // the stored-spectrum path: the same transform, bit for bit
  fft.forward(x.data());
  double* s = fft.spectrum();
  for (std::size_t k = 0; k < 2 * fft.spectrum_size(); ++k) ASSERT_EQ(fft.stored(0)[k], s[k]);
  for (std::size_t k = 0; k < fft.spectrum_size(); ++k) {
    const double re = s[2 * k], im = s[2 * k + 1];
    s[2 * k] = spectrum[2 * k] * re - spectrum[2 * k + 1] * im;
    s[2 * k + 1] = spectrum[2 * k] * im + spectrum[2 * k + 1] * re;
  }
  std::vector<double> y(x.size());
  fft.inverse(y.data());
  const double norm = static_cast<double>(mx) * my;
  double worst = 0.0, scale = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double direct = 0.0;
      for (int jj = 0; jj < ny; ++jj)
        for (int ii = 0; ii < nx; ++ii) direct += K(i - ii, j - jj) * x[ii + static_cast<std::size_t>(nx) * jj];
      worst = std::max(worst, std::abs(y[i + static_cast<std::size_t>(nx) * j] / norm - direct));
      scale = std::max(scale, std::abs(direct));
    }
  EXPECT_LT(worst, 1e-12 * scale) << nx << "x" << ny << " in " << mx << "x" << my;
}

TEST(PaddedFft, LinearConvolutionEqualsTheDirectSum) {
  check_convolution(8, 8, fft_good_size(15), fft_good_size(15));
  check_convolution(7, 5, fft_good_size(13), fft_good_size(9));  // odd sizes, x and y differ
  check_convolution(11, 1, fft_good_size(21), 1);                 // one-dimensional (2-D problems)
  check_convolution(6, 9, 12, 18);                                 // even padded box, y longer
  check_convolution(5, 3, 510, 7);  // 256 complex per row: the row buffer is padded off 4 KiB
}

/// Random kernel tables for an n_out x n_in block operator on `grid`. Symmetry by block, in
/// turn: none (a complex spectrum), even in both offsets (real) and odd along x (imaginary), as
/// the half-space's kernels are.
std::vector<KernelTable> random_blocks(const Grid& grid, int count, unsigned seed, bool symmetric) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<KernelTable> blocks(static_cast<std::size_t>(count));
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    KernelTable& t = blocks[b];
    t.nx = grid.nx;
    t.ny = grid.ny;
    t.values.resize(static_cast<std::size_t>(2 * grid.nx - 1) * static_cast<std::size_t>(2 * grid.ny - 1));
    for (double& v : t.values) v = u(rng);
    const int kind = symmetric ? static_cast<int>(b % 3) : 0;
    if (kind == 0) continue;
    for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj)
      for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di) {
        const double mirror = t.at(std::abs(di), std::abs(dj));
        if (kind == 1) t.at(di, dj) = mirror;
        else t.at(di, dj) = di == 0 ? 0.0 : (di > 0 ? mirror : -mirror);
      }
  }
  return blocks;
}

/// The FFT kind of make_convolution_operator against the dense matrix of the same tables.
void check_block_operator(const Grid& grid, int n_out, int n_in, bool symmetric = false) {
  const std::vector<KernelTable> blocks = random_blocks(grid, n_out * n_in, 11u + 3u * grid.nx + grid.ny, symmetric);
  const auto fft = make_convolution_operator(grid, blocks, n_out, n_in, OperatorKind::fft);
  const auto dense = make_convolution_operator(grid, blocks, n_out, n_in, OperatorKind::dense);
  std::vector<double> x(grid.size() * n_in), y_fft, y_dense;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::cos(0.7 * static_cast<double>(i)) + 0.1;
  for (int pass = 0; pass < 2; ++pass) {  // twice: no state left from the first apply
    fft->apply(x, y_fft);
    dense->apply(x, y_dense);
    ASSERT_EQ(y_fft.size(), y_dense.size());
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < y_fft.size(); ++i) {
      worst = std::max(worst, std::abs(y_fft[i] - y_dense[i]));
      scale = std::max(scale, std::abs(y_dense[i]));
    }
    EXPECT_LT(worst, 1e-12 * scale) << grid.nx << "x" << grid.ny << ", " << n_out << "x" << n_in << " blocks";
  }
}

TEST(PaddedFft, BlockConvolutionEqualsTheDenseOperator) {
  // 7 x 5 elements: a 16 x 10 box (the odd boxes, 15 x 9, in LinearConvolutionEqualsTheDirectSum).
  const Grid g = Grid::make(3, 7, 5, 0.0, 7e-3, 0.0, 5e-3);
  check_block_operator(g, 2, 2);
  check_block_operator(g, 2, 1);
  check_block_operator(g, 1, 2);
  check_block_operator(g, 1, 1);
  check_block_operator(g, 2, 2, true);  // real and imaginary kernel spectra kept as one part
  check_block_operator(g, 1, 2, true);
  check_block_operator(g, 1, 1, true);
  check_block_operator(Grid::make(2, 12, 1, 0.0, 12e-3, 0.0, 0.0), 2, 2);  // one-dimensional
}

TEST(PaddedFft, TransformsTwiceGiveTheSameResult) {
  // No state leaks between calls (the padding stays zero, the spectrum is rebuilt).
  PaddedFft fft(5, 4, 9, 8);
  std::vector<double> x(20), a(20), b(20);
  for (int i = 0; i < 20; ++i) x[i] = std::sin(1.0 + i);
  fft.forward(x.data());
  fft.inverse(a.data());
  fft.forward(x.data());
  fft.inverse(b.data());
  for (int i = 0; i < 20; ++i) {
    EXPECT_NEAR(a[i] / 72.0, x[i], 1e-13);
    EXPECT_EQ(a[i], b[i]);
  }
}

TEST(FftPlanning, GoodSizesHaveOnlySmallPrimeFactors) {
  EXPECT_EQ(fft_good_size(1), 1);
  EXPECT_EQ(fft_good_size(11), 12);
  EXPECT_EQ(fft_good_size(1023), 1024);
  EXPECT_EQ(fft_good_size(97), 100);   // 2^2 5^2: 98 = 2 7^2 is passed over
  EXPECT_EQ(fft_good_size(181), 192);  // not 189 = 3^3 7
  // The padded box of a convolution: the cheapest length, not the smallest.
  EXPECT_EQ(fft_fast_size(2 * 304 - 1), 640);  // not 625 = 5^4 (odd: 2.2x the time)
  EXPECT_EQ(fft_fast_size(2 * 91 - 1), 200);   // not 192 = 2^6 3
  EXPECT_EQ(fft_fast_size(2 * 512 - 1), 1024);
  for (int n = 1; n < 300; ++n) {
    const int m = fft_fast_size(n);
    EXPECT_GE(m, n);
    EXPECT_EQ(fft_good_size(m), m) << n;  // 2, 3, 5-smooth
  }
  EXPECT_GE(fft_threads(), 1);
}

}  // namespace
}  // namespace dc

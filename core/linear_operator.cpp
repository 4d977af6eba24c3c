#include "linear_operator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fft_planning.hpp"
#include "interrupt.hpp"
#include "padded_fft.hpp"

namespace dc {
namespace {

/// Common part of the dense and FFT kinds: the kernel tables and their layout.
class ConvolutionBase : public LinearOperator {
 public:
  ConvolutionBase(const Grid& grid, std::vector<KernelTable> blocks, int n_out, int n_in)
      : grid_(grid), blocks_(std::move(blocks)), n_out_(n_out), n_in_(n_in) {
    if (static_cast<int>(blocks_.size()) != n_out * n_in)
      throw std::invalid_argument("convolution operator: blocks must be n_out * n_in");
  }
  std::size_t rows() const override { return grid_.size() * n_out_; }
  std::size_t cols() const override { return grid_.size() * n_in_; }
  double diagonal(std::size_t i) const override {
    const std::size_t c = i / grid_.size();
    if (rows() != cols()) throw std::logic_error("diagonal of a non-square operator");
    return blocks_[c * n_in_ + c].at(0, 0);
  }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override {
    if (rows() * cols() > max_entries)
      throw std::length_error("operator too large for a dense matrix (" + std::to_string(rows()) + "^2)");
    const std::size_t N = grid_.size();
    Eigen::MatrixXd m(rows(), cols());
    for (int r = 0; r < n_out_; ++r)
      for (int c = 0; c < n_in_; ++c) {
        const KernelTable& t = blocks_[r * n_in_ + c];
        for (int jo = 0; jo < grid_.ny; ++jo) {
          throw_if_interrupted();
          for (int io = 0; io < grid_.nx; ++io)
            for (int ji = 0; ji < grid_.ny; ++ji)
              for (int ii = 0; ii < grid_.nx; ++ii)
                m(r * N + grid_.index(io, jo), c * N + grid_.index(ii, ji)) = t.at(io - ii, jo - ji);
        }
      }
    return m;
  }

 protected:
  Grid grid_;
  std::vector<KernelTable> blocks_;
  int n_out_, n_in_;
};

class DenseConvolution final : public ConvolutionBase {
 public:
  DenseConvolution(const Grid& grid, std::vector<KernelTable> blocks, int n_out, int n_in)
      : ConvolutionBase(grid, std::move(blocks), n_out, n_in), matrix_(to_dense(kDenseAutoLimit * 16)) {}
  void apply(const double* x, double* y) const override {
    Eigen::Map<Eigen::VectorXd>(y, rows()).noalias() =
        matrix_ * Eigen::Map<const Eigen::VectorXd>(x, cols());
  }
  std::string kind() const override { return "dense"; }

 private:
  Eigen::MatrixXd matrix_;
};

/// The spectrum of one kernel block, 1/(mx my) included. The half-space's kernels are even or
/// odd in each offset, so their spectra are real (zz, xx, xy, yy) or imaginary (the kappa
/// terms); such a spectrum keeps one value per entry (half the memory and the reads of a
/// product). Shifted kernels (rolling) keep both parts.
struct KernelSpectrum {
  enum class Kind { complex, real, imaginary } kind = Kind::complex;
  std::vector<double> values;  ///< complex: interleaved re/im; otherwise the one nonzero part

  KernelSpectrum(const std::vector<double>& spectrum, double norm) {
    const std::size_t ncplx = spectrum.size() / 2;
    double largest = 0.0, re_max = 0.0, im_max = 0.0;
    for (std::size_t k = 0; k < ncplx; ++k) {
      re_max = std::max(re_max, std::abs(spectrum[2 * k]));
      im_max = std::max(im_max, std::abs(spectrum[2 * k + 1]));
    }
    largest = std::max(re_max, im_max);
    // A part below this is the transform's round-off of an exactly even or odd kernel.
    const double round_off = 1e-13 * largest;
    const int part = im_max <= round_off ? 0 : (re_max <= round_off ? 1 : -1);
    if (part < 0) {
      values.resize(spectrum.size());
      for (std::size_t k = 0; k < spectrum.size(); ++k) values[k] = spectrum[k] * norm;
      return;
    }
    kind = part == 0 ? Kind::real : Kind::imaginary;
    values.resize(ncplx);
    for (std::size_t k = 0; k < ncplx; ++k) values[k] = spectrum[2 * k + part] * norm;
  }

  /// out (=, or += when accumulate) kernel * in, both interleaved re/im; out may be in.
  template <bool accumulate>
  void multiply(const double* in, double* out, std::size_t ncplx) const {
    const double* kv = values.data();
    const auto store = [out](std::size_t k, double re, double im) {
      if constexpr (accumulate) {
        out[2 * k] += re;
        out[2 * k + 1] += im;
      } else {
        out[2 * k] = re;
        out[2 * k + 1] = im;
      }
    };
    // Written out: std::complex's operator* guards against inf/nan and is several times slower.
    switch (kind) {
      case Kind::complex:
        for (std::size_t k = 0; k < ncplx; ++k) {
          const double re = in[2 * k], im = in[2 * k + 1];
          store(k, kv[2 * k] * re - kv[2 * k + 1] * im, kv[2 * k] * im + kv[2 * k + 1] * re);
        }
        break;
      case Kind::real:
        for (std::size_t k = 0; k < ncplx; ++k) {
          const double re = in[2 * k], im = in[2 * k + 1];
          store(k, kv[k] * re, kv[k] * im);
        }
        break;
      case Kind::imaginary:
        for (std::size_t k = 0; k < ncplx; ++k) {
          const double re = in[2 * k], im = in[2 * k + 1];
          store(k, -kv[k] * im, kv[k] * re);
        }
        break;
    }
  }
};

/// Zero-padded (linear, not circular) convolution by FFTW: the kernel spectra and plans are
/// made once; every apply() does n_in forward and n_out inverse transforms (padded_fft.hpp).
/// Several inputs: each forward transform writes its own stored spectrum, and the products of
/// one output row are summed straight into the transform's buffer (no copies of spectra).
class FftConvolution final : public ConvolutionBase {
 public:
  FftConvolution(const Grid& grid, std::vector<KernelTable> blocks, int n_out, int n_in)
      : ConvolutionBase(grid, std::move(blocks), n_out, n_in),
        fft_(grid_.nx, grid_.ny, grid_.nx == 1 ? 1 : fft_fast_size(2 * grid_.nx - 1),
             grid_.ny == 1 ? 1 : fft_fast_size(2 * grid_.ny - 1), keep_spectra() ? n_in : 0) {
    const int mx = fft_.mx(), my = fft_.my();
    const double norm = 1.0 / (static_cast<double>(mx) * my);
    kernel_spectra_.reserve(blocks_.size());
    std::vector<double> box(static_cast<std::size_t>(mx) * my), spectrum;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      throw_if_interrupted();  // a large grid's spectra take seconds
      std::fill(box.begin(), box.end(), 0.0);
      const KernelTable& t = blocks_[b];
      for (int dj = -(grid_.ny - 1); dj <= grid_.ny - 1; ++dj)
        for (int di = -(grid_.nx - 1); di <= grid_.nx - 1; ++di)
          box[wrap(di, mx) + static_cast<std::size_t>(mx) * wrap(dj, my)] = t.at(di, dj);
      fft_.periodic_forward(box, spectrum);
      kernel_spectra_.emplace_back(spectrum, norm);
    }
  }

  void apply(const double* x, double* y) const override {
    const std::size_t N = grid_.size();
    const std::size_t ncplx = fft_.spectrum_size();
    double* spectrum = fft_.spectrum();
    if (!keep_spectra()) {  // one block: multiply in place
      fft_.forward(x);
      kernel_spectra_[0].multiply<false>(spectrum, spectrum, ncplx);
      fft_.inverse(y);
      return;
    }
    for (int c = 0; c < n_in_; ++c) fft_.forward_into(x + c * N, c);
    for (int r = 0; r < n_out_; ++r) {
      const KernelSpectrum* row = kernel_spectra_.data() + static_cast<std::size_t>(r) * n_in_;
      row[0].multiply<false>(fft_.stored(0), spectrum, ncplx);
      for (int c = 1; c < n_in_; ++c) row[c].multiply<true>(fft_.stored(c), spectrum, ncplx);
      fft_.inverse(y + r * N);
    }
  }
  std::string kind() const override { return "fft"; }

 private:
  static std::size_t wrap(int d, int m) { return static_cast<std::size_t>(d < 0 ? d + m : d); }
  /// A single block multiplies in place; several keep the input spectra.
  bool keep_spectra() const { return n_in_ > 1 || n_out_ > 1; }

  mutable PaddedFft fft_;
  std::vector<KernelSpectrum> kernel_spectra_;  ///< one per block, r * n_in + c
};

}  // namespace

std::unique_ptr<LinearOperator> make_convolution_operator(const Grid& grid,
                                                          std::vector<KernelTable> blocks,
                                                          int n_out, int n_in, OperatorKind kind) {
  const std::size_t entries = grid.size() * n_out * grid.size() * n_in;
  if (kind == OperatorKind::automatic)
    kind = entries <= kDenseAutoLimit ? OperatorKind::dense : OperatorKind::fft;
  if (kind == OperatorKind::dense) {
    if (entries > 16 * kDenseAutoLimit)
      throw std::length_error("dense operator refused: " + std::to_string(grid.size()) +
                              " elements would need an N x N matrix; use the FFT kind");
    return std::make_unique<DenseConvolution>(grid, std::move(blocks), n_out, n_in);
  }
  return std::make_unique<FftConvolution>(grid, std::move(blocks), n_out, n_in);
}

HalfSpace::HalfSpace(const Grid& grid, const MaterialPair& materials, InfluenceOptions options)
    : grid_(grid), materials_(materials), options_(options) {}

std::unique_ptr<LinearOperator> HalfSpace::normal(OperatorKind kind) const {
  return make_convolution_operator(grid_, {influence_table(grid_, materials_, kZ, kZ, options_)}, 1, 1, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential(OperatorKind kind) const {
  if (grid_.dimension == 2)
    return make_convolution_operator(grid_, {influence_table(grid_, materials_, kX, kX, options_)}, 1, 1, kind);
  std::vector<KernelTable> blocks;
  for (Axis out : {kX, kY})
    for (Axis in : {kX, kY}) blocks.push_back(influence_table(grid_, materials_, out, in, options_));
  return make_convolution_operator(grid_, std::move(blocks), 2, 2, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential_from_normal(OperatorKind kind) const {
  std::vector<KernelTable> blocks{influence_table(grid_, materials_, kX, kZ, options_)};
  if (grid_.dimension == 3) blocks.push_back(influence_table(grid_, materials_, kY, kZ, options_));
  return make_convolution_operator(grid_, std::move(blocks), tangential_components(), 1, kind);
}

namespace {
/// Steady rolling's convective form of a compliance: here minus upstream, table by table.
void subtract_upstream(std::vector<KernelTable>& blocks, const std::vector<KernelTable>& upstream) {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (std::size_t i = 0; i < blocks[b].values.size(); ++i) blocks[b].values[i] -= upstream[b].values[i];
}

/// Table of the same kernel with every offset moved by (shift_x, shift_y) elements:
/// at(di, dj) = K(di + shift_x, dj + shift_y). 2-D grids have no y offsets (shift_y must be 0).
KernelTable shifted_table(const Grid& grid, const MaterialPair& m, Axis out, Axis in, int shift_x, int shift_y,
                          const InfluenceOptions& options) {
  if (grid.dimension == 2 && shift_y != 0) throw std::invalid_argument("a 2-D kernel has no y shift");
  Grid wide = grid;
  wide.nx = grid.nx + std::abs(shift_x);
  wide.ny = grid.ny + std::abs(shift_y);
  InfluenceOptions o = options;
  if (grid.dimension == 2 && o.reference_length <= 0.0) o.reference_length = grid.nx * grid.dx;
  const KernelTable big = influence_table(wide, m, out, in, o);
  KernelTable t;
  t.nx = grid.nx;
  t.ny = grid.ny;
  t.values.assign(static_cast<std::size_t>(2 * grid.nx - 1) * static_cast<std::size_t>(2 * grid.ny - 1), 0.0);
  for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj)
    for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di) t.at(di, dj) = big.at(di + shift_x, dj + shift_y);
  return t;
}

/// The tangential blocks (xx | xx, xy, yx, yy) with every offset moved by (shift_x, shift_y).
std::vector<KernelTable> tangential_tables(const Grid& grid, const MaterialPair& m, int shift_x, int shift_y,
                                           const InfluenceOptions& options) {
  const std::vector<Axis> axes = grid.dimension == 2 ? std::vector<Axis>{kX} : std::vector<Axis>{kX, kY};
  std::vector<KernelTable> blocks;
  for (Axis out : axes)
    for (Axis in : axes) blocks.push_back(shifted_table(grid, m, out, in, shift_x, shift_y, options));
  return blocks;
}
}  // namespace

std::unique_ptr<LinearOperator> HalfSpace::tangential_shifted(int shift_x, int shift_y, OperatorKind kind) const {
  const int m = tangential_components();
  return make_convolution_operator(grid_, tangential_tables(grid_, materials_, shift_x, shift_y, options_), m, m,
                                   kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential_convective(int shift, OperatorKind kind) const {
  std::vector<KernelTable> blocks = tangential_tables(grid_, materials_, 0, 0, options_);
  const std::vector<KernelTable> upstream = tangential_tables(grid_, materials_, shift, 0, options_);
  subtract_upstream(blocks, upstream);
  const int m = tangential_components();
  return make_convolution_operator(grid_, std::move(blocks), m, m, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential_from_normal_convective(int shift, OperatorKind kind) const {
  std::vector<KernelTable> blocks{influence_table(grid_, materials_, kX, kZ, options_)};
  std::vector<KernelTable> upstream{shifted_table(grid_, materials_, kX, kZ, shift, 0, options_)};
  if (grid_.dimension == 3) {
    blocks.push_back(influence_table(grid_, materials_, kY, kZ, options_));
    upstream.push_back(shifted_table(grid_, materials_, kY, kZ, shift, 0, options_));
  }
  subtract_upstream(blocks, upstream);
  return make_convolution_operator(grid_, std::move(blocks), tangential_components(), 1, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential_from_normal_shifted(int shift_x, int shift_y,
                                                                         OperatorKind kind) const {
  std::vector<KernelTable> blocks{shifted_table(grid_, materials_, kX, kZ, shift_x, shift_y, options_)};
  if (grid_.dimension == 3) blocks.push_back(shifted_table(grid_, materials_, kY, kZ, shift_x, shift_y, options_));
  return make_convolution_operator(grid_, std::move(blocks), tangential_components(), 1, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::normal_from_tangential(OperatorKind kind) const {
  std::vector<KernelTable> blocks{influence_table(grid_, materials_, kZ, kX, options_)};
  if (grid_.dimension == 3) blocks.push_back(influence_table(grid_, materials_, kZ, kY, options_));
  return make_convolution_operator(grid_, std::move(blocks), 1, tangential_components(), kind);
}

}  // namespace dc

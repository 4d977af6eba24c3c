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
  const Eigen::MatrixXd& matrix() const { return matrix_; }

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

  /// out (=, or += when accumulate) weight * kernel * in, both interleaved re/im; out may be in.
  /// (weight * kernel is the kernel itself, bit for bit, at weight 1.)
  template <bool accumulate>
  void multiply(const double* in, double* out, std::size_t ncplx, double weight = 1.0) const {
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
          const double re = in[2 * k], im = in[2 * k + 1], kr = weight * kv[2 * k], ki = weight * kv[2 * k + 1];
          store(k, kr * re - ki * im, kr * im + ki * re);
        }
        break;
      case Kind::real:
        for (std::size_t k = 0; k < ncplx; ++k) {
          const double re = in[2 * k], im = in[2 * k + 1], kr = weight * kv[k];
          store(k, kr * re, kr * im);
        }
        break;
      case Kind::imaginary:
        for (std::size_t k = 0; k < ncplx; ++k) {
          const double re = in[2 * k], im = in[2 * k + 1], ki = weight * kv[k];
          store(k, -ki * im, ki * re);
        }
        break;
    }
  }
};

/// The zero-padded transform's length for n elements along an axis (linear convolution).
int box_length(int n) { return n == 1 ? 1 : fft_fast_size(2 * n - 1); }

/// The spectra of kernel tables on the transform's box (1/(mx my) included).
std::vector<KernelSpectrum> kernel_spectra(const Grid& grid, const PaddedFft& fft, const std::vector<KernelTable>& blocks) {
  const int mx = fft.mx(), my = fft.my();
  const auto wrap = [](int d, int m) { return static_cast<std::size_t>(d < 0 ? d + m : d); };
  const double norm = 1.0 / (static_cast<double>(mx) * my);
  std::vector<KernelSpectrum> spectra;
  spectra.reserve(blocks.size());
  std::vector<double> box(static_cast<std::size_t>(mx) * my), spectrum;
  for (const KernelTable& t : blocks) {
    throw_if_interrupted();  // a large grid's spectra take seconds
    std::fill(box.begin(), box.end(), 0.0);
    for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj)
      for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di)
        box[wrap(di, mx) + static_cast<std::size_t>(mx) * wrap(dj, my)] = t.at(di, dj);
    throw_if_interrupted();
    fft.periodic_forward(box, spectrum);
    throw_if_interrupted();
    spectra.emplace_back(spectrum, norm);
  }
  return spectra;
}

/// Zero-padded (linear, not circular) convolution by FFTW: the kernel spectra and plans are
/// made once; every apply() does n_in forward and n_out inverse transforms (padded_fft.hpp).
/// Several inputs: each forward transform writes its own stored spectrum, and the products of
/// one output row are summed straight into the transform's buffer (no copies of spectra).
class FftConvolution final : public ConvolutionBase {
 public:
  FftConvolution(const Grid& grid, std::vector<KernelTable> blocks, int n_out, int n_in)
      : ConvolutionBase(grid, std::move(blocks), n_out, n_in),
        fft_(grid_.nx, grid_.ny, box_length(grid_.nx), box_length(grid_.ny), keep_spectra() ? n_in : 0),
        kernel_spectra_(kernel_spectra(grid_, fft_, blocks_)) {}

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
  /// A single block multiplies in place; several keep the input spectra.
  bool keep_spectra() const { return n_in_ > 1 || n_out_ > 1; }

  mutable PaddedFft fft_;
  std::vector<KernelSpectrum> kernel_spectra_;  ///< one per block, r * n_in + c
};

/// Checks the terms of a weighted sum: at least one, each of n_out * n_in blocks.
void check_terms(const std::vector<std::vector<KernelTable>>& terms, int n_out, int n_in) {
  if (terms.empty()) throw std::invalid_argument("weighted convolutions: no term");
  for (const auto& t : terms)
    if (static_cast<int>(t.size()) != n_out * n_in)
      throw std::invalid_argument("weighted convolutions: every term must have n_out * n_in blocks");
}

/// The shared part of both kinds: the weights and the shape.
class WeightedConvolutionsBase : public WeightedConvolutions {
 public:
  WeightedConvolutionsBase(const Grid& grid, std::size_t terms, int n_out, int n_in)
      : grid_(grid), weights_(terms, 0.0), n_out_(n_out), n_in_(n_in) {
    weights_[0] = 1.0;
  }
  std::size_t rows() const override { return grid_.size() * n_out_; }
  std::size_t cols() const override { return grid_.size() * n_in_; }
  double diagonal(std::size_t) const override { throw std::logic_error("diagonal of a weighted sum of convolutions"); }
  void set_weights(const std::vector<double>& weights) override {
    if (weights.size() != weights_.size()) throw std::invalid_argument("weighted convolutions: one weight per term");
    weights_ = weights;
  }

 protected:
  Grid grid_;
  std::vector<double> weights_;
  int n_out_, n_in_;
};

/// Small grids: the terms' matrices, summed with the weights at each apply.
class DenseWeightedConvolutions final : public WeightedConvolutionsBase {
 public:
  DenseWeightedConvolutions(const Grid& grid, std::vector<std::vector<KernelTable>> terms, int n_out, int n_in)
      : WeightedConvolutionsBase(grid, terms.size(), n_out, n_in) {
    for (auto& t : terms) matrices_.push_back(DenseConvolution(grid, std::move(t), n_out, n_in).matrix());
  }
  void apply(const double* x, double* y) const override {
    Eigen::Map<Eigen::VectorXd> out(y, rows());
    const Eigen::Map<const Eigen::VectorXd> in(x, cols());
    out.setZero();
    for (std::size_t t = 0; t < matrices_.size(); ++t)
      if (weights_[t] != 0.0) out.noalias() += weights_[t] * (matrices_[t] * in);
  }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override {
    if (rows() * cols() > max_entries) throw std::length_error("weighted convolutions: too large to be dense");
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(rows(), cols());
    for (std::size_t t = 0; t < matrices_.size(); ++t) m += weights_[t] * matrices_[t];
    return m;
  }
  std::string kind() const override { return "dense"; }

 private:
  std::vector<Eigen::MatrixXd> matrices_;
};

/// The FFT kind: the inputs transformed once, each output's spectrum the weighted sum of the
/// terms' products, transformed back once: n_in forward and n_out inverse transforms per apply
/// whatever the number of terms.
class FftWeightedConvolutions final : public WeightedConvolutionsBase {
 public:
  FftWeightedConvolutions(const Grid& grid, const std::vector<std::vector<KernelTable>>& terms, int n_out, int n_in)
      : WeightedConvolutionsBase(grid, terms.size(), n_out, n_in),
        fft_(grid.nx, grid.ny, box_length(grid.nx), box_length(grid.ny), n_in) {
    for (const auto& t : terms) spectra_.push_back(kernel_spectra(grid_, fft_, t));
  }
  void apply(const double* x, double* y) const override {
    const std::size_t N = grid_.size(), ncplx = fft_.spectrum_size();
    double* spectrum = fft_.spectrum();
    for (int c = 0; c < n_in_; ++c) fft_.forward_into(x + c * N, c);
    for (int r = 0; r < n_out_; ++r) {
      bool first = true;
      for (std::size_t t = 0; t < spectra_.size(); ++t) {
        if (weights_[t] == 0.0) continue;
        const KernelSpectrum* row = spectra_[t].data() + static_cast<std::size_t>(r) * n_in_;
        for (int c = 0; c < n_in_; ++c) {
          if (first) row[c].multiply<false>(fft_.stored(c), spectrum, ncplx, weights_[t]);
          else row[c].multiply<true>(fft_.stored(c), spectrum, ncplx, weights_[t]);
          first = false;
        }
      }
      if (first) std::fill(spectrum, spectrum + 2 * ncplx, 0.0);
      fft_.inverse(y + r * N);
    }
  }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override {
    return dense_by_columns(*this, max_entries, "weighted convolutions");
  }
  std::string kind() const override { return "fft"; }

 private:
  mutable PaddedFft fft_;
  std::vector<std::vector<KernelSpectrum>> spectra_;  ///< per term, one per block, r * n_in + c
};

}  // namespace

namespace {
/// `automatic` resolved by the matrix's size (dense up to kDenseAutoLimit entries); a dense kind
/// refused beyond 16 times that.
OperatorKind resolved_kind(const Grid& grid, int n_out, int n_in, OperatorKind kind) {
  const std::size_t entries = grid.size() * n_out * grid.size() * n_in;
  if (kind == OperatorKind::automatic) kind = entries <= kDenseAutoLimit ? OperatorKind::dense : OperatorKind::fft;
  if (kind == OperatorKind::dense && entries > 16 * kDenseAutoLimit)
    throw std::length_error("dense operator refused: " + std::to_string(grid.size()) +
                            " elements would need an N x N matrix; use the FFT kind");
  return kind;
}
}  // namespace

Eigen::MatrixXd dense_by_columns(const LinearOperator& op, std::size_t max_entries, const std::string& what) {
  if (op.rows() * op.cols() > max_entries) throw std::length_error(what + ": too large to be dense");
  Eigen::MatrixXd m(op.rows(), op.cols());
  std::vector<double> e(op.cols(), 0.0), column(op.rows());
  for (std::size_t j = 0; j < op.cols(); ++j) {
    e[j] = 1.0;
    op.apply(e.data(), column.data());
    e[j] = 0.0;
    m.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(column.data(), static_cast<Eigen::Index>(op.rows()));
  }
  return m;
}

std::unique_ptr<LinearOperator> make_convolution_operator(const Grid& grid,
                                                          std::vector<KernelTable> blocks,
                                                          int n_out, int n_in, OperatorKind kind) {
  if (resolved_kind(grid, n_out, n_in, kind) == OperatorKind::dense)
    return std::make_unique<DenseConvolution>(grid, std::move(blocks), n_out, n_in);
  return std::make_unique<FftConvolution>(grid, std::move(blocks), n_out, n_in);
}

std::unique_ptr<WeightedConvolutions> make_weighted_convolutions(const Grid& grid,
                                                                std::vector<std::vector<KernelTable>> terms,
                                                                int n_out, int n_in, OperatorKind kind) {
  check_terms(terms, n_out, n_in);
  if (resolved_kind(grid, n_out, n_in, kind) == OperatorKind::dense)
    return std::make_unique<DenseWeightedConvolutions>(grid, std::move(terms), n_out, n_in);
  return std::make_unique<FftWeightedConvolutions>(grid, terms, n_out, n_in);
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

std::unique_ptr<WeightedConvolutions> HalfSpace::displacement_shifted(const std::vector<std::pair<int, int>>& shifts,
                                                                     bool with_pressure, OperatorKind kind) const {
  const std::vector<Axis> outputs = grid_.dimension == 2 ? std::vector<Axis>{kX} : std::vector<Axis>{kX, kY};
  std::vector<Axis> inputs = outputs;
  if (with_pressure) inputs.push_back(kZ);
  std::vector<std::vector<KernelTable>> terms;
  for (const auto& [sx, sy] : shifts) {
    std::vector<KernelTable> blocks;
    for (Axis out : outputs)
      for (Axis in : inputs) blocks.push_back(shifted_table(grid_, materials_, out, in, sx, sy, options_));
    terms.push_back(std::move(blocks));
  }
  return make_weighted_convolutions(grid_, std::move(terms), static_cast<int>(outputs.size()),
                                    static_cast<int>(inputs.size()), kind);
}

std::unique_ptr<LinearOperator> HalfSpace::normal_from_tangential(OperatorKind kind) const {
  std::vector<KernelTable> blocks{influence_table(grid_, materials_, kZ, kX, options_)};
  if (grid_.dimension == 3) blocks.push_back(influence_table(grid_, materials_, kZ, kY, options_));
  return make_convolution_operator(grid_, std::move(blocks), 1, tangential_components(), kind);
}

}  // namespace dc

#include "linear_operator.hpp"
#include "interrupt.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <thread>
#include <stdexcept>

#include <fftw3.h>

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

/// Transforms of at least this many points run on threads. Every plan is FFTW_ESTIMATE: a
/// measured plan depends on the timings of the moment, and with it the round-off, so the same
/// case would not give bit-identical results run after run.
constexpr std::size_t kLargeTransform = 1024u * 1024u;

std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

/// Threads for large transforms: the hardware's cores (DYNCONTACT_THREADS overrides).
int fft_threads() {
  static const int threads = [] {
    fftw_init_threads();
    int n = static_cast<int>(std::thread::hardware_concurrency());
    if (const char* env = std::getenv("DYNCONTACT_THREADS")) n = std::atoi(env);
    return std::max(1, n);
  }();
  return threads;
}

/// Smallest n' >= n whose prime factors are 2, 3, 5 and 7 (fast FFT lengths).
int fft_size(int n) {
  for (int m = n;; ++m) {
    int r = m;
    for (int p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

/// Zero-padded (linear, not circular) convolution by FFTW: the kernel spectra and plans are
/// made once; every apply() does n_in forward and n_out inverse transforms.
class FftConvolution final : public ConvolutionBase {
 public:
  FftConvolution(const Grid& grid, std::vector<KernelTable> blocks, int n_out, int n_in)
      : ConvolutionBase(grid, std::move(blocks), n_out, n_in) {
    mx_ = grid_.nx == 1 ? 1 : fft_size(2 * grid_.nx - 1);
    my_ = grid_.ny == 1 ? 1 : fft_size(2 * grid_.ny - 1);
    mxc_ = mx_ / 2 + 1;
    const std::size_t nreal = static_cast<std::size_t>(mx_) * my_;
    const std::size_t ncplx = static_cast<std::size_t>(mxc_) * my_;
    real_ = fftw_alloc_real(nreal);
    cplx_ = fftw_alloc_complex(ncplx);
    {
      // Planning is not thread-safe in FFTW; large transforms are threaded.
      std::lock_guard<std::mutex> lock(planner_mutex());
      const bool large = nreal >= kLargeTransform;
      fftw_plan_with_nthreads(large ? fft_threads() : 1);
      const unsigned flags = FFTW_ESTIMATE;
      forward_ = fftw_plan_dft_r2c_2d(my_, mx_, real_, cplx_, flags);
      inverse_ = fftw_plan_dft_c2r_2d(my_, mx_, cplx_, real_, flags);
    }
    if (!forward_ || !inverse_) {
      release();
      throw std::runtime_error("FFTW could not plan the convolution");
    }
    kernel_spectra_.resize(2 * blocks_.size() * ncplx);
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      if (interrupt_requested()) {  // a large grid's spectra take seconds
        release();
        throw_if_interrupted();
      }
      std::fill(real_, real_ + nreal, 0.0);
      const KernelTable& t = blocks_[b];
      for (int dj = -(grid_.ny - 1); dj <= grid_.ny - 1; ++dj)
        for (int di = -(grid_.nx - 1); di <= grid_.nx - 1; ++di)
          real_[wrap(di, mx_) + static_cast<std::size_t>(mx_) * wrap(dj, my_)] = t.at(di, dj);
      fftw_execute(forward_);
      for (std::size_t k = 0; k < ncplx; ++k) {
        kernel_spectra_[2 * (b * ncplx + k)] = cplx_[k][0] / double(nreal);
        kernel_spectra_[2 * (b * ncplx + k) + 1] = cplx_[k][1] / double(nreal);
      }
    }
    if (keep_spectra()) input_spectra_.resize(2 * static_cast<std::size_t>(n_in_) * ncplx);
  }
  ~FftConvolution() override { release(); }
  FftConvolution(const FftConvolution&) = delete;
  FftConvolution& operator=(const FftConvolution&) = delete;

  void apply(const double* x, double* y) const override {
    const std::size_t N = grid_.size();
    const std::size_t nreal = static_cast<std::size_t>(mx_) * my_;
    const std::size_t ncplx = static_cast<std::size_t>(mxc_) * my_;
    for (int c = 0; c < n_in_; ++c) {
      std::fill(real_, real_ + nreal, 0.0);
      for (int j = 0; j < grid_.ny; ++j)
        std::copy_n(x + c * N + grid_.index(0, j), grid_.nx, real_ + static_cast<std::size_t>(mx_) * j);
      fftw_execute(forward_);
      if (keep_spectra()) std::copy_n(&cplx_[0][0], 2 * ncplx, input_spectra_.data() + 2 * c * ncplx);
    }
    for (int r = 0; r < n_out_; ++r) {
      // Spectral product, written out (std::complex's operator* guards against inf/nan and is
      // several times slower in this loop).
      if (!keep_spectra()) {
        multiply(kernel_spectra_.data() + 2 * r * ncplx, ncplx);
      } else {
        for (std::size_t k = 0; k < ncplx; ++k) {
          double re = 0.0, im = 0.0;
          for (int c = 0; c < n_in_; ++c) {
            const double* kern = kernel_spectra_.data() + 2 * ((r * n_in_ + c) * ncplx + k);
            const double* in = input_spectra_.data() + 2 * (c * ncplx + k);
            re += kern[0] * in[0] - kern[1] * in[1];
            im += kern[0] * in[1] + kern[1] * in[0];
          }
          cplx_[k][0] = re;
          cplx_[k][1] = im;
        }
      }
      fftw_execute(inverse_);
      for (int j = 0; j < grid_.ny; ++j)
        std::copy_n(real_ + static_cast<std::size_t>(mx_) * j, grid_.nx, y + r * N + grid_.index(0, j));
    }
  }
  std::string kind() const override { return "fft"; }

 private:
  static std::size_t wrap(int d, int m) { return static_cast<std::size_t>(d < 0 ? d + m : d); }
  /// Frees the plans and buffers (the destructor, or a constructor that stops early).
  void release() {
    if (forward_) fftw_destroy_plan(forward_);
    if (inverse_) fftw_destroy_plan(inverse_);
    fftw_free(real_);
    fftw_free(cplx_);
    forward_ = inverse_ = nullptr;
    real_ = nullptr;
    cplx_ = nullptr;
  }
  /// A single block multiplies in place; several keep the input spectra.
  bool keep_spectra() const { return n_in_ > 1 || n_out_ > 1; }
  /// cplx_ *= kernel (interleaved re/im), in place.
  void multiply(const double* kern, std::size_t ncplx) const {
    for (std::size_t k = 0; k < ncplx; ++k) {
      const double re = cplx_[k][0], im = cplx_[k][1];
      cplx_[k][0] = kern[2 * k] * re - kern[2 * k + 1] * im;
      cplx_[k][1] = kern[2 * k] * im + kern[2 * k + 1] * re;
    }
  }

  int mx_ = 1, my_ = 1, mxc_ = 1;
  double* real_ = nullptr;
  fftw_complex* cplx_ = nullptr;
  fftw_plan forward_ = nullptr, inverse_ = nullptr;
  std::vector<double> kernel_spectra_;               ///< interleaved re/im, one spectrum per block
  mutable std::vector<double> input_spectra_;        ///< interleaved re/im, one per input
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
/// Table of the same kernel with every offset moved by `shift` along x: at(di, dj) = K(di + shift, dj).
KernelTable shifted_table(const Grid& grid, const MaterialPair& m, Axis out, Axis in, int shift,
                          const InfluenceOptions& options) {
  Grid wide = grid;
  wide.nx = grid.nx + std::abs(shift);
  InfluenceOptions o = options;
  if (grid.dimension == 2 && o.reference_length <= 0.0) o.reference_length = grid.nx * grid.dx;
  const KernelTable big = influence_table(wide, m, out, in, o);
  KernelTable t;
  t.nx = grid.nx;
  t.ny = grid.ny;
  t.values.assign(static_cast<std::size_t>(2 * grid.nx - 1) * static_cast<std::size_t>(2 * grid.ny - 1), 0.0);
  for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj)
    for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di) t.at(di, dj) = big.at(di + shift, dj);
  return t;
}

/// The tangential blocks (xx | xx, xy, yx, yy) with every offset moved by `shift` along x.
std::vector<KernelTable> tangential_tables(const Grid& grid, const MaterialPair& m, int shift,
                                           const InfluenceOptions& options) {
  const std::vector<Axis> axes = grid.dimension == 2 ? std::vector<Axis>{kX} : std::vector<Axis>{kX, kY};
  std::vector<KernelTable> blocks;
  for (Axis out : axes)
    for (Axis in : axes) blocks.push_back(shifted_table(grid, m, out, in, shift, options));
  return blocks;
}
}  // namespace

std::unique_ptr<LinearOperator> HalfSpace::tangential_shifted(int shift, OperatorKind kind) const {
  const int m = tangential_components();
  return make_convolution_operator(grid_, tangential_tables(grid_, materials_, shift, options_), m, m, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential_convective(int shift, OperatorKind kind) const {
  std::vector<KernelTable> blocks = tangential_tables(grid_, materials_, 0, options_);
  const std::vector<KernelTable> upstream = tangential_tables(grid_, materials_, shift, options_);
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (std::size_t i = 0; i < blocks[b].values.size(); ++i) blocks[b].values[i] -= upstream[b].values[i];
  const int m = tangential_components();
  return make_convolution_operator(grid_, std::move(blocks), m, m, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::tangential_from_normal_shifted(int shift, OperatorKind kind) const {
  std::vector<KernelTable> blocks{shifted_table(grid_, materials_, kX, kZ, shift, options_)};
  if (grid_.dimension == 3) blocks.push_back(shifted_table(grid_, materials_, kY, kZ, shift, options_));
  return make_convolution_operator(grid_, std::move(blocks), tangential_components(), 1, kind);
}

std::unique_ptr<LinearOperator> HalfSpace::normal_from_tangential(OperatorKind kind) const {
  std::vector<KernelTable> blocks{influence_table(grid_, materials_, kZ, kX, options_)};
  if (grid_.dimension == 3) blocks.push_back(influence_table(grid_, materials_, kZ, kY, options_));
  return make_convolution_operator(grid_, std::move(blocks), 1, tangential_components(), kind);
}

}  // namespace dc

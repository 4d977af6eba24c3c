#pragma once
// Linear operators on grid fields: the compliance of the half-space applied matrix-free.
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "grid.hpp"
#include "influence.hpp"
#include "operator_kind.hpp"

namespace dc {

/// y = A x for stacked component fields (component c of element e at c * N + e).
class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  virtual std::size_t rows() const = 0;
  virtual std::size_t cols() const = 0;
  /// y = A x; x has cols() entries, y rows(). Not thread-safe (work buffers are reused).
  virtual void apply(const double* x, double* y) const = 0;
  /// Diagonal entry A_ii (square operators).
  virtual double diagonal(std::size_t i) const = 0;
  /// The matrix itself; throws std::length_error when rows()*cols() exceeds `max_entries`.
  virtual Eigen::MatrixXd to_dense(std::size_t max_entries = 4096u * 4096u) const = 0;
  virtual std::string kind() const = 0;  ///< "dense" or "fft"

  void apply(const std::vector<double>& x, std::vector<double>& y) const {
    y.resize(rows());
    apply(x.data(), y.data());
  }
};

/// The matrix of `op` column by column (one apply per column); throws std::length_error naming
/// `what` when rows()*cols() exceeds `max_entries`. For operators without a matrix of their own.
Eigen::MatrixXd dense_by_columns(const LinearOperator& op, std::size_t max_entries, const std::string& what);

/// Largest rows*cols for which `automatic` picks a dense matrix.
inline constexpr std::size_t kDenseAutoLimit = 1024u * 1024u;

/// Block convolution operator built from kernel tables: blocks[r * n_in + c] maps input
/// component c to output component r. Dense and FFT kinds give the same result to round-off.
std::unique_ptr<LinearOperator> make_convolution_operator(const Grid& grid,
                                                          std::vector<KernelTable> blocks,
                                                          int n_out, int n_in, OperatorKind kind);

/// A weighted sum w_0 A_0 + w_1 A_1 + ... of block convolutions of one grid and one block shape
/// (n_out x n_in), applied in one pass: on the FFT kind n_in forward and n_out inverse transforms
/// whatever the number of terms (the weights scale the kernels' spectra). Weights: set_weights
/// before an apply (initially the first term alone); a term of weight 0 costs nothing.
class WeightedConvolutions : public LinearOperator {
 public:
  /// One weight per term, in the terms' order.
  virtual void set_weights(const std::vector<double>& weights) = 0;
};

/// terms[t][r * n_in + c]: block (r, c) of term t (as make_convolution_operator's blocks).
std::unique_ptr<WeightedConvolutions> make_weighted_convolutions(const Grid& grid,
                                                                std::vector<std::vector<KernelTable>> terms,
                                                                int n_out, int n_in, OperatorKind kind);

/// The half-space compliances of one grid and material pair (tables computed once).
/// normal(): w_z <- p (N x N); tangential(): (w_x, w_y) <- (tau_x, tau_y) (2N x 2N, 2-D: N x N);
/// tangential_from_normal(): (w_x, w_y) <- p (the kappa B21 term); normal_from_tangential():
/// w_z <- (tau_x, tau_y) (the kappa B32 term).
class HalfSpace {
 public:
  HalfSpace(const Grid& grid, const MaterialPair& materials, InfluenceOptions options = {});
  const Grid& grid() const { return grid_; }
  const MaterialPair& materials() const { return materials_; }
  std::unique_ptr<LinearOperator> normal(OperatorKind kind = OperatorKind::automatic) const;
  std::unique_ptr<LinearOperator> tangential(OperatorKind kind = OperatorKind::automatic) const;
  std::unique_ptr<LinearOperator> tangential_from_normal(OperatorKind kind = OperatorKind::automatic) const;
  std::unique_ptr<LinearOperator> normal_from_tangential(OperatorKind kind = OperatorKind::automatic) const;
  /// The same tangential compliances evaluated (shift_x, shift_y) elements downstream: row
  /// (i, j) gives w at the centre of element (i + shift_x, j + shift_y) (the convective term of
  /// (3.8): the previous displacement of the material point now at (i, j)). Exact also beyond
  /// the grid edge. 2-D: shift_y must be 0 (std::invalid_argument otherwise).
  std::unique_ptr<LinearOperator> tangential_shifted(int shift_x, int shift_y,
                                                     OperatorKind kind = OperatorKind::automatic) const;
  std::unique_ptr<LinearOperator> tangential_from_normal_shifted(int shift_x, int shift_y,
                                                                 OperatorKind kind = OperatorKind::automatic) const;
  /// Steady rolling's convective compliance tangential() - tangential_shifted(shift) as one
  /// operator (one transform per apply): the slip a traction field produces per `shift`
  /// elements of travel when it is the same upstream and here ((2.19), (4.4)-(4.6)).
  std::unique_ptr<LinearOperator> tangential_convective(int shift, OperatorKind kind = OperatorKind::automatic) const;
  /// The same for the kappa B21 term: tangential_from_normal() - tangential_from_normal_shifted(shift, 0).
  std::unique_ptr<LinearOperator> tangential_from_normal_convective(int shift,
                                                                    OperatorKind kind = OperatorKind::automatic) const;
  /// The relative tangential displacement kappa B21 p + B22 tau (4.2) at whole-element shifts
  /// (each as tangential_shifted and tangential_from_normal_shifted), one term per shift:
  /// input (tau_x, tau_y, p) stacked, or (tau_x, tau_y) without `with_pressure` (kappa = 0);
  /// output (w_x, w_y) (2-D: tau_x, w_x). Weights between neighbouring shifts interpolate the
  /// convected memory of (3.8) in one apply.
  std::unique_ptr<WeightedConvolutions> displacement_shifted(const std::vector<std::pair<int, int>>& shifts,
                                                             bool with_pressure,
                                                             OperatorKind kind = OperatorKind::automatic) const;
  int tangential_components() const { return grid_.dimension == 2 ? 1 : 2; }

 private:
  Grid grid_;
  MaterialPair materials_;
  InfluenceOptions options_;
};

}  // namespace dc

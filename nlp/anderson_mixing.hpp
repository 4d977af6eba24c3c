#pragma once
// Anderson acceleration (Walker & Ni, SIAM J. Numer. Anal. 49, 2011) of a fixed-point
// iteration x = G(x): from the last m pairs (x_k, G(x_k)) the next iterate is the combination
// of the G(x_k) whose residuals G(x_k) - x_k combine to the smallest norm. Used for the
// normal-tangential alternation (4.26)-(4.27), where plain alternation converges linearly.
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace dc {

class AndersonMixing {
 public:
  explicit AndersonMixing(int memory = 5) : memory_(memory) {}
  /// Given x and g = G(x), returns the next iterate (the first call, and any call after a
  /// badly conditioned history, returns g: plain iteration).
  std::vector<double> next(const std::vector<double>& x, const std::vector<double>& g);
  /// The same into `out` (which may be x): the history and the least-squares work are kept
  /// between calls, so a loop of one size allocates nothing once each history length was met.
  void next(const std::vector<double>& x, const std::vector<double>& g, std::vector<double>& out);
  void reset();

 private:
  /// gamma = argmin |r - dR gamma| for the m = count_ differences, by column-pivoting QR with
  /// a rank threshold of 1e-10; false when the history no longer spans new directions.
  bool least_squares(std::size_t n, int m);

  int memory_;
  std::vector<double> last_g_, last_r_, r_, next_;
  // The differences of G and of the residuals, a ring of memory_ slots (oldest at start_).
  std::vector<std::vector<double>> dg_, dr_;
  int start_ = 0, count_ = 0;
  // Per history length m (index m - 1): the n x m matrix of residual differences and its QR.
  std::vector<Eigen::MatrixXd> dR_;
  std::vector<Eigen::ColPivHouseholderQR<Eigen::MatrixXd>> qr_;
  Eigen::VectorXd c_;          // the rotated residual
  std::vector<double> gamma_;  // the coefficients
};

}  // namespace dc

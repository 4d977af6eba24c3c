#pragma once
// Anderson acceleration (Walker & Ni, SIAM J. Numer. Anal. 49, 2011) of a fixed-point
// iteration x = G(x): from the last m pairs (x_k, G(x_k)) the next iterate is the combination
// of the G(x_k) whose residuals G(x_k) - x_k combine to the smallest norm. Used for the
// normal-tangential alternation (4.26)-(4.27), where plain alternation converges linearly.
#include <cstddef>
#include <deque>
#include <vector>

namespace dc {

class AndersonMixing {
 public:
  explicit AndersonMixing(int memory = 5) : memory_(memory) {}
  /// Given x and g = G(x), returns the next iterate (the first call, and any call after a
  /// badly conditioned history, returns g: plain iteration).
  std::vector<double> next(const std::vector<double>& x, const std::vector<double>& g);
  void reset();

 private:
  int memory_;
  std::vector<double> last_g_, last_r_;
  std::deque<std::vector<double>> dg_, dr_;  ///< differences of G and of the residuals
};

}  // namespace dc

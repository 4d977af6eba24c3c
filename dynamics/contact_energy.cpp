#include "contact_energy.hpp"

namespace dc::dynamics {

double elastic_energy(const std::vector<double>* pressure, const std::vector<double>& heights, double approach,
                      bool with_normal, const std::vector<double>& tx, const std::vector<double>& ty,
                      const LinearOperator* tangential_compliance, const LinearOperator* coupling, double area,
                      EnergyScratch& scratch) {
  double twice = 0.0;
  if (pressure && with_normal)
    for (std::size_t e = 0; e < pressure->size() && e < heights.size(); ++e)
      if ((*pressure)[e] > 0.0) twice += (*pressure)[e] * (approach - heights[e]);  // the gap closed: u_n = delta - h
  if (tangential_compliance && !tx.empty()) {
    // tau in the compliance's layout: every element's x component, then (3-D) every y.
    const std::size_t N = tx.size(), n = tangential_compliance->cols();
    std::vector<double>& tau = scratch.tau;
    std::vector<double>& u = scratch.displacement;
    tau.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) tau[i] = i < N ? tx[i] : (i - N < ty.size() ? ty[i - N] : 0.0);
    tangential_compliance->apply(tau, u);
    if (coupling && pressure) {
      std::vector<double>& w = scratch.coupled;
      coupling->apply(*pressure, w);
      for (std::size_t i = 0; i < u.size() && i < w.size(); ++i) u[i] += w[i];
    }
    for (std::size_t i = 0; i < n && i < u.size(); ++i) twice += tau[i] * u[i];
  }
  return 0.5 * twice * area;
}

}  // namespace dc::dynamics

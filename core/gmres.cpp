#include "gmres.hpp"
#include "interrupt.hpp"
#include "vector_ops.hpp"

#include <cmath>
#include <cstddef>

namespace dc {

GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, const std::vector<double>& b,
                  std::vector<double>& x, double rtol, int restart, int max_iter) {
  GmresWorkspace work;
  return gmres(apply, precondition, b, x, rtol, restart, max_iter, work);
}

GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, const std::vector<double>& b,
                  std::vector<double>& x, double rtol, int restart, int max_iter, GmresWorkspace& work) {
  const std::size_t n = b.size();
  GmresResult result;
  x.resize(n, 0.0);
  const double b_norm = std::sqrt(dot(b, b));
  if (b_norm == 0.0) {
    x.assign(n, 0.0);
    result.converged = true;
    return result;
  }
  // Every entry of H, g and y is written before it is read; the basis vectors are sized as the
  // iteration reaches them (a converging call touches only the first few).
  auto& V = work.V;
  auto& H = work.H;
  auto& cs = work.cs;
  auto& sn = work.sn;
  auto& g = work.g;
  auto& z = work.z;
  auto& w = work.w;
  auto& y = work.y;
  const std::size_t m = static_cast<std::size_t>(restart);
  if (V.size() < m + 1) V.resize(m + 1);
  if (H.size() < m + 1) H.resize(m + 1);
  for (auto& row : H)
    if (row.size() < m) row.resize(m);
  for (auto* v : {&cs, &sn, &y})
    if (v->size() < m) v->resize(m);
  if (g.size() < m + 1) g.resize(m + 1);
  z.resize(n);
  w.resize(n);
  V[0].resize(n);
  auto preconditioned = [&](const std::vector<double>& v, std::vector<double>& out) {
    if (precondition) precondition(v, out);
    else out = v;
  };
  while (true) {
    throw_if_interrupted();
    // r = b - A x
    apply(x, w);
    ++result.iterations;
    for (std::size_t i = 0; i < n; ++i) V[0][i] = b[i] - w[i];
    double beta = std::sqrt(dot(V[0], V[0]));
    result.relative_residual = beta / b_norm;
    if (result.relative_residual <= rtol) {
      result.converged = true;
      return result;
    }
    if (result.iterations >= max_iter) return result;
    for (double& v : V[0]) v /= beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    int k = 0;
    for (; k < restart && result.iterations < max_iter; ++k) {
      preconditioned(V[k], z);
      apply(z, w);
      ++result.iterations;
      for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
        H[i][k] = dot(w, V[i]);
        for (std::size_t j = 0; j < n; ++j) w[j] -= H[i][k] * V[i][j];
      }
      H[k + 1][k] = std::sqrt(dot(w, w));
      V[k + 1].resize(n);
      if (H[k + 1][k] > 0.0)
        for (std::size_t j = 0; j < n; ++j) V[k + 1][j] = w[j] / H[k + 1][k];
      for (int i = 0; i < k; ++i) {  // previous rotations
        const double t = cs[i] * H[i][k] + sn[i] * H[i + 1][k];
        H[i + 1][k] = -sn[i] * H[i][k] + cs[i] * H[i + 1][k];
        H[i][k] = t;
      }
      const double d = std::hypot(H[k][k], H[k + 1][k]);
      cs[k] = d > 0.0 ? H[k][k] / d : 1.0;
      sn[k] = d > 0.0 ? H[k + 1][k] / d : 0.0;
      H[k][k] = d;
      H[k + 1][k] = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      result.relative_residual = std::abs(g[k + 1]) / b_norm;
      if (result.relative_residual <= rtol || H[k][k] == 0.0) {
        ++k;
        break;
      }
    }
    // x += M^-1 V y with H y = g (upper triangular, k columns)
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= H[i][j] * y[j];
      y[i] = H[i][i] != 0.0 ? s / H[i][i] : 0.0;
    }
    std::fill(w.begin(), w.end(), 0.0);
    for (int j = 0; j < k; ++j)
      for (std::size_t i = 0; i < n; ++i) w[i] += y[j] * V[j][i];
    preconditioned(w, z);
    for (std::size_t i = 0; i < n; ++i) x[i] += z[i];
    if (result.relative_residual <= rtol) {
      result.converged = true;
      return result;
    }
    if (result.iterations >= max_iter) return result;
  }
}

}  // namespace dc

#include "quadratic_program.hpp"
#include "sparse_block.hpp"

#include <vector>

namespace dc {

double QuadraticProgram::objective(const double* x) const {
  std::vector<double> g(c.size());
  return gradient(x, g.data());
}

std::string QuadraticProgram::invalid_reason() const {
  const auto size = c.size();
  if (Q == nullptr) return "no operator Q";
  if (Q->rows() != size || Q->cols() != size) return "Q does not match c in size";
  if (preconditioner && (preconditioner->rows() != size || preconditioner->cols() != size))
    return "the preconditioner does not match c in size";
  if ((!lower.empty() && lower.size() != size) || (!upper.empty() && upper.size() != size))
    return "bounds do not match c in size";
  for (const auto& eq : equalities)
    if (eq.a.size() != size) return "an equality row does not match c in size";
  for (const auto& d : disks)
    if (d.ix < 0 || d.iy < 0 || static_cast<std::size_t>(d.ix) >= size || static_cast<std::size_t>(d.iy) >= size ||
        d.ix == d.iy)
      return "a disk has bad indices";
  if (block) {
    if (block->n < 0 || block->hessian.rows() != block->n || block->hessian.cols() != block->n)
      return "the sparse block's Hessian does not match its unknowns";
    if (block->rows.cols() != static_cast<Eigen::Index>(size) + block->n)
      return "the sparse block's rows do not match the unknowns";
  }
  return {};
}

double QuadraticProgram::gradient(const double* x, double* g) const {
  Q->apply(x, g);
  double f = 0.0;
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i) {
    f += x[i] * (0.5 * g[i] + c[i]);
    g[i] += c[i];
  }
  return f;
}

}  // namespace dc

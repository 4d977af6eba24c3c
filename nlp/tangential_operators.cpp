// TangentialProblem::Impl: the operators of one grid and material pair (C, Ct, the kappa terms
// B21, B32 of (4.26)-(4.27)), the relative displacement kappa B21 p + B22 tau (4.2), and the
// previous displacement shifted by whole elements and convected between them (3.8).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "tangential_problem_impl.hpp"

namespace dc {

TangentialProblem::Impl::Impl(const Grid& g, const MaterialPair& m, std::vector<double> h, FrictionLaw f,
                              OperatorKind k)
    : grid(g), materials(m), friction(std::move(f)), kind(k), half_space(std::in_place, g, m),
      comps(g.dimension == 2 ? 1 : 2), N(g.size()), coupled(m.kappa() != 0.0),
      heights(std::move(h)) {
  C = half_space->normal(kind);
  Ct = half_space->tangential(kind);
  if (coupled) {
    B21 = half_space->tangential_from_normal(kind);
    B32 = half_space->normal_from_tangential(kind);
  }
  normal = std::make_unique<NormalProblem>(C, grid, heights);
  reset();
}

/// Given compliances (the finite-contact constructor), no coupling.
TangentialProblem::Impl::Impl(const Grid& g, std::shared_ptr<const LinearOperator> normal_c,
                              std::shared_ptr<const LinearOperator> tangential_c, std::vector<double> h,
                              FrictionLaw f)
    : grid(g), materials{Elastic::make_rigid(), Elastic::make_rigid()}, friction(std::move(f)),
      kind(OperatorKind::automatic),
      comps(g.dimension == 2 ? 1 : 2), N(g.size()), coupled(false), given_operators(true), heights(std::move(h)) {
  C = std::move(normal_c);
  Ct = std::move(tangential_c);
  if (Ct->rows() != comps * N || Ct->cols() != comps * N)
    throw std::invalid_argument("tangential problem: the tangential compliance does not fit the grid");
  normal = std::make_unique<NormalProblem>(C, grid, heights);
  reset();
}

/// Relative tangential displacement of (p, tau): kappa B21 p + B22 tau (4.2).
void TangentialProblem::Impl::displacement(const std::vector<double>& p, const std::vector<double>& tau,
                                           std::vector<double>& u, const LinearOperator& ct,
                                           const LinearOperator* b21) const {
  ct.apply(tau, u);
  if (coupled && b21) {
    std::vector<double>& w = displacement_work;
    b21->apply(p, w);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] += w[i];
  }
}

/// The previous relative displacement taken (shift_x, shift_y) elements downstream (the
/// material now at (x, y) was at (x + shift_x dx, y + shift_y dy) at the start of the step,
/// (3.8)): bilinear interpolation between the four neighbouring whole-element shifts.
/// With displacement_prev known, the shifts are index shifts of it: no operator apply (the
/// values beyond the grid's edge, which only an apply gives, are taken from the nearest element
/// and the elements that needed them listed in memory_beyond_grid). Otherwise, or `exact`, one
/// apply of the shifted kernels' weighted sum, exact also beyond the grid edge (the weights
/// scale their spectra: three forward and two inverse transforms for any travel).
void TangentialProblem::Impl::convected_displacement(double shift_x, double shift_y, std::vector<double>& u,
                                                     bool exact) {
  const int kx = static_cast<int>(std::floor(shift_x)), ky = static_cast<int>(std::floor(shift_y));
  const double tx = shift_x - kx, ty = shift_y - ky;
  memory_beyond_grid.clear();
  if (!exact && displacement_prev.size() == comps * N) return interpolate_convected(kx, ky, tx, ty, u);
  if (kx == 0 && ky == 0 && tx <= 0.0 && ty <= 0.0) return displacement(p_prev, tau_prev, u, *Ct, B21.get());
  const bool lateral = ty > 0.0;
  std::unique_ptr<WeightedConvolutions>& op = convected[{kx, ky, lateral}];
  if (!op) {
    std::vector<std::pair<int, int>> shifts{{kx, ky}, {kx + 1, ky}};
    if (lateral) shifts.insert(shifts.end(), {{kx, ky + 1}, {kx + 1, ky + 1}});
    op = half_space->displacement_shifted(shifts, coupled, kind);
  }
  if (lateral)
    op->set_weights({(1.0 - tx) * (1.0 - ty), tx * (1.0 - ty), (1.0 - tx) * ty, tx * ty});
  else
    op->set_weights({1.0 - tx, tx});
  convected_input = tau_prev;
  if (coupled) convected_input.insert(convected_input.end(), p_prev.begin(), p_prev.end());
  op->apply(convected_input, u);
}

/// u_prev of (3.8) at element (i, j): sum over the shifts (kx + a, ky + b), a, b in {0, 1}, of
/// weight_ab D(i + kx + a, j + ky + b), D = displacement_prev; the same weighted sum of whole
/// shifts as the exact apply, whose shift (k, l) is D at (i + k, j + l) wherever that is on the
/// grid. A source beyond the edge is clamped to the grid and its element listed.
void TangentialProblem::Impl::interpolate_convected(int kx, int ky, double tx, double ty, std::vector<double>& u) {
  const int nx = grid.nx, ny = grid.ny;
  const double wx[2] = {1.0 - tx, tx}, wy[2] = {1.0 - ty, ty};
  u.resize(comps * N);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t e = grid.index(i, j);
      bool beyond = false;
      const auto on_grid = [&beyond](int k, int n) {  // a source index clamped to the grid
        beyond = beyond || k < 0 || k >= n;
        return std::clamp(k, 0, n - 1);
      };
      double sum[2] = {0.0, 0.0};
      for (int b = 0; b < 2; ++b) {
        if (wy[b] == 0.0) continue;
        const int js = on_grid(j + ky + b, ny);
        for (int a = 0; a < 2; ++a) {
          if (wx[a] == 0.0) continue;
          const std::size_t source = grid.index(on_grid(i + kx + a, nx), js);
          const double w = wx[a] * wy[b];
          for (int c = 0; c < comps; ++c) sum[c] += w * displacement_prev[c * N + source];
        }
      }
      for (int c = 0; c < comps; ++c) u[c * N + e] = sum[c];
      if (beyond) memory_beyond_grid.push_back(e);
    }
}

/// The whole grid's tangential preconditioner (built on first use); none for given operators
/// (a finite body's compliance is not translation invariant) or the sparse form.
const TangentialPreconditioner* TangentialProblem::Impl::grid_preconditioner() {
  if (!half_space || sparse) return nullptr;
  if (!Ct_preconditioner) Ct_preconditioner = std::make_unique<TangentialPreconditioner>(*Ct, grid);
  return Ct_preconditioner.get();
}

}  // namespace dc

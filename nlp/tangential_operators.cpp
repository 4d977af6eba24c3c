// TangentialProblem::Impl: the operators of one grid and material pair (C, Ct, the kappa terms
// B21, B32 of (4.26)-(4.27)), the relative displacement kappa B21 p + B22 tau (4.2), and the
// previous displacement shifted by whole elements and convected between them (3.8).
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

/// u at the shift s (elements) along one axis: linear interpolation between the neighbouring
/// whole-element shifts, at_whole(k, out) filling out at the shift k; `work` holds the second.
template <class AtWhole>
void TangentialProblem::Impl::interpolate(double s, std::vector<double>& u, std::vector<double>& work,
                                          AtWhole&& at_whole) {
  const int k = static_cast<int>(std::floor(s));
  const double theta = s - k;
  at_whole(k, u);
  if (theta <= 0.0) return;
  at_whole(k + 1, work);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = (1.0 - theta) * u[i] + theta * work[i];
}

/// The previous relative displacement taken (shift_x, shift_y) elements downstream (the
/// material now at (x, y) was at (x + shift_x dx, y + shift_y dy) at the start of the step,
/// (3.8)): bilinear interpolation between the four neighbouring whole-element shifts, each exact
/// also beyond the grid edge. shift_y = 0 is the linear interpolation along x alone (the same
/// arithmetic, bit for bit, as before y was convected).
void TangentialProblem::Impl::convected_displacement(double shift_x, double shift_y, std::vector<double>& u) {
  interpolate(shift_y, u, convected_row_work, [&](int ky, std::vector<double>& row) {
    interpolate(shift_x, row, convected_x_work, [&](int kx, std::vector<double>& out) {
      shifted_displacement(kx, ky, out);
    });
  });
}

/// The previous relative displacement at the whole-element shift (kx, ky).
void TangentialProblem::Impl::shifted_displacement(int kx, int ky, std::vector<double>& out) {
  if (kx == 0 && ky == 0) return displacement(p_prev, tau_prev, out, *Ct, B21.get());
  ShiftedCompliance& ops = shifted[{kx, ky}];
  if (!ops.ct) {
    ops.ct = half_space->tangential_shifted(kx, ky, kind);
    if (coupled) ops.b21 = half_space->tangential_from_normal_shifted(kx, ky, kind);
  }
  displacement(p_prev, tau_prev, out, *ops.ct, ops.b21.get());
}

/// The whole grid's tangential preconditioner (built on first use); none for given operators
/// (a finite body's compliance is not translation invariant) or the sparse form.
const TangentialPreconditioner* TangentialProblem::Impl::grid_preconditioner() {
  if (!half_space || sparse) return nullptr;
  if (!Ct_preconditioner) Ct_preconditioner = std::make_unique<TangentialPreconditioner>(*Ct, grid);
  return Ct_preconditioner.get();
}

}  // namespace dc

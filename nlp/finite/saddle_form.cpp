#include "saddle_form.hpp"

#include <algorithm>
#include <cmath>

#include "backend_choice.hpp"
#include "errors.hpp"
#include "scaled_operator.hpp"

namespace dc {

SaddleBody saddle_body_block(const fe::ElasticBody& body, const fe::ContactFace& face, const Grid& grid,
                             const std::vector<int>& components, double traction_unit, double energy_unit,
                             double force_scale) {
  const Eigen::Index N = static_cast<Eigen::Index>(grid.size()), n = static_cast<Eigen::Index>(body.dofs());
  const Eigen::Index n_x = static_cast<Eigen::Index>(components.size()) * N, col_v = n_x, col_a = n_x + n;
  const double area = grid.area(), force_unit = traction_unit * area;
  SaddleBody out;
  out.v_unit = energy_unit / force_unit;  // the displacement the traction unit causes
  // Scales of the rigid modes: rows R'(M R a - B t) in units of the resultant (times the radius
  // of gyration for the rotations), a in units of the acceleration it gives.
  const Eigen::Matrix<double, 6, 6>& RMR = body.rigid_mass();
  Eigen::Matrix<double, 6, 1> rigid_row, a_unit;
  for (int j = 0; j < 6; ++j) {
    const double lever = j < 3 ? 1.0 : std::sqrt(RMR(j, j) / body.mass());
    rigid_row(j) = 1.0 / (force_scale * lever);
    a_unit(j) = force_scale * lever / RMR(j, j);
  }
  const Eigen::SparseMatrix<double>& Ks = body.supported_stiffness();
  const Eigen::MatrixXd& MR = body.mass_rigid_modes();
  const Eigen::MatrixXd& R = body.rigid_modes();
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& Bt = face.transfer();
  std::vector<char> held(static_cast<std::size_t>(n), 0);
  for (int s : body.supports()) held[static_cast<std::size_t>(s)] = 1;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(2 * Ks.nonZeros() + 7 * n + 7 * n_x));
  // The equilibrium rows in units of force_unit: Ks v - B t + M R a = 0 (held dofs: v = 0).
  const double kv = out.v_unit / force_unit;
  for (Eigen::Index c = 0; c < Ks.outerSize(); ++c)  // both halves from the lower one
    for (Eigen::SparseMatrix<double>::InnerIterator it(Ks, c); it; ++it) {
      if (it.value() == 0.0) continue;
      t.emplace_back(it.row(), col_v + it.col(), kv * it.value());
      if (it.row() != it.col()) t.emplace_back(it.col(), col_v + it.row(), kv * it.value());
    }
  Eigen::Matrix<double, 6, Eigen::Dynamic> RtB = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n_x);
  for (std::size_t c = 0; c < components.size(); ++c)
    for (Eigen::Index k = 0; k < Bt.outerSize(); ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(c) * N + k;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Bt, k); it; ++it) {
        const Eigen::Index dof = 3 * it.col() + components[c];  // t acts on the body along +component
        RtB.col(col) += it.value() * R.row(dof).transpose();
        if (!held[static_cast<std::size_t>(dof)]) t.emplace_back(dof, col, -traction_unit / force_unit * it.value());
      }
    }
  for (Eigen::Index r = 0; r < n; ++r)  // + M R a: the inertia relief
    if (!held[static_cast<std::size_t>(r)])
      for (int j = 0; j < 6; ++j)
        if (MR(r, j) != 0.0) t.emplace_back(r, col_a + j, a_unit(j) / force_unit * MR(r, j));
  for (int j = 0; j < 6; ++j) {  // R'M R a - R'B t = 0
    for (int l = 0; l < 6; ++l)
      if (RMR(j, l) != 0.0) t.emplace_back(n + j, col_a + l, rigid_row(j) * a_unit(l) * RMR(j, l));
    for (Eigen::Index k = 0; k < n_x; ++k)
      if (RtB(j, k) != 0.0) t.emplace_back(n + j, k, -rigid_row(j) * traction_unit * RtB(j, k));
  }
  SparseBlock& b = out.block;
  b.n = static_cast<int>(n + 6);
  b.rows.resize(n + 6, n_x + n + 6);
  b.rows.setFromTriplets(t.begin(), t.end());
  // The body's energy 1/2 v'Ks v in units of energy_unit.
  b.hessian.resize(n + 6, n + 6);
  std::vector<Eigen::Triplet<double>> h;
  h.reserve(static_cast<std::size_t>(Ks.nonZeros()));
  const double kh = out.v_unit * out.v_unit / energy_unit;
  for (Eigen::Index c = 0; c < Ks.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Ks, c); it; ++it)
      if (it.row() >= it.col()) h.emplace_back(it.row(), it.col(), kh * it.value());
  b.hessian.setFromTriplets(h.begin(), h.end());
  return out;
}

Eigen::VectorXd saddle_body_displacement(const fe::ElasticBody& body, const std::vector<double>& block_x,
                                         double v_unit) {
  const Eigen::Index n = static_cast<Eigen::Index>(body.dofs());
  if (static_cast<Eigen::Index>(block_x.size()) < n) return Eigen::VectorXd::Zero(n);
  // u = v - R (R'M R)^-1 (M R)'v: the displacement relative to the body's mean rigid motion.
  const Eigen::VectorXd v = v_unit * Eigen::Map<const Eigen::VectorXd>(block_x.data(), n);
  const Eigen::Matrix<double, 6, 1> r = body.rigid_mass().ldlt().solve(body.mass_rigid_modes().transpose() * v);
  return v - body.rigid_modes() * r;
}

std::vector<std::string> saddle_backend_order(const std::string& requested) {
  if (requested == "auto" || requested == "ipopt") return {"ipopt"};
  throw InputError("solver.backend", "the sparse form (fe_body.program 'sparse') is solved by Ipopt: use 'ipopt' or "
                                     "'auto', or the condensed program for '" + requested + "'");
}

SaddleNormalOutcome solve_saddle_normal(const fe::ElasticBody& body, const fe::ContactFace& face,
                                        const LinearOperator& halfspace, const Grid& grid,
                                        const std::vector<double>& heights, const NormalSpec& control,
                                        SolveOptions options, const std::string& backend) {
  const std::size_t N = grid.size();
  const double area = grid.area(), c0 = halfspace.diagonal(0);
  std::size_t n_free = 0;
  for (double h : heights) n_free += std::isfinite(h) ? 1 : 0;
  // Scaled as NormalProblem scales (4.7): p_ref is the pressure of the force on a quarter of the
  // grid, the objective in units of the energy A c0 p_ref^2 (the pressure block's diagonal is 1).
  const double n_ref = std::max(1.0, 0.25 * static_cast<double>(n_free));
  const double p_ref = control.control == Control::force ? control.value / (area * n_ref)
                                                         : control.value / (c0 * std::sqrt(n_ref));
  const double energy = area * c0 * p_ref * p_ref;
  const double delta = control.control == Control::approach ? control.value : 0.0;
  const ScaledOperator Q(halfspace, 1.0 / c0);
  const SaddleBody rows = saddle_body_block(body, face, grid, {2}, p_ref, energy, p_ref * area * n_ref);
  QuadraticProgram qp;
  qp.Q = &Q;
  qp.block = &rows.block;
  qp.c.assign(N, 0.0);
  qp.lower.assign(N, 0.0);
  qp.upper.assign(N, kInf);
  qp.x0.assign(N, 0.0);
  LinearEquality force;  // sum A p = P in units of A p_ref n_ref
  force.a.assign(N, 0.0);
  force.b = 1.0;
  for (std::size_t i = 0; i < N; ++i) {
    if (!std::isfinite(heights[i])) {
      qp.upper[i] = 0.0;  // cannot touch
      continue;
    }
    qp.c[i] = p_ref * area * (heights[i] - delta) / energy;
    force.a[i] = 1.0 / n_ref;
    qp.x0[i] = n_ref / static_cast<double>(n_free);  // the force row holds
  }
  if (control.control == Control::force) qp.equalities.push_back(std::move(force));

  SaddleNormalOutcome out;
  options.exact_hessian_limit = static_cast<int>(kSaddleExactLimit);
  out.exact_hessian = options.hessian == "exact" || (options.hessian != "limited-memory" && N <= kSaddleExactLimit);
  const TimedOutcome run = run_backend(backend, qp, options, [](const QuadraticProgram&, const SolveOptions&) {
    SolveOutcome none;
    none.message = "native: the native solvers take no sparse rows";
    return none;
  });
  const SolveOutcome& o = run.outcome;
  out.success = o.success;
  out.iterations = o.iterations;
  out.message = "sparse form" +
                std::string(backend != "ipopt" ? "" : out.exact_hessian ? ", exact Hessian" : ", limited-memory Hessian") +
                ": " + o.message;
  if (o.x.size() != N || static_cast<int>(o.block_x.size()) != rows.block.n) {
    out.success = false;
    return out;
  }
  out.pressure.resize(N);
  for (std::size_t i = 0; i < N; ++i) out.pressure[i] = std::max(o.x[i], 0.0) * p_ref;
  out.body_displacement = saddle_body_displacement(body, o.block_x, rows.v_unit);
  std::vector<double> w_hs, w_body(N);
  halfspace.apply(out.pressure, w_hs);
  face.mean_displacement(out.body_displacement, 2, w_body.data());
  out.displacement.resize(N);
  for (std::size_t i = 0; i < N; ++i) out.displacement[i] = w_hs[i] + w_body[i];
  return out;
}

}  // namespace dc

#include "saddle_form.hpp"

#include <algorithm>
#include <cmath>

#include "backend_choice.hpp"
#include "errors.hpp"
#include "scaled_operator.hpp"

namespace dc {

SaddleBody saddle_body_block(const fe::ElasticBody& body, const fe::StressEquilibrium& stresses,
                             const fe::ContactFace& face, const Grid& grid, const std::vector<int>& components, double traction_unit, double energy_unit,
                             double force_scale) {
  const Eigen::Index N = static_cast<Eigen::Index>(grid.size()), n = static_cast<Eigen::Index>(body.dofs());
  const Eigen::Index ns = static_cast<Eigen::Index>(stresses.stresses());
  const Eigen::Index n_x = static_cast<Eigen::Index>(components.size()) * N, col_s = n_x, col_a = n_x + ns;
  const double area = grid.area(), force_unit = traction_unit * area;
  SaddleBody out;
  // The weighted stresses in units that give the energy's blocks a diagonal of order one.
  double mean_compliance = 0.0;
  for (const auto& H : stresses.compliance) mean_compliance += H(0, 0) / static_cast<double>(stresses.compliance.size());
  out.s_unit = std::sqrt(energy_unit / mean_compliance);
  // Scales of the rigid modes: rows R'(M R a - B t) in units of the resultant (times the radius
  // of gyration for the rotations), a in units of the acceleration it gives.
  const Eigen::Matrix<double, 6, 6>& RMR = body.rigid_mass();
  Eigen::Matrix<double, 6, 1> rigid_row, a_unit;
  for (int j = 0; j < 6; ++j) {
    const double lever = j < 3 ? 1.0 : std::sqrt(RMR(j, j) / body.mass());
    rigid_row(j) = 1.0 / (force_scale * lever);
    a_unit(j) = force_scale * lever / RMR(j, j);
  }
  const Eigen::MatrixXd& MR = body.mass_rigid_modes();
  const Eigen::MatrixXd& R = body.rigid_modes();
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& Bt = face.transfer();
  // One equilibrium row per dof but the six held ones (their rows follow from the rigid modes').
  std::vector<Eigen::Index> row_of_dof(static_cast<std::size_t>(n), 0);
  for (int held : body.supports()) row_of_dof[static_cast<std::size_t>(held)] = -1;
  Eigen::Index equilibrium_rows = 0;
  for (auto& r : row_of_dof)
    if (r >= 0) r = equilibrium_rows++;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(stresses.forces.nonZeros() + 7 * n + 7 * n_x));
  // The equilibrium rows in units of force_unit: Gt s - B t + M R a = 0.
  const double ks = out.s_unit / force_unit;
  for (Eigen::Index c = 0; c < stresses.forces.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(stresses.forces, c); it; ++it)
      if (const Eigen::Index row = row_of_dof[static_cast<std::size_t>(it.row())]; row >= 0)
        t.emplace_back(row, col_s + it.col(), ks * it.value());
  Eigen::Matrix<double, 6, Eigen::Dynamic> RtB = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n_x);
  for (std::size_t c = 0; c < components.size(); ++c)
    for (Eigen::Index k = 0; k < Bt.outerSize(); ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(c) * N + k;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Bt, k); it; ++it) {
        const Eigen::Index dof = 3 * it.col() + components[c];  // t acts on the body along +component
        RtB.col(col) += it.value() * R.row(dof).transpose();
        if (const Eigen::Index row = row_of_dof[static_cast<std::size_t>(dof)]; row >= 0)
          t.emplace_back(row, col, -traction_unit / force_unit * it.value());
      }
    }
  for (Eigen::Index dof = 0; dof < n; ++dof)  // + M R a: the inertia relief
    if (const Eigen::Index row = row_of_dof[static_cast<std::size_t>(dof)]; row >= 0)
      for (int j = 0; j < 6; ++j)
        if (MR(dof, j) != 0.0) t.emplace_back(row, col_a + j, a_unit(j) / force_unit * MR(dof, j));
  for (int j = 0; j < 6; ++j) {  // R'M R a - R'B t = 0
    for (int l = 0; l < 6; ++l)
      if (RMR(j, l) != 0.0) t.emplace_back(equilibrium_rows + j, col_a + l, rigid_row(j) * a_unit(l) * RMR(j, l));
    for (Eigen::Index k = 0; k < n_x; ++k)
      if (RtB(j, k) != 0.0) t.emplace_back(equilibrium_rows + j, k, -rigid_row(j) * traction_unit * RtB(j, k));
  }
  SparseBlock& b = out.block;
  b.n = static_cast<int>(ns + 6);
  b.rows.resize(equilibrium_rows + 6, n_x + ns + 6);
  b.rows.setFromTriplets(t.begin(), t.end());
  // The body's complementary energy 1/2 s'H s in units of energy_unit: 6 x 6 blocks, lower triangles.
  b.hessian.resize(ns + 6, ns + 6);
  std::vector<Eigen::Triplet<double>> h;
  h.reserve(stresses.compliance.size() * 21);
  const double kh = out.s_unit * out.s_unit / energy_unit;
  for (std::size_t q = 0; q < stresses.compliance.size(); ++q) {
    const Eigen::Index base = 6 * static_cast<Eigen::Index>(q);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j <= i; ++j) h.emplace_back(base + i, base + j, kh * stresses.compliance[q](i, j));
  }
  b.hessian.setFromTriplets(h.begin(), h.end());
  return out;
}

Eigen::VectorXd saddle_body_displacement(const fe::ElasticBody& body, const fe::ContactFace& face, int component,
                                         const std::vector<double>& tractions) {
  // The nodal forces B t of the tractions, deformed with the kept factor: u = P' Ks^-1 P F.
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(body.dofs())), u;
  face.add_forces(tractions.data(), component, 1.0, F);
  body.deform(F, u);
  return u;
}

std::vector<std::string> saddle_backend_order(Backend requested) {
  if (requested == Backend::automatic || requested == Backend::ipopt) return {"ipopt"};
  throw InputError("solver.backend", "the sparse form (fe_body.program 'sparse') is solved by Ipopt: use 'ipopt' or "
                                     "'auto', or the condensed program for '" +
                                         std::string(to_string(requested)) + "'");
}

SaddleNormalOutcome solve_saddle_normal(const fe::ElasticBody& body, const fe::StressEquilibrium& stresses,
                                        const fe::ContactFace& face,
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
  const SaddleBody rows = saddle_body_block(body, stresses, face, grid, {2}, p_ref, energy, p_ref * area * n_ref);
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
  out.exact_hessian =
      options.hessian == Hessian::exact || (options.hessian != Hessian::limited_memory && N <= kSaddleExactLimit);
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
  out.body_displacement = saddle_body_displacement(body, face, 2, out.pressure);
  out.weighted_stresses.resize(static_cast<std::size_t>(rows.block.n - 6));
  for (std::size_t q = 0; q < out.weighted_stresses.size(); ++q) out.weighted_stresses[q] = rows.s_unit * o.block_x[q];
  std::vector<double> w_hs, w_body(N);
  halfspace.apply(out.pressure, w_hs);
  face.mean_displacement(out.body_displacement, 2, w_body.data());
  out.displacement.resize(N);
  for (std::size_t i = 0; i < N; ++i) out.displacement[i] = w_hs[i] + w_body[i];
  return out;
}

}  // namespace dc

#pragma once
// Melan's static shakedown theorem for a translation-invariant moving load, as a convex program
// solved by Ipopt, with our own certificate.
//
// Melan (E. Melan, Ing.-Arch. 9 (1938) 116-126; W. T. Koiter, Progress in Solid Mechanics 1,
// 1960): an elastic-perfectly plastic body shakes down under a load history if a time-
// independent self-equilibrated residual stress rho exists with lambda sigma^e(t) + rho inside
// the yield surface everywhere at all times. For a load moving along x over a half-space
// (nlp/shakedown_input.hpp: the positions x_i are the instants, rho depends on depth only) with
// the yield function f(sigma) = |L sigma| (core/yield_criterion.hpp), sampled at depths z_j and
// positions x_i, the largest safe load factor is
//   lambda* = max lambda  over (lambda, rho_1 .. rho_m)
//             s.t.  g_ij = |lambda u_ij + W y_j|^2 <= 1   for every sample (i, j),           (1)
// u_ij = L sigma^e(x_i, z_j), W y_j = L rho_j (nlp/shakedown_samples.hpp). Each g_ij is a convex
// quadratic (a second-order cone squared): Ipopt with the exact Hessian, 1 + m p unknowns and
// m n constraints (p the residual's free components, 2 for the line contact).
//
// Constraint generation (ShakedownOptions::constraint_generation, the default): few samples of a
// depth bind, so Ipopt solves (1) on a working set (per depth the first-yield sample and the
// extremes along and across the residual's directions), the samples its answer violates are
// added and (1) solved again from the answer scaled inside, until no sample is violated; 64 x 256
// samples take 2 rounds of a few hundred conditions. The certificate below is measured on every
// sample, so it certifies the whole program.
//
// Structure: given lambda the depths separate, and each depth's safe set of lambda is an
// interval [0, lambda_j] (convex, containing lambda = 0 with rho = 0), so lambda* = min_j lambda_j;
// nlp/shakedown_by_depth.hpp computes the lambda_j independently (bisection, exact per-depth
// feasibility) as the cross-check.
//
// Certificate (measured by us, never Ipopt's claim):
//  - primal: v = max_ij sqrt(g_ij) at Ipopt's point. (1) is positively homogeneous in
//    (lambda, y), so the point scaled by 1/v is feasible: lambda_lo = lambda / v is a certified
//    lower bound, and the yield violation is max(v - 1, 0).
//  - dual: for any multipliers mu_ij >= 0 (Ipopt's, clipped at 0; 0 off the working set), weak
//    duality gives
//      lambda* <= lambda_up = sqrt(S / Q),   S = sum_ij mu_ij,
//      Q = sum_j min_y sum_i mu_ij |u_ij + W y|^2,                                           (2)
//    from the Lagrangian lambda - sum mu_ij (g_ij - 1): its supremum over y is
//    lambda - lambda^2 Q + S (each g is homogeneous of degree 2 in (lambda, y)), over lambda
//    1/(4Q) + S, and over a scaling t mu of the multipliers sqrt(S/Q).
//    The duality gap (lambda_up - lambda_lo) / lambda_up bounds the relative error of lambda*.
// The program itself, over stations (a depth here), is nlp/shakedown_stations.hpp, shared with the
// 3-D model (nlp/shakedown_3d.hpp).
// The elastic limit (first yield) is lambda_e = 1 / max_ij |u_ij|, exact (tresca_inscribed:
// Tresca's own first yield from the principal stresses, core/yield_criterion.hpp). The verdict at the
// load as given (lambda = 1) compares both (shakedown_result.hpp); when the residual absorbs the
// stress of every depth (one y_j with u_ij = -W y_j for all i) the program is unbounded.
#include "shakedown_input.hpp"
#include "shakedown_options.hpp"
#include "shakedown_result.hpp"
#include "yield_criterion.hpp"

namespace dc {

/// The shakedown analysis of `history` (the elastic stress of the unit load) under `criterion`
/// with the residual stresses of `model`. Throws std::invalid_argument for invalid input (the
/// validate() messages); solver trouble is reported in the result's status.
ShakedownResult solve_shakedown(const StressHistory& history, const YieldCriterion& criterion,
                                const ResidualModel& model = ResidualModel::line_contact(),
                                const ShakedownOptions& options = {});

}  // namespace dc

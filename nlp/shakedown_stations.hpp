#pragma once
// Program (1) of shakedown_problem.hpp in its general form, over "stations": a station is the set
// of samples that share one residual stress (a depth of the depth-only model; a point (y_j, z_k)
// of the 3-D model, nlp/shakedown_3d.hpp). Station s has the samples u_si (i = 0 .. n-1, the
// positions along x) and its residual in the yield function's space is W_s theta[I_s]: a q x |I_s|
// matrix on the unknowns I_s of one vector theta (the residual over k), shared between stations
// when the model couples them (the 3-D stress functions do):
//   lambda* = max lambda  s.t.  g_si = |lambda u_si + W_s theta[I_s]|^2 <= 1  for every (s, i).  (1')
// The depth-only model is the special case I_j = {j p, .., j p + p - 1}, W_j = W.
//
// The certificate is (2) of shakedown_problem.hpp with the inner minimisation over the whole of theta:
//   Q = min_theta sum_s sum_i mu_si |u_si + W_s theta[I_s]|^2
//     = sum_s (sum_i mu_si |u_si|^2 - |b_s|^2 / m_s) + min_theta sum_s m_s |b_s / m_s + W_s theta[I_s]|^2,
// m_s = sum_i mu_si, b_s = sum_i mu_si u_si (the stations with m_s = 0 drop out): one sparse
// linear least-squares problem (stations coupled through theta), solved by its normal equations
// (a sparse LDL' with iterative refinement; a singular system, e.g. unknowns no weighted station
// sees, is consistent and Q, the residual, unique), and Q summed as non-negative terms at that
// minimiser. The derivation of lambda* <= sqrt(S / Q) is unchanged: each g is homogeneous of
// degree 2 in (lambda, theta).
// The program is unbounded when Q with unit weights is zero (one theta absorbs every sample).
#include <vector>

#include <Eigen/Core>

#include "shakedown_options.hpp"
#include "shakedown_result.hpp"
#include "shakedown_samples.hpp"

namespace dc {

struct ShakedownStations {
  int stations = 0, positions = 0;
  int unknowns = 0;                      ///< the size of theta
  Eigen::MatrixXd u;                     ///< q x (stations * positions): column s * positions + i
  std::vector<std::vector<int>> index;   ///< I_s, ascending, one per station
  std::vector<Eigen::MatrixXd> w;        ///< W_s (q x |I_s|), one per station

  Eigen::Ref<const Eigen::VectorXd> sample(int station, int position) const {
    return u.col(static_cast<Eigen::Index>(station) * positions + position);
  }
};

/// The depth-only model's stations: one per depth, I_j = {j p .. j p + p - 1}, W_j = samples.w.
ShakedownStations depth_stations(const ShakedownSamples& samples);

/// Program (1') with constraint generation and the certificate (shakedown_problem.hpp), by Ipopt.
/// Fills status, message, load_factor, elastic_limit (1 / max |u|), elastic_limit_depth (the
/// station) and _position, critical_depth (the station), certificate, iterations, rounds,
/// constraints; `theta` gets Ipopt's residual unknowns. Not set: residual, verdict, time_s,
/// limit_upper_bound (the front ends do).
ShakedownResult solve_shakedown_stations(const ShakedownStations& stations, const ShakedownOptions& options,
                                         std::vector<double>& theta);

/// The verdict of a result whose elastic limit and bounds are set (shakedown_result.hpp).
void set_shakedown_verdict(ShakedownResult& result);

}  // namespace dc

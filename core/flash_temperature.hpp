#pragma once
// Flash temperature: the quasi-steady surface temperature rise of the two bodies of a contact
// heated by the frictional flux q (W/m^2, piecewise constant on the grid, q >= 0), shared
// between them.
//
// Each surface s (base, body) has its own conductivity K_s, diffusivity kappa_s and the speed
// V_s of the contact relative to it (moving_heat_source.hpp: the surface moves at -V_s through
// the contact; V_s = 0 for a surface the contact does not move over, e.g. a pin on a disc).
// The flux into the base is g = f q, into the body (1 - f) q, and
//   T_s = A_s g_s,   (A_s g)(i, j) = sum over (i', j') of table_s(i - i', j - j') g(i', j')     (1)
// with table_s the exact element coefficients of moving_heat_source.hpp (Jaeger's moving
// source), summed through the project's convolution operators (linear_operator.hpp): the dense
// matrix for small grids, the zero-padded (linear, not circular) FFT convolution for large.
//
// The partition f (Blok 1937, Proc. Gen. Discussion on Lubrication, IMechE 2, 222-235: the two
// surfaces share the contact's temperature; Jaeger 1942, Archard 1958, Wear 2, 438-455):
//   equal_mean:  one fraction f with equal mean temperatures over the heated elements (q > 0):
//                f mean(A_base q) = (1 - f) mean(A_body q), i.e. f = m_body / (m_base + m_body)
//                (a case's `partition: auto`);
//   equal_max:   the same with the maxima (each T_s is linear in f, its maximum scales with it);
//   pointwise:   f per element so that T_base = T_body on every heated element: with g = f q,
//                (A_base + A_body)_SS g_S = (A_body q)_S on the heated set S, solved densely
//                (LU with partial pivoting) up to `dense_limit` heated elements, beyond by
//                restarted GMRES (gmres.hpp) with the operators (1), from the equal-mean share,
//                to 1e-12 relative residual. The local fraction may leave [0, 1] near the
//                leading edge (heat flows back into the body that is cooler there); it is
//                reported as it is;
//   fixed:       f given.
// The quasi-steady form: the flux field is taken as steady in the contact's frame (steady
// rolling or sliding, or one step of a run whose flux changes slowly over the contact time).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "grid.hpp"
#include "influence.hpp"
#include "linear_operator.hpp"
#include "moving_heat_source.hpp"
#include "operator_kind.hpp"
#include "subsurface_influence.hpp"

namespace dc {

/// How the flux is shared between base and body (see above).
struct HeatPartition {
  enum class Rule { equal_mean, equal_max, pointwise, fixed } rule = Rule::equal_mean;
  double base_fraction = 0.5;  ///< `fixed`: the fraction of q into the base, in [0, 1]
  /// `pointwise`: heated elements solved densely at most (2000: a 32 MB matrix); beyond, GMRES.
  std::size_t dense_limit = 2000;
};

/// Temperature rises (K) at the element centres, the grid's order.
struct FlashTemperatureResult {
  std::vector<double> base, body;
  /// Per element the fraction of q into the base (elements without heat: the overall fraction).
  std::vector<double> base_flux_fraction;
  double base_fraction = 0.5;  ///< of the total heat (W, 2-D W/m) into the base
  double base_max = 0.0, body_max = 0.0;    ///< over the grid
  std::size_t base_max_element = 0, body_max_element = 0;
  double base_mean = 0.0, body_mean = 0.0;  ///< over the heated elements (area mean)
  std::size_t heated_elements = 0;
  double total_heat = 0.0;  ///< sum q * element area (W; 2-D W/m)
};

/// r.total_heat and r.heated_elements of the flux q (std::invalid_argument for a value that is
/// negative or not finite).
void flash_flux_totals(const Grid& grid, const std::vector<double>& q, FlashTemperatureResult& r);
/// r's maxima (and their elements) and heated means of r.base and r.body, over the elements
/// where q > 0 (the statistics of compute(), for another model's maps).
void flash_result_statistics(const std::vector<double>& q, FlashTemperatureResult& r);

/// The two surfaces' operators (1) for one grid, built once (a run calls compute at every
/// step). Not thread-safe (the operators reuse their buffers).
class FlashTemperature {
 public:
  /// Errors (InputError) name `base_key` / `body_key` with the failing member (e.g.
  /// "base.conductivity", "body.speed": 2-D needs both speeds nonzero); a run passes its case's
  /// keys.
  FlashTemperature(const Grid& grid, const ThermalSurface& base, const ThermalSurface& body,
                   OperatorKind kind = OperatorKind::automatic, const std::string& base_key = "base",
                   const std::string& body_key = "body");

  /// Both temperature maps for the frictional flux `heat_flux` (grid.size() values >= 0,
  /// std::invalid_argument otherwise) shared by `partition`.
  FlashTemperatureResult compute(const std::vector<double>& heat_flux, const HeatPartition& partition = {}) const;

  /// T = A_side flux (the whole flux into that surface): grid.size() values each.
  void surface_temperature(BodySide side, const double* flux, double* temperature) const;
  std::vector<double> surface_temperature(BodySide side, const std::vector<double>& flux) const;

  const KernelTable& table(BodySide side) const { return side == BodySide::base ? base_table_ : body_table_; }
  const ThermalSurface& surface(BodySide side) const { return side == BodySide::base ? base_ : body_; }
  const Grid& grid() const { return grid_; }
  std::string kind() const { return base_op_->kind(); }  ///< "dense" or "fft"

 private:
  std::vector<double> pointwise_base_flux(const std::vector<double>& q, const std::vector<double>& body_full,
                                          double start_fraction, std::size_t dense_limit) const;

  Grid grid_;
  ThermalSurface base_, body_;
  KernelTable base_table_, body_table_;
  std::unique_ptr<LinearOperator> base_op_, body_op_;
};

/// The mean of T over the heated elements (q > 0); 0 when none is heated.
double heated_mean(const std::vector<double>& T, const std::vector<double>& q);

}  // namespace dc

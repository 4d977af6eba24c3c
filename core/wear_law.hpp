#pragma once
// Local wear laws: the worn depth one element loses in one load step from its pressure,
// traction and slip increment (issue 30; docs/wear_energy.md "Wear").
//   Archard:  dh = k p |ds| / H          (k dimensionless, H hardness in Pa)
//   energy:   dh = alpha (-tau . ds)     (alpha in m^3/J; -tau . ds the dissipated energy per
//                                         area, J/m^2, with tau the traction ON THE BODY)
// Each worn body loses this depth (a law per contact pair, not per body).
namespace dc {

enum class WearLawKind { archard, energy };

struct WearLaw {
  WearLawKind kind = WearLawKind::archard;
  double k = 0.0;            ///< Archard's dimensionless coefficient
  double hardness = 0.0;     ///< Archard's H (Pa)
  double coefficient = 0.0;  ///< energy law (m^3/J)

  /// The worn depth of one step (m) at pressure p (Pa), traction (tx, ty) on the body (Pa) and
  /// slip increment (sx, sy) (m); never negative (a dissipation below zero is the solver's
  /// round-off in stick).
  double depth(double p, double tx, double ty, double sx, double sy) const;
};

const char* to_string(WearLawKind kind);

}  // namespace dc

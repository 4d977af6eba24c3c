#pragma once
// Wear over a dynamic run (CASES.md "wear", docs/wear_energy.md "Wear in dynamic runs"): every
// accepted step wears both surfaces by the local law (core/wear_law.hpp) from the step's
// pressure, traction and slip, the slip scaled to the step's (the energy audit's frictional work,
// DynamicSample's contact_state.frictional_work: a steady-rolling step's slip is per dx of
// travel), so that Archard's volume is k/(mu H) x the dissipated energy to round-off. Each body's
// map is in its own frame:
//  - the base's along the track, world coordinates: the element at x of the contact frame (the
//    grid, centred under the body) is at X = x_c + x, x_c the body's x position at the step's end
//    (the lateral motion is left out: the rows keep the grid's y);
//  - the body's on its surface, over its circumference 2 pi R (R = body.radius): the material at
//    x is at arc S = R phi + x, phi the rotation about y (a body rolling along +x without slip
//    keeps its contact point at X = S); a body that does not turn wears in place.
// Over a step the contact travels from the step's start to its end: each element's volume is
// spread uniformly over the path its centre took (on the track from x_c,start + x to x_c,end + x,
// on the body from R phi_start + x to R phi_end + x) and binned into cells (the grid's dx along
// the track, doubled whenever the track would pass 16384 cells; 2 pi R / round(2 pi R / dx),
// at most 16384, round the circumference) by overlap, which keeps the
// volume: a steady-rolling step travelling many contact lengths wears the whole path, as steady
// rolling's pass does (wear_run.hpp); a body that does not move wears in place (the two cells
// around the centre, shared linearly). With wear.gap_feedback (default) the worn depth enters the
// gap (2.6) of the following steps: at every evaluation of a step the contact grid samples both
// maps (linear between cell centres) at the trial position and rotation (worn_depth), their sum
// added to the body's gap (dynamics::ContactWrench::set_worn_gap); the step's own wear is added
// when it is accepted.
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"

namespace dc::runs {

/// A worn-depth map: cells of the track or the circumference (a Grid whose x is world X or the
/// arc S, its rows the contact grid's y) and each cell's depth (m) in grid order i + nx j.
struct WornStrip {
  Grid grid;
  std::vector<double> depth;
  double max_depth() const;
  double volume() const;  ///< sum depth x cell area (2-D: per unit length)
};

class DynamicWear {
 public:
  /// `c` must outlive this object.
  explicit DynamicWear(const Case& c);
  bool wanted() const { return case_.wear.has_value(); }
  /// Every accepted step: its wear added to both maps.
  void observe(const Grid& grid, const dynamics::DynamicSample& s);
  /// wear.gap_feedback: the worn depth enters the following steps' gap.
  bool feeds_back() const { return wanted() && case_.wear->gap_feedback; }
  /// Both maps' depth under each grid element at trial kinematics k (m, summed), for the gap.
  void worn_depth(const dynamics::StepKinematics& k, std::vector<double>& depth) const;
  /// summary["wear"]: law, base / body {max_depth, volume}, cycles (the body's revolutions),
  /// travel (m), rolling_radius, the frames.
  void add_entries(nlohmann::json& summary) const;
  WornStrip base() const;  ///< along the track (x: world X); empty when the base does not wear
  WornStrip body() const;  ///< along the circumference (x: arc S from the first contact point)

 private:
  /// Cells of `width` along a line (k from `first`), ny rows each: depth at (k - first) * ny + j.
  struct Cells {
    double width = 0.0;
    long long wrap = 0;  ///< > 0: a circumference of `wrap` cells (k modulo wrap)
    long long first = 0, count = 0;
    std::vector<double> depth;
    double& at(long long k, int j, int ny);
    void coarsen(int ny);  ///< the track's cells doubled (their volume kept)
  };
  /// Adds the volume per unit y `volume` of an element whose centre went from a to b in row j.
  void deposit(Cells& cells, double a, double b, int j, double volume);
  /// The depth at `at` in row j, linear between cell centres (0 off the track).
  static double sample(const Cells& cells, double at, int j, int ny);
  WornStrip strip(const Cells& cells) const;
  const Case& case_;
  Cells base_, body_;
  double phi_ = 0.0, last_angle_ = 0.0, x_start_ = 0.0, x_end_ = 0.0;
  Grid grid_;  ///< the contact grid (its rows and dx)
};

}  // namespace dc::runs

#pragma once
// Wear over a dynamic run (CASES.md "wear", docs/wear_energy.md "Wear in dynamic runs"): every
// accepted step wears both surfaces by the local law (core/wear_law.hpp) from the step's
// pressure, traction and slip, the slip scaled to the step's (the energy audit's frictional work,
// DynamicSample's contact_state.frictional_work: a steady-rolling step's slip is per dx of
// travel), so that Archard's volume is k/(mu H) x the dissipated energy to round-off. Each body's
// map is in its own frame:
//  - the base's fixed to the track, world coordinates: the element at (x, y) of the contact frame
//    (the grid, centred under the body) is at (X, Y) = (x_c + x, y_c + y), (x_c, y_c) the body's
//    position; the map's rows are the grid's rows where the body started (cells of the grid's dy)
//    and grow sideways as the body moves laterally;
//  - the body's on its surface, over its circumference 2 pi R (R = body.radius): the material at
//    x is at arc S = R phi + x, phi the rotation about y (a body rolling along +x without slip
//    keeps its contact point at X = S); a body that does not turn wears in place.
// Over a step the contact travels from the step's start to its end: each element's volume is
// spread uniformly over the path its centre took (on the track from (x_c, y_c)_start + (x, y) to
// (x_c, y_c)_end + (x, y), on the body from R phi_start + x to R phi_end + x, in its row) and
// binned into cells by overlap along x (the grid's dx along the track, doubled whenever the track
// would pass 16384 cells; 2 pi R / round(2 pi R / dx), at most 16384, round the circumference)
// and, across the track, shared between the two rows whose centres the element's centre lies
// between (linearly: the overlap of a row of width dy with the element), taken at the middle of
// each part of the path between row centres; the rows double when the map would pass 2^22
// cells. This keeps the volume: a steady-rolling step travelling many contact lengths wears the
// whole path, as steady rolling's pass does (wear_run.hpp); a body that does not move wears in
// place (the two cells around the centre, shared linearly). With wear.gap_feedback (default) the
// worn depth enters the gap (2.6) of the following steps: at every evaluation of a step the
// contact grid samples both maps (linear between cell centres, along and across) at the trial
// position and rotation (worn_depth), their sum added to the body's gap
// (dynamics::ContactWrench::set_worn_gap); the step's own wear is added when it is accepted.
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"

namespace dc::runs {

/// A worn-depth map: cells of the track or the circumference (a Grid whose x is world X or the
/// arc S, its y world Y or the body's y) and each cell's depth (m) in grid order i + nx j.
struct WornStrip {
  Grid grid;
  std::vector<double> depth;
  double max_depth() const;
  double volume() const;  ///< sum depth x cell area (2-D: per unit length)
};

class DynamicWear {
 public:
  /// The most cells of the track's map in all (rows x cells along): beyond, the smaller cells double.
  static constexpr long long kMaxMapCells = 1LL << 22;
  /// `c` must outlive this object; `max_map_cells` the track map's budget (tests take smaller ones).
  explicit DynamicWear(const Case& c, long long max_map_cells = kMaxMapCells);
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
  WornStrip base() const;  ///< on the track (x, y: world X, Y); empty when the base does not wear
  WornStrip body() const;  ///< along the circumference (x: arc S from the first contact point)

 private:
  /// Cells of `width` x `height`: along x from `first` (count), across from `row_first` (rows);
  /// depth at (k - first) * rows + (l - row_first).
  struct Cells {
    double width = 0.0, height = 0.0;
    long long wrap = 0;  ///< > 0: a circumference of `wrap` cells (k modulo wrap)
    long long first = 0, count = 0, row_first = 0, rows = 0;
    bool fixed_rows = false;  ///< the body's: the grid's rows, never grown
    std::vector<double> depth;
    double& at(long long k, long long l);
    double value(long long k, long long l) const;  ///< 0 off the map
    void coarsen();       ///< the cells along x doubled (their volume kept)
    void coarsen_rows();  ///< the rows doubled (their volume kept)
  };
  /// Adds the volume `volume` of an element (its depth x the element's area) whose centre went
  /// from (a, u_a) to (b, u_b), u in rows (row l's centre at u = l).
  void deposit(Cells& cells, double a, double b, double u_a, double u_b, double volume);
  /// The same along x in row l alone.
  void deposit_in_row(Cells& cells, double a, double b, long long l, double volume);
  /// The depth at (at, u), linear between cell centres (0 off the map).
  static double sample(const Cells& cells, double at, double u);
  /// The base's row coordinate of world Y.
  double base_row(double Y) const;
  WornStrip strip(const Cells& cells) const;
  const Case& case_;
  Cells base_, body_;
  double phi_ = 0.0, last_angle_ = 0.0, x_start_ = 0.0, x_end_ = 0.0, y_end_ = 0.0;
  double y_reference_ = 0.0;  ///< world Y of the lower edge of the base's row 0
  Grid grid_;  ///< the contact grid (its rows and dx)
  long long max_map_cells_ = kMaxMapCells;
};

}  // namespace dc::runs

#pragma once
// The subsurface field of a run in time (CASES.md "subsurface"): the states of a loading history
// (every step, or every output.snapshot_every-th and the last) or a dynamic run's snapshots
// (output.snapshot_every), each state's field at the same depths (subsurface_run.hpp), and per
// body the worst von Mises, Tresca and orthogonal shear over the run with the step (and time)
// where each occurred. A sink (the command line's) writes each state's field as it is computed,
// so only one state's field is held at a time.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsurface_run.hpp"

namespace dc::runs {

/// One state of the run: its tractions and where it is in the run.
struct SubsurfaceState {
  int step = 0;
  double time = 0.0;  ///< s (a history: the step number)
  const output::StaticFields* fields = nullptr;
  double x_offset = 0.0, y_offset = 0.0;  ///< the grid origin's place in the base (a dynamic run: the body's)
};

/// What a dynamic run keeps for its field while it runs: the tractions of its snapshots and of
/// the step with the largest normal force so far (the slips and bounds dropped).
class SubsurfaceStates {
 public:
  void keep(int step, double time, double x_offset, double y_offset, output::StaticFields fields);
  bool exceeds_peak(double normal_force) const { return !has_peak_ || normal_force > peak_force_; }
  void keep_peak(int step, double time, double x_offset, double y_offset, double normal_force,
                 output::StaticFields fields);
  bool empty() const { return kept_.empty() && !has_peak_; }
  int peak_step() const { return has_peak_ ? peak_.step : -1; }
  /// The kept states by step, the peak's once (also when it is a snapshot's).
  std::vector<SubsurfaceState> states() const;

 private:
  struct Kept {
    int step = 0;
    double time = 0.0, x_offset = 0.0, y_offset = 0.0;
    output::StaticFields fields;
    SubsurfaceState state() const { return {step, time, &fields, x_offset, y_offset}; }
  };
  static output::StaticFields tractions_only(output::StaticFields fields);
  std::vector<Kept> kept_;
  Kept peak_;
  double peak_force_ = 0.0;
  bool has_peak_ = false;
};

/// A body's worst over the run: the extreme and the state it occurred in.
struct WorstSubsurface {
  struct At {
    FieldExtreme extreme;
    int step = 0;
    double time = 0.0;
  };
  std::string name;
  At von_mises, tresca, orthogonal_shear;
};

struct SubsurfaceSeries {
  std::vector<double> depths;
  std::vector<WorstSubsurface> bodies;  ///< the named, elastic ones
  std::vector<std::string> rigid;
  /// Per state: step, time, each body's largest von Mises stress, and the sink's file.
  nlohmann::json states = nlohmann::json::array();
};

/// Called with each state's field; returns the file it wrote ("" for none).
using SubsurfaceSink = std::function<std::string(const SubsurfaceState&, const SubsurfaceRun&)>;

/// A sink writing each state's field into `series` (subsurface_<step>.vti, subsurface.pvd) when
/// the depths are evenly spaced (an image's third axis); `series` must outlive the sink.
SubsurfaceSink subsurface_file_sink(output::SubsurfaceSnapshots& series);

/// The largest contact half-width of `fields` on `grid` (3-D: the larger of x and y), 0 without contact.
double contact_half_width(const Grid& grid, const output::StaticFields& fields);

/// The depths of c.subsurface, by default 32 from 0 to 1.5 x the largest contact half-width over
/// `states`.
std::vector<double> subsurface_series_depths(const Case& c, const Grid& grid, const std::vector<SubsurfaceState>& states);

/// The field of every state of `states` at subsurface_series_depths, the worst over them, `sink`
/// called per state.
SubsurfaceSeries subsurface_series(const Case& c, const Grid& grid, const std::vector<SubsurfaceState>& states,
                                   const SubsurfaceSink& sink = nullptr);

/// summary.json's "subsurface" of a run in time: per body the keys of subsurface_json (the worst
/// over the run) with step, step_tresca, step_orthogonal (`timed`: also time, time_tresca,
/// time_orthogonal), "depths", and "states" (step, time, max_von_mises per body, file).
nlohmann::json subsurface_series_json(const SubsurfaceSeries& series, int dimension, bool timed);

/// The worst over the run on stdout.
void print_subsurface_series(const SubsurfaceSeries& series, bool timed);

}  // namespace dc::runs

#pragma once
// The output folder of a run: created, locked (output_lock.hpp) and cleared of an earlier run's
// result files before anything is solved.
#include <memory>
#include <string>

#include "case_model.hpp"
#include "output_lock.hpp"

namespace dc::output {

/// Whether `name` is one of the result files a run writes (summary.json, fields[_k].csv,
/// timeseries[_k].csv, compare.json, the plots and their data, body.vtu, body_<k>.vtu,
/// body.pvd, subsurface.vti, subsurface_<k>.vti and subsurface.pvd, the planes' CSV): a new run removes these from its folder first. A run kind that writes new file
/// names lists them here.
bool is_result_file(const std::string& name);

/// An output folder ready for a run, locked while `lock` lives.
struct OutputFolder {
  std::string dir;
  std::unique_ptr<OutputFolderLock> lock;
};

/// `--out` when given, else output.dir, else out/<name>; created if missing and locked
/// (output_lock.hpp: a folder another run holds is refused at once). Throws InputError naming
/// the key (--out, output.dir, name) when it cannot be created, locked or written into, before
/// anything is solved; removes the temporaries of a killed run (output_files.hpp) and the
/// result files of an earlier run (only those). `out_key` names the folder given (Python: out).
OutputFolder open_output_folder(const Case& c, const std::string& cli_out, const std::string& out_key = "--out");

}  // namespace dc::output

// dyncontact: the command line. Subcommand wiring and error handling only; each subcommand
// lives in its own file (solve_command.cpp, compare_command.cpp, validate_command.cpp,
// example_command.cpp, table_command.cpp); main() is in main.cpp.
#include "program.hpp"

#include <csignal>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "blas_threads.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "interrupt.hpp"
#include "interrupt_handler.hpp"
#include "output_files.hpp"
#ifdef DYNCONTACT_WITH_MPI
#include "table_ranks_mpi.hpp"
#endif

#ifndef DYNCONTACT_VERSION
#define DYNCONTACT_VERSION "unknown"
#endif

namespace dc::cli {

int run_program(int argc, char** argv) {
  int exit_code = runs::kExitOk;
  runs::install_interrupt_handlers();
#ifdef DYNCONTACT_WITH_MPI
  table::use_mpi_ranks();  // `mpirun -n N dyncontact ...`: a table's lines, a sweep's runs over the ranks
#endif
  // A file-size limit (ulimit -f) makes a write fail with EFBIG, an OutputError like a full disk,
  // instead of killing the program mid-file.
  std::signal(SIGXFSZ, SIG_IGN);
  dc::use_one_blas_thread();
  try {
    CLI::App app{
        "dyncontact: frictional contact between an elastic body and an elastic half-space "
        "(after Spector & Batra), solved as convex programs with certified results.\n"
        "Start with `dyncontact example --list`, save one with `dyncontact example hertz-sphere > case.json`, "
        "then `dyncontact solve case.json`.",
        "dyncontact"};
    app.set_version_flag("--version", std::string("dyncontact ") + DYNCONTACT_VERSION);
    app.require_subcommand(1);
    app.footer(
        "Exit codes: 0 success, 2 bad input (also: the output folder is in use by another run, or the case needs "
        "more memory than the machine has), 3 solver did not converge, 4 internal error, 5 an output file could "
        "not be written (disk full, permissions; the message names the file).");
    add_solve_command(app, exit_code);
    add_compare_command(app, exit_code);
    add_validate_command(app, exit_code);
    add_example_command(app, exit_code);
    add_table_command(app, exit_code);
    // A first argument that is neither an option nor a subcommand: say so (CLI11 would only
    // say that a subcommand is required).
    auto is_subcommand = [&app](const std::string& name) {
      try {
        return app.get_subcommand(name) != nullptr;
      } catch (const CLI::OptionNotFound&) {
        return false;
      }
    };
    if (argc > 1 && argv[1][0] != '-' && !is_subcommand(argv[1])) {
      std::cerr << "error: unknown subcommand '" << argv[1]
                << "' (expected solve, compare, validate, example or table; see dyncontact --help)\n";
      return runs::kExitBadInput;
    }
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      const int code = app.exit(e);
      return code == 0 ? runs::kExitOk : runs::kExitBadInput;
    }
    return exit_code;
  } catch (const dc::Interrupted&) {  // a subcommand that had nothing finished to write
    std::cout.flush();
    std::cerr << "interrupted\n";
    return runs::interrupted_exit_code();
  } catch (const dc::InputError& e) {
    std::cout.flush();
    std::cerr << "error: " << e.what() << '\n';
    return runs::kExitBadInput;
  } catch (const dc::OutputError& e) {
    std::cout.flush();
    std::cerr << "error: " << e.what() << '\n';  // the file, then why
    return runs::kExitOutput;
  } catch (const std::bad_alloc&) {
    std::cout.flush();
    std::cerr << "error: the case needs more memory than this machine has: reduce grid.nx and grid.ny (or "
                 "fe_body.elements, or a coarser fe_body.contact_size, for a finite-element body)\n";
    return runs::kExitBadInput;
  } catch (const dc::SolverFailure& e) {
    std::cout.flush();
    std::cerr << "error: solver: " << e.what() << '\n';
    return runs::kExitUnconverged;
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "error: internal: " << e.what() << '\n';
    return runs::kExitInternal;
  } catch (...) {
    std::cerr << "error: internal: unknown exception\n";
    return runs::kExitInternal;
  }
}

}  // namespace dc::cli

#pragma once
// The subcommands of `dyncontact`. Each add_*_command registers its options and a callback
// that runs the command and stores its exit code in `exit_code`; errors are thrown
// (InputError: bad input, exit 2; anything else: internal, exit 4) and handled in main().
namespace CLI {
class App;
class Validator;
}

namespace dc::cli {

void add_solve_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
void add_validate_command(CLI::App& app, int& exit_code);
void add_example_command(CLI::App& app, int& exit_code);
void add_table_command(CLI::App& app, int& exit_code);

/// --out: a folder name, not empty.
const CLI::Validator& non_empty_folder();

}  // namespace dc::cli

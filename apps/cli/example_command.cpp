// dyncontact example [NAME] [--list]
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "examples.hpp"
#include "output_files.hpp"

namespace dc::cli {
namespace {

struct ExampleArgs {
  std::string name;
  bool list = false;
};

int run_example(const ExampleArgs& args) {
  if (args.list || args.name.empty()) {
    for (const auto& e : runs::bundled_examples()) std::printf("%-20s %s\n", e.name, e.summary);
    return runs::kExitOk;
  }
  const runs::BundledExample* e = runs::find_example(args.name);
  if (!e) throw InputError("example", "unknown example '" + args.name + "' (see `dyncontact example --list`)");
  // Usually redirected into a file (`> case.json`): a full disk is an output error, not a success.
  if (std::fputs(e->text, stdout) < 0 || std::fflush(stdout) != 0) {
    const int err = errno;
    throw OutputError("standard output", std::string("cannot write the example: ") + std::strerror(err), err);
  }
  return runs::kExitOk;
}

}  // namespace

void add_example_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ExampleArgs>();
  CLI::App* sub = app.add_subcommand("example", "Print a bundled example case (JSON) to start from");
  sub->footer(
      "Prints one of the bundled case files to standard output; save it and edit it to set up your own case: "
      "`dyncontact example hertz-sphere > my-case.json`, then `dyncontact solve my-case.json`. "
      "`--list` (or no name) lists the examples with a one-line description. The same files are in examples/.");
  sub->add_option("name", args->name, "example name (see --list)");
  sub->add_flag("-l,--list", args->list, "list the bundled examples");
  sub->callback([args, &exit_code] { exit_code = run_example(*args); });
}

}  // namespace dc::cli

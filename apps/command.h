#pragma once

#include <functional>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "lrsvo/graph/registry.h"

namespace lrsvo::cli {

// A subcommand of the `lrsvo` program, in Registry<Command> by its name ("run",
// "bench bal"). Each lives in its own command_*.cpp and registers itself with
// LRSVO_REGISTER_COMMAND, a static initialiser, which the program's own objects
// always keep; main() adds them all in name order. `add` creates the CLI11
// subcommand (options, callback) on the given app.
struct Command {
  std::function<void(CLI::App&)> add;
};

}  // namespace lrsvo::cli

#define LRSVO_REGISTER_COMMAND(name, function)                                                                \
  static const ::lrsvo::Registrar<::lrsvo::cli::Command> LRSVO_CONCAT(lrsvo_command_registrar_, __COUNTER__)( \
      name, [] { return std::make_unique<::lrsvo::cli::Command>(::lrsvo::cli::Command{function}); })

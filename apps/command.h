#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lrsvo::cli {

// A subcommand of the `lrsvo` program. Each lives in its own command_*.cpp
// and registers itself with LRSVO_REGISTER_COMMAND; main() adds them all.
// `add` creates the CLI11 subcommand (options, callback) on the given app.
struct Command {
  std::string name;
  std::function<void(CLI::App&)> add;
};

std::vector<Command>& commands();

struct CommandRegistrar {
  CommandRegistrar(std::string name, std::function<void(CLI::App&)> add) {
    commands().push_back({std::move(name), std::move(add)});
  }
};

}  // namespace lrsvo::cli

#define LRSVO_REGISTER_COMMAND(name, function) \
  static const ::lrsvo::cli::CommandRegistrar lrsvo_command_registrar(name, function)

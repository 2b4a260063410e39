#include <iostream>

#include <CLI/CLI.hpp>

#include "apps/command.h"
#include "apps/failure_report.h"
#include "apps/stop_on_signal.h"

int main(int argc, char** argv) {
  CLI::App app{"lrsvo: long-range stereo visual odometry on a g2o-style graph optimiser"};
  app.require_subcommand(1);
  for (const auto& [name, entry] : lrsvo::Registry<lrsvo::cli::Command>::instance().entries())
    entry.factory()->add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const lrsvo::cli::Interrupted& stopped) {
    std::cerr << "lrsvo: stopped by signal " << stopped.signal << " with the outputs written\n";
    return 128 + stopped.signal;
  } catch (...) {
    const auto chosen = app.get_subcommands();
    std::cerr << lrsvo::cli::failureLine(chosen.empty() ? "" : chosen.front()->get_name(), std::current_exception())
              << '\n';
    return 1;
  }
  return 0;
}

#include "lrsvo/eval/plotting.h"

#include <cstdlib>

namespace lrsvo {
namespace {

std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

bool canImportMatplotlib(const std::string& python) {
  const std::string command = shellQuoted(python) + " -c 'import matplotlib' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

}  // namespace

std::string plottingPython() {
  static const std::string found = [] {
    std::vector<std::string> candidates;
    if (const char* python = std::getenv("LRSVO_PYTHON")) candidates.emplace_back(python);
    candidates.emplace_back("python3");
    candidates.emplace_back("/usr/bin/python3");
    for (const std::string& candidate : candidates)
      if (canImportMatplotlib(candidate)) return candidate;
    return std::string();
  }();
  return found;
}

std::filesystem::path plottingScript(const std::string& name) {
  std::vector<std::filesystem::path> places;
  if (const char* dir = std::getenv("LRSVO_PLOTS_DIR")) places.emplace_back(dir);
  std::error_code noProgram;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", noProgram);
  if (!noProgram) places.emplace_back(program.parent_path().parent_path() / "share" / "lrsvo" / "plots");
  places.emplace_back(std::filesystem::path(LRSVO_INSTALL_DATADIR) / "plots");
  for (const auto& place : places) {
    const std::filesystem::path script = place / (name + ".py");
    if (std::filesystem::exists(script)) return script;
  }
  return {};
}

std::string plottingCommand(const std::string& python, const std::filesystem::path& script,
                            const std::vector<std::string>& arguments) {
  std::string command = shellQuoted(python) + " " + shellQuoted(script.string());
  for (const std::string& argument : arguments) command.append(" ").append(shellQuoted(argument));
  return command;
}

}  // namespace lrsvo

#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lrsvo {

// The Python interpreter that plots: $LRSVO_PYTHON, else `python3` on the
// PATH, else /usr/bin/python3 (Debian's, where python3-matplotlib installs),
// the first that can import matplotlib. Empty when none can.
std::string plottingPython();

// The plotting script eval/plots/<name>.py: looked for in $LRSVO_PLOTS_DIR,
// then in share/lrsvo/plots beside the running program's bin/ (the build tree
// holds a copy there, as the install tree does), then under the install
// prefix. Empty when none has it.
std::filesystem::path plottingScript(const std::string& name);

// The shell command that runs `script` with `arguments` under `python`, every word quoted.
std::string plottingCommand(const std::string& python, const std::filesystem::path& script,
                            const std::vector<std::string>& arguments);

}  // namespace lrsvo

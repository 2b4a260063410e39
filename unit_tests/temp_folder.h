#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace lrsvo::test {

// A path in the temporary directory, unique to this name and test process,
// with nothing there: a test writes its files under it.
inline std::filesystem::path freshFolder(const std::string& name) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("lrsvo_test_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(folder);
  return folder;
}

}  // namespace lrsvo::test

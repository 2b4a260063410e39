#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lrsvo {

// One study's outcome in `lrsvo study all`: its report lies in outDir/<name>/
// (summary.json, CSVs, <name>.png) unless it failed.
struct StudyOutcome {
  std::string name;
  std::string figure;
  std::string title;
  double wallSeconds = 0.0;  // the whole run, writing and plotting included
  std::string error;         // empty when the study succeeded
};

// Writes outDir/index.html: a self-contained page (no scripts) with a first
// table of every check of every study (ours beside the paper's), then one
// section per study with its figure, plot, checks, settings, files and run
// time, all read back from outDir/<name>/summary.json. A failed study, or one
// whose summary cannot be read, shows as failed with the reason. Returns the path.
std::filesystem::path writeStudyIndex(const std::filesystem::path& outDir, const std::vector<StudyOutcome>& outcomes);

}  // namespace lrsvo

#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lrsvo/eval/plotting.h"

#include "lrsvo/graph/registry.h"

namespace lrsvo {

// Settings every study takes (`lrsvo study NAME --seed --trials --out`).
struct StudyOptions {
  std::uint64_t seed = 1;
  int trials = 0;                // 0: the paper's count for this study
  std::filesystem::path outDir;  // created if missing
  bool plot = true;              // run the study's matplotlib script
  // Called as work advances: fraction done in [0, 1] and a short message.
  std::function<void(double, const std::string&)> progress = [](double, const std::string&) {};

  int trialsOr(int paperDefault) const { return trials > 0 ? trials : paperDefault; }
};

// A figure's headline number with the paper's beside it (docs/method.md, the paper's numbers to reproduce).
// `paper` is NaN where the paper gives no number; `note` says how to read it.
struct StudyCheck {
  std::string name;
  double ours = 0.0;
  double paper = 0.0;
  std::string unit;
  std::string note;
};

// A CSV table a study writes: a header and rows of numbers or text.
class StudyTable {
 public:
  StudyTable(std::string fileName, std::vector<std::string> columns);
  void addRow(const std::vector<double>& values);
  void addRow(const std::vector<std::string>& values);
  const std::string& fileName() const { return fileName_; }
  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }

 private:
  std::string fileName_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

// What a study produces. `write` puts in outDir: every table as CSV,
// summary.json ({"study", "figure", "title", "settings", "checks": [{"name",
// "ours", "paper", "unit", "note"}], "files", "seconds"}) and, when plotting,
// <study>.png from eval/plots/<study>.py; `print` shows the checks as a table.
// Without a script or a Python that has matplotlib, the plot is skipped and
// summary.json says why under "plot"; a script that fails throws lrsvo::Error.
class StudyReport {
 public:
  StudyReport(std::string study, std::string figure, std::string title);
  StudyTable& addTable(const std::string& fileName, std::vector<std::string> columns);
  void addSetting(const std::string& key, const std::string& value);
  void addSetting(const std::string& key, double value);
  void addCheck(StudyCheck check);
  void setSeconds(double seconds) { seconds_ = seconds; }

  void write(const StudyOptions& options) const;
  void print(std::ostream& out) const;

  const std::string& study() const { return study_; }
  const std::vector<StudyCheck>& checks() const { return checks_; }
  const std::vector<std::unique_ptr<StudyTable>>& tables() const { return tables_; }

 private:
  std::string study_, figure_, title_;
  std::vector<std::pair<std::string, std::string>> settings_;
  std::vector<StudyCheck> checks_;
  std::vector<std::unique_ptr<StudyTable>> tables_;
  double seconds_ = 0.0;
};

// A study, in Registry<Study> by name. The paper's are defined one per file
// of eval/studies/ and added on the registry's first use; a program adds its
// own with Registry<Study>::instance().add(...).
struct Study {
  std::string name;    // e.g. "range-bias"
  std::string figure;  // e.g. "Fig. 6"
  std::string title;
  int paperTrials = 0;  // the paper's trial count (0: not a Monte Carlo study)
  std::function<StudyReport(const StudyOptions&)> run;

  static void addBuiltins(Registry<Study>& registry);
};

std::vector<Study> studies();              // every registered study, by name
Study findStudy(const std::string& name);  // throws lrsvo::Error listing the known names

}  // namespace lrsvo

#include "lrsvo/eval/study.h"

#include "lrsvo/eval/studies/paper_studies.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lrsvo/eval/plotting.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

std::string formatNumber(double value) {
  if (std::isnan(value)) return "";
  std::ostringstream out;
  out << std::setprecision(10) << value;
  return out.str();
}

// CSV field: quoted when it holds a separator, quote or line break.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

nlohmann::json numberOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

}  // namespace

StudyTable::StudyTable(std::string fileName, std::vector<std::string> columns)
    : fileName_(std::move(fileName)), columns_(std::move(columns)) {}

void StudyTable::addRow(const std::vector<double>& values) {
  std::vector<std::string> row;
  row.reserve(values.size());
  for (double v : values) row.push_back(formatNumber(v));
  addRow(row);
}

void StudyTable::addRow(const std::vector<std::string>& values) {
  if (values.size() != columns_.size())
    throw Error("study table " + fileName_ + ": a row of " + std::to_string(values.size()) + " values for " +
                std::to_string(columns_.size()) + " columns");
  rows_.push_back(values);
}

StudyReport::StudyReport(std::string study, std::string figure, std::string title)
    : study_(std::move(study)), figure_(std::move(figure)), title_(std::move(title)) {}

StudyTable& StudyReport::addTable(const std::string& fileName, std::vector<std::string> columns) {
  tables_.push_back(std::make_unique<StudyTable>(fileName, std::move(columns)));
  return *tables_.back();
}

void StudyReport::addSetting(const std::string& key, const std::string& value) { settings_.emplace_back(key, value); }
void StudyReport::addSetting(const std::string& key, double value) { settings_.emplace_back(key, formatNumber(value)); }
void StudyReport::addCheck(StudyCheck check) { checks_.push_back(std::move(check)); }

void StudyReport::write(const StudyOptions& options) const {
  if (options.outDir.empty()) throw Error("study " + study_ + ": no output folder");
  std::filesystem::create_directories(options.outDir);
  nlohmann::json files = nlohmann::json::array();
  for (const auto& table : tables_) {
    std::ofstream out(options.outDir / table->fileName());
    if (!out) throw Error("study " + study_ + ": cannot write " + (options.outDir / table->fileName()).string());
    for (std::size_t i = 0; i < table->columns().size(); ++i) out << (i ? "," : "") << csvField(table->columns()[i]);
    out << '\n';
    for (const auto& row : table->rows()) {
      for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csvField(row[i]);
      out << '\n';
    }
    files.push_back(table->fileName());
  }

  std::string plotNote;
  if (options.plot) {
    const std::filesystem::path script = plottingScript(study_);
    const std::string python = script.empty() ? std::string() : plottingPython();
    if (script.empty()) {
      plotNote = "no plotting script eval/plots/" + study_ + ".py";
    } else if (python.empty()) {
      plotNote = "plot skipped: no Python with matplotlib (install python3-matplotlib or set LRSVO_PYTHON)";
    } else {
      const std::string command = plottingCommand(python, script, {options.outDir.string()});
      if (std::system(command.c_str()) != 0) throw Error("study " + study_ + ": the plot failed: " + command);
      files.push_back(study_ + ".png");
    }
  }

  nlohmann::json summary;
  summary["study"] = study_;
  summary["figure"] = figure_;
  summary["title"] = title_;
  summary["seed"] = options.seed;
  nlohmann::json settings = nlohmann::json::object();
  for (const auto& [key, value] : settings_) settings[key] = value;
  summary["settings"] = settings;
  nlohmann::json checks = nlohmann::json::array();
  for (const StudyCheck& c : checks_)
    checks.push_back({{"name", c.name},
                      {"ours", numberOrNull(c.ours)},
                      {"paper", numberOrNull(c.paper)},
                      {"unit", c.unit},
                      {"note", c.note}});
  summary["checks"] = checks;
  summary["files"] = files;
  summary["seconds"] = seconds_;
  if (!plotNote.empty()) summary["plot"] = plotNote;
  std::ofstream out(options.outDir / "summary.json");
  if (!out) throw Error("study " + study_ + ": cannot write summary.json in " + options.outDir.string());
  out << summary.dump(2) << '\n';
}

void StudyReport::print(std::ostream& out) const {
  out << study_ << " (" << figure_ << "): " << title_ << '\n';
  std::size_t nameWidth = 5, unitWidth = 4;
  for (const StudyCheck& c : checks_) {
    nameWidth = std::max(nameWidth, c.name.size());
    unitWidth = std::max(unitWidth, c.unit.size());
  }
  char line[512];
  std::snprintf(line, sizeof line, "  %-*s  %14s  %14s  %-*s  %s\n", static_cast<int>(nameWidth), "check", "ours",
                "paper", static_cast<int>(unitWidth), "unit", "note");
  out << line;
  for (const StudyCheck& c : checks_) {
    std::snprintf(line, sizeof line, "  %-*s  %14.4g  %14s  %-*s  %s\n", static_cast<int>(nameWidth), c.name.c_str(),
                  c.ours, std::isnan(c.paper) ? "-" : formatNumber(c.paper).c_str(), static_cast<int>(unitWidth),
                  c.unit.c_str(), c.note.c_str());
    out << line;
  }
  std::snprintf(line, sizeof line, "  (%.1f s)\n", seconds_);
  out << line;
}

void Study::addBuiltins(Registry<Study>& registry) {
  for (Study study : {depthDistributionStudy(), disparityStudy(), epipolarStudy(), initAltitudeStudy(),
                      initScaleStudy(), rangeBiasStudy(), triangulationStudy()}) {
    const std::string name = study.name, title = study.title;
    registry.add(
        name, [study = std::move(study)] { return std::make_unique<Study>(study); }, title);
  }
}

std::vector<Study> studies() {
  std::vector<Study> all;
  for (const auto& [name, entry] : Registry<Study>::instance().entries()) all.push_back(*entry.factory());
  return all;
}

Study findStudy(const std::string& name) {
  const Registry<Study>& registry = Registry<Study>::instance();
  if (!registry.contains(name))
    throw Error("unknown study '" + name + "'; known: " + (registry.entries().empty() ? "(none)" : registry.names()));
  return *registry.create(name);
}

}  // namespace lrsvo

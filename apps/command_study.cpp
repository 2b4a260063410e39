// `lrsvo study`: reruns the paper's studies (eval/studies/) and writes their
// tables, plots and checks beside the paper's numbers.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "lrsvo/eval/study.h"
#include "lrsvo/eval/study_index.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo::cli {
namespace {

struct StudyCommandOptions {
  std::string name;
  std::uint64_t seed = 1;
  int trials = 0;
  std::string out;
  bool noPlot = false;
};

// Progress on stderr: on a terminal one line rewritten at most a few times a
// second; otherwise (a log, CI) one line per step, i.e. per new message.
class ProgressPrinter {
 public:
  explicit ProgressPrinter(std::string study) : study_(std::move(study)), terminal_(isatty(fileno(stderr)) != 0) {}

  void operator()(double fraction, const std::string& message) {
    const bool done = fraction >= 1.0;
    if (terminal_) {
      if (!done && printed_ && sinceLast_.seconds() < 0.25) return;
      std::fprintf(stderr, "\r\033[K[%s] %3.0f%% %s", study_.c_str(), 100.0 * fraction, message.c_str());
      if (done) std::fputc('\n', stderr);
    } else {
      if (message == lastMessage_) return;
      std::fprintf(stderr, "[%s] %3.0f%% %s\n", study_.c_str(), 100.0 * fraction, message.c_str());
    }
    std::fflush(stderr);
    printed_ = true;
    sinceLast_.restart();
    lastMessage_ = message;
  }

 private:
  std::string study_;
  bool terminal_;
  bool printed_ = false;
  Stopwatch sinceLast_;  // since the last line printed
  std::string lastMessage_;
};

StudyOptions studyOptions(const StudyCommandOptions& o, const std::string& name, const std::filesystem::path& outDir) {
  StudyOptions options;
  options.seed = o.seed;
  options.trials = o.trials;
  options.outDir = outDir;
  options.plot = !o.noPlot;
  auto printer = std::make_shared<ProgressPrinter>(name);
  options.progress = [printer](double fraction, const std::string& message) { (*printer)(fraction, message); };
  return options;
}

// Runs one study, writes its report and prints its checks; returns the wall time.
double runOne(const Study& study, const StudyOptions& options) {
  const Stopwatch stopwatch;
  const StudyReport report = study.run(options);
  report.write(options);
  const double seconds = stopwatch.seconds();
  report.print(std::cout);
  std::cout << "  report in " << options.outDir.string() << "/ (summary.json, CSV";
  if (std::filesystem::exists(options.outDir / (study.name + ".png"))) std::cout << ", " << study.name << ".png";
  std::cout << ")\n";
  if (options.plot) {
    std::ifstream in(options.outDir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
    if (summary.is_object() && summary.contains("plot"))
      std::cout << "  " << summary["plot"].get<std::string>() << '\n';
  }
  std::cout.flush();
  return seconds;
}

// The figure's number, for ordering studies as the paper does.
int figureNumber(const Study& study) {
  const std::size_t digit = study.figure.find_first_of("0123456789");
  return digit == std::string::npos ? 1 << 20 : std::stoi(study.figure.substr(digit));
}

std::vector<Study> studiesInFigureOrder() {
  std::vector<Study> ordered = studies();
  std::stable_sort(ordered.begin(), ordered.end(), [](const Study& a, const Study& b) {
    return std::make_pair(figureNumber(a), a.name) < std::make_pair(figureNumber(b), b.name);
  });
  return ordered;
}

void listStudies() {
  std::printf("%-20s %-8s %-14s %s\n", "study", "figure", "paper trials", "title");
  for (const Study& s : studiesInFigureOrder())
    std::printf("%-20s %-8s %-14s %s\n", s.name.c_str(), s.figure.c_str(),
                s.paperTrials > 0 ? std::to_string(s.paperTrials).c_str() : "-", s.title.c_str());
}

void runAll(const StudyCommandOptions& o) {
  const std::filesystem::path outDir =
      o.out.empty() ? std::filesystem::path("lrsvo_studies") : std::filesystem::path(o.out);
  std::vector<StudyOutcome> outcomes;
  std::string failed;
  for (const Study& study : studiesInFigureOrder()) {
    StudyOutcome outcome{study.name, study.figure, study.title, 0.0, ""};
    const Stopwatch stopwatch;
    try {
      outcome.wallSeconds = runOne(study, studyOptions(o, study.name, outDir / study.name));
    } catch (const std::exception& e) {
      outcome.error = e.what();
      outcome.wallSeconds = stopwatch.seconds();
      failed += (failed.empty() ? "" : ", ") + study.name;
      std::cerr << "[" << study.name << "] failed: " << e.what() << '\n';
    }
    std::cout << '\n';
    outcomes.push_back(std::move(outcome));
  }
  const std::filesystem::path index = writeStudyIndex(outDir, outcomes);
  std::cout << "Index of all studies: " << index.string() << '\n';
  if (!failed.empty()) throw Error("these studies failed: " + failed + " (see " + index.string() + ")");
}

void runStudyCommand(const StudyCommandOptions& o) {
  if (o.name == "list") return listStudies();
  if (o.name == "all") return runAll(o);
  const Study study = findStudy(o.name);
  const std::filesystem::path outDir =
      o.out.empty() ? std::filesystem::path("lrsvo_studies") / study.name : std::filesystem::path(o.out);
  try {
    runOne(study, studyOptions(o, study.name, outDir));
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("study " + study.name + ": " + e.what());
  }
}

std::string studyFooter() {
  std::string text = "Studies (lrsvo study list):\n";
  for (const Study& s : studiesInFigureOrder()) {
    text += "  " + s.name + std::string(s.name.size() < 20 ? 20 - s.name.size() : 1, ' ') + s.figure + ": " + s.title;
    if (s.paperTrials > 0) text += " (" + std::to_string(s.paperTrials) + " trials per case by default)";
    text += '\n';
  }
  text +=
      "\nEach study runs with the paper's settings by default, writes CSV tables, summary.json (settings, checks: "
      "ours beside the paper's) and a PNG plot (python3 with matplotlib; LRSVO_PYTHON picks the interpreter), and "
      "prints its checks. `all` runs every study into DIR/<name>/ and writes DIR/index.html; it exits with status 1 "
      "when a study fails, after running the others. docs/studies.md explains the settings and every gap to the "
      "paper.";
  return text;
}

void addStudyCommand(CLI::App& app) {
  auto options = std::make_shared<StudyCommandOptions>();
  CLI::App* command = app.add_subcommand("study", "Rerun one of the paper's studies (figures 1, 4-7, ...), or all");
  command->footer(studyFooter());
  command->add_option("name", options->name, "A study's name, `list` to list them, or `all` to run every one")
      ->required();
  command->add_option("--seed", options->seed, "Seed of every random draw (Monte Carlo studies)")
      ->capture_default_str();
  command->add_option("--trials", options->trials, "Trials per case (0: the paper's count)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--out", options->out,
                      "Output folder (default: lrsvo_studies/NAME for one study, lrsvo_studies for all)");
  command->add_flag("--no-plot", options->noPlot, "Write tables and summary.json only, no PNG");
  command->callback([options] { runStudyCommand(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("study", addStudyCommand);

}  // namespace lrsvo::cli

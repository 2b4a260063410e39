#include "apps/bench/bench_common.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <CLI/CLI.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo::bench {

CLI::App& benchSubcommand(CLI::App& app) {
  const auto existing = app.get_subcommands([](CLI::App* sub) { return sub->get_name() == "bench"; });
  if (!existing.empty()) return *existing.front();
  CLI::App* bench = app.add_subcommand("bench", "Compare this project's solvers with Ceres on generated problems");
  bench->require_subcommand(1);
  return *bench;
}

namespace {

// A "Vm...:" line of /proc/self/status in megabytes, if there is one.
std::optional<double> procStatusMegabytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;  // kB
  return std::nullopt;
}

}  // namespace

SolveMemory::SolveMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);  // freed memory the C library kept would otherwise be reused unseen
#endif
  std::ofstream clear("/proc/self/clear_refs");
  if (!(clear << "5" << std::flush)) return;  // the peak cannot be reset: no figure
  residentBefore_ = procStatusMegabytes("VmRSS");
}

std::optional<double> SolveMemory::addedMegabytes() const {
  const std::optional<double> peak = procStatusMegabytes("VmHWM");
  if (!residentBefore_ || !peak) return std::nullopt;
  return std::max(0.0, *peak - *residentBefore_);
}

SolveResult resultFromSummary(const SolverSummary& summary, const Stopwatch& stopwatch) {
  SolveResult result;
  result.iterations = summary.iterationCount();
  result.initialCost = summary.initialCost;
  result.finalCost = summary.finalCost;
  result.totalSeconds = stopwatch.seconds();
  result.cpuSeconds = stopwatch.cpuSeconds();
  result.termination = terminationName(summary.termination);
  result.setupSeconds = summary.setupSeconds;
  result.linearizeSeconds = summary.linearizeSeconds;
  result.linearSolveSeconds = summary.schurSeconds + summary.factorizeSeconds;
  result.schurSeconds = summary.schurSeconds;
  result.costSeconds = summary.costSeconds;
  result.ordering = summary.ordering;
  if (!summary.ordering.empty()) result.factorizationFlops = summary.factorizationFlops;
  return result;
}

SolveResult medianRun(int repeat, const std::function<SolveResult()>& solve,
                      const std::function<void(int run)>& progress) {
  if (repeat < 1) throw Error("bench: the repeat count must be at least 1");
  std::vector<SolveResult> runs;
  for (int run = 1; run <= repeat; ++run) {
    if (progress) progress(run);
    runs.push_back(solve());
  }
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.totalSeconds < b.totalSeconds; });
  return runs[(runs.size() - 1) / 2];
}

void computeRatios(std::vector<BenchRow>& rows, std::size_t first) {
  for (std::size_t i = first; i < rows.size(); ++i) {
    BenchRow& ours = rows[i];
    if (ours.reference) continue;
    double fastest = std::numeric_limits<double>::infinity();
    for (std::size_t j = first; j < rows.size(); ++j) {
      const BenchRow& reference = rows[j];
      if (!reference.reference || reference.threads != ours.threads) continue;
      fastest = std::min(fastest, reference.result.totalSeconds);
      if (reference.family != ours.family) continue;
      ours.ratioTime = ours.result.totalSeconds / reference.result.totalSeconds;
      ours.ratioCost = ours.result.finalCost / reference.result.finalCost;
    }
    if (std::isfinite(fastest)) ours.ratioTimeFastest = ours.result.totalSeconds / fastest;
  }
}

namespace {

nlohmann::ordered_json optionalNumber(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json rowsToJson(const std::vector<BenchRow>& rows) {
  auto list = nlohmann::ordered_json::array();
  for (const BenchRow& row : rows) {
    const SolveResult& r = row.result;
    nlohmann::ordered_json object;
    object["problem"] = row.problem;
    for (const auto& [key, value] : row.problemFields.items()) object[key] = value;
    object["solver"] = row.solver;
    object["threads"] = row.threads;
    object["iterations"] = r.iterations;
    object["time_per_iteration_s"] = r.secondsPerIteration();
    object["total_time_s"] = r.totalSeconds;
    object["cpu_time_s"] = r.cpuSeconds;
    object["initial_cost"] = r.initialCost;
    object["final_cost"] = r.finalCost;
    object["ratio_time"] = optionalNumber(row.ratioTime);
    object["ratio_cost"] = optionalNumber(row.ratioCost);
    object["ratio_time_fastest"] = optionalNumber(row.ratioTimeFastest);
    object["termination"] = r.termination;
    object["family"] = row.family;
    object["jacobians"] = row.jacobians;
    object["setup_s"] = r.setupSeconds;
    object["linearize_s"] = r.linearizeSeconds;
    object["linear_solve_s"] = r.linearSolveSeconds;
    object["schur_s"] = optionalNumber(r.schurSeconds);
    object["cost_s"] = r.costSeconds;
    object["solve_mb"] = optionalNumber(r.solveMegabytes);
    object["ordering"] = r.ordering.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.ordering);
    object["factorization_flops"] = optionalNumber(r.factorizationFlops);
    list.push_back(std::move(object));
  }
  return list;
}

void writeJson(const std::vector<BenchRow>& rows, const std::string& path) { writeJsonValue(rowsToJson(rows), path); }

void writeJsonValue(const nlohmann::ordered_json& value, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error("bench: cannot open '" + path + "' for writing");
  out << value.dump(2) << '\n';
  if (!out) throw Error("bench: cannot write '" + path + "'");
}

namespace {

bool looksNumeric(const std::string& cell) {
  if (cell == "-") return true;
  const std::size_t first = cell.find_first_not_of("+-");
  return first != std::string::npos && (std::isdigit(static_cast<unsigned char>(cell[first])) || cell[first] == '.');
}

}  // namespace

void TextTable::print(std::ostream& out) const {
  const std::size_t columns = header_.size();
  std::vector<std::size_t> widths(columns, 0);
  std::vector<bool> rightAligned(columns, false);  // numeric columns, judged by their first cell
  const auto firstRow = std::find_if(rows_.begin(), rows_.end(), [](const auto& row) { return !row.empty(); });
  for (std::size_t c = 0; c < columns; ++c) {
    widths[c] = header_[c].size();
    for (const auto& row : rows_)
      if (c < row.size()) widths[c] = std::max(widths[c], row[c].size());
    rightAligned[c] = firstRow != rows_.end() && c < firstRow->size() && looksNumeric((*firstRow)[c]);
  }
  std::size_t lineWidth = 0;
  for (std::size_t w : widths) lineWidth += w + 2;
  const std::string rule(lineWidth - 2, '-');

  auto printCells = [&](const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t c = 0; c < columns; ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      const std::string padding(widths[c] - cell.size(), ' ');
      line += rightAligned[c] ? padding + cell : cell + padding;
      if (c + 1 < columns) line += "  ";
    }
    out << line.substr(0, line.find_last_not_of(' ') + 1) << '\n';
  };
  printCells(header_);
  out << rule << '\n';
  for (const auto& row : rows_) {
    if (row.empty())
      out << rule << '\n';
    else
      printCells(row);
  }
}

std::string format(const char* pattern, ...) {
  char buffer[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  return buffer;
}

std::string formatRatio(const std::optional<double>& ratio) { return ratio ? format("%.3f", *ratio) : "-"; }

}  // namespace lrsvo::bench

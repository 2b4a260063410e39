#include "lrsvo/eval/study_index.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A summary.json value: a number in 4 significant digits, null as a dash, text as it is.
std::string shown(const nlohmann::json& value) {
  if (value.is_null()) return "&ndash;";
  if (value.is_number()) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", value.get<double>());
    return text;
  }
  return escaped(value.is_string() ? value.get<std::string>() : value.dump());
}

// A study's summary.json, or null (with the reason in `problem`) when it cannot be read.
nlohmann::json readSummary(const std::filesystem::path& file, std::string& problem) {
  std::ifstream in(file);
  if (!in) {
    problem = "no " + file.string();
    return nullptr;
  }
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    problem = file.string() + " is not valid JSON: " + e.what();
    return nullptr;
  }
}

std::string secondsText(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 2em; max-width: 75em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #eee; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
.failed { color: #a00; font-weight: bold; }
img { max-width: 100%; border: 1px solid #ddd; }
section { border-top: 2px solid #ccc; margin-top: 2em; }
</style>
)";

}  // namespace

std::filesystem::path writeStudyIndex(const std::filesystem::path& outDir, const std::vector<StudyOutcome>& outcomes) {
  std::vector<nlohmann::json> summaries;
  std::vector<std::string> problems;
  for (const StudyOutcome& outcome : outcomes) {
    std::string problem = outcome.error;
    nlohmann::json summary = problem.empty() ? readSummary(outDir / outcome.name / "summary.json", problem) : nullptr;
    summaries.push_back(std::move(summary));
    problems.push_back(problem);
  }

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<title>lrsvo: the paper's studies</title>\n"
       << kStyle << "</head>\n<body>\n<h1>lrsvo: the paper's studies</h1>\n"
       << "<p>Warren, Corke and Upcroft, &ldquo;Long-range stereo visual odometry for extended altitude flight of "
          "unmanned aerial vehicles&rdquo; (IJRR 2016), rerun by <code>lrsvo study all</code>. Each check sets our "
          "number beside the paper's (a dash: the paper gives none).</p>\n";

  html << "<h2>All checks</h2>\n<table>\n<tr><th>study</th><th>check</th><th>ours</th><th>paper</th><th>unit</th>"
          "<th>note</th></tr>\n";
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const std::string link = "<a href=\"#" + escaped(outcomes[i].name) + "\">" + escaped(outcomes[i].name) + "</a>";
    if (!problems[i].empty()) {
      html << "<tr><td>" << link << "</td><td colspan=\"5\" class=\"failed\">failed: " << escaped(problems[i])
           << "</td></tr>\n";
      continue;
    }
    for (const auto& check : summaries[i].value("checks", nlohmann::json::array()))
      html << "<tr><td>" << link << "</td><td>" << shown(check.value("name", "")) << "</td><td class=\"number\">"
           << shown(check.value("ours", nlohmann::json())) << "</td><td class=\"number\">"
           << shown(check.value("paper", nlohmann::json())) << "</td><td>" << shown(check.value("unit", ""))
           << "</td><td>" << shown(check.value("note", "")) << "</td></tr>\n";
  }
  html << "</table>\n";

  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const StudyOutcome& outcome = outcomes[i];
    const nlohmann::json& summary = summaries[i];
    html << "<section id=\"" << escaped(outcome.name) << "\">\n<h2>" << escaped(outcome.figure) << ": "
         << escaped(outcome.title) << " <small>(<code>" << escaped(outcome.name) << "</code>)</small></h2>\n";
    if (!problems[i].empty()) {
      html << "<p class=\"failed\">Failed after " << secondsText(outcome.wallSeconds) << ": " << escaped(problems[i])
           << "</p>\n</section>\n";
      continue;
    }
    html << "<p>Run time " << secondsText(summary.value("seconds", 0.0)) << " (" << secondsText(outcome.wallSeconds)
         << " with writing and plotting), seed " << shown(summary.value("seed", nlohmann::json())) << ".</p>\n";
    const std::string png = outcome.name + ".png";
    if (std::filesystem::exists(outDir / outcome.name / png))
      html << "<p><img src=\"" << escaped(outcome.name + "/" + png) << "\" alt=\"" << escaped(outcome.title)
           << "\"></p>\n";
    else
      html << "<p>No plot: " << shown(summary.value("plot", "plotting was off")) << "</p>\n";

    html << "<h3>Checks</h3>\n<table>\n<tr><th>check</th><th>ours</th><th>paper</th><th>unit</th><th>note</th></tr>\n";
    for (const auto& check : summary.value("checks", nlohmann::json::array()))
      html << "<tr><td>" << shown(check.value("name", "")) << "</td><td class=\"number\">"
           << shown(check.value("ours", nlohmann::json())) << "</td><td class=\"number\">"
           << shown(check.value("paper", nlohmann::json())) << "</td><td>" << shown(check.value("unit", ""))
           << "</td><td>" << shown(check.value("note", "")) << "</td></tr>\n";
    html << "</table>\n<h3>Settings</h3>\n<table>\n";
    const nlohmann::json settings = summary.value("settings", nlohmann::json::object());
    for (const auto& [key, value] : settings.items())
      html << "<tr><th>" << escaped(key) << "</th><td>" << shown(value) << "</td></tr>\n";
    html << "</table>\n<p>Files:";
    for (const auto& file : summary.value("files", nlohmann::json::array())) {
      const std::string name = file.is_string() ? file.get<std::string>() : file.dump();
      html << " <a href=\"" << escaped(outcome.name + "/" + name) << "\">" << escaped(name) << "</a>";
    }
    html << " <a href=\"" << escaped(outcome.name + "/summary.json") << "\">summary.json</a></p>\n</section>\n";
  }
  html << "</body>\n</html>\n";

  std::filesystem::create_directories(outDir);
  const std::filesystem::path index = outDir / "index.html";
  std::ofstream out(index);
  if (!out) throw Error("study index: cannot write " + index.string());
  out << html.str();
  return index;
}

}  // namespace lrsvo

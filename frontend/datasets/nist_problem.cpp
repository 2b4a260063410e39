#include "lrsvo/frontend/datasets/nist_problem.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

bool startsWith(const std::string& line, const std::string& prefix) { return line.rfind(prefix, 0) == 0; }

class Parser {
 public:
  Parser(const std::string& text, const std::string& sourceName) : lines_(splitLines(text)), source_(sourceName) {}

  NistProblem parse() {
    NistProblem problem;
    problem.name = valueAfter("Dataset Name:", "the dataset name");
    parseParameters(problem);
    const std::string rss = "Residual Sum of Squares:", observationCount = "Number of Observations:";
    problem.certifiedResidualSumOfSquares = number(valueAfter(rss, "the residual sum of squares"), lineOf(rss));
    const int observations =
        count(valueAfter(observationCount, "the number of observations"), lineOf(observationCount));
    parseData(problem, observations);
    return problem;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const { throw ParseError(source_, line + 1, message); }

  // Index of the first line holding `label`; -1 when none.
  int lineOf(const std::string& label) const {
    for (std::size_t i = 0; i < lines_.size(); ++i)
      if (lines_[i].find(label) != std::string::npos) return static_cast<int>(i);
    return -1;
  }

  std::string valueAfter(const std::string& label, const std::string& what) const {
    const int line = lineOf(label);
    if (line < 0) fail(static_cast<int>(lines_.size()) - 1, "no " + what + " ('" + label + "')");
    const std::vector<std::string> words = tokens(lines_[line].substr(lines_[line].find(label) + label.size()));
    if (words.empty()) fail(line, "'" + label + "' has no value");
    return words.front();
  }

  double number(const std::string& word, int line) const {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      fail(line, "'" + word + "' is not a number");
    }
    if (used != word.size() || !std::isfinite(value)) fail(line, "'" + word + "' is not a finite number");
    return value;
  }

  int count(const std::string& word, int line) const {
    const double value = number(word, line);
    constexpr double kLargest = 1e7;  // far above any NIST problem, and an int
    if (value < 1 || value > kLargest || value != std::floor(value))
      fail(line, "'" + word + "' is not a count from 1 to 10^7");
    return static_cast<int>(value);
  }

  // "  b1 =   start1   start2   certified   deviation", one line per parameter after the "Start 1" header.
  void parseParameters(NistProblem& problem) const {
    const int header = lineOf("Start 1");
    if (header < 0) fail(static_cast<int>(lines_.size()) - 1, "no starting values ('Start 1')");
    std::vector<std::array<double, 3>> rows;
    for (int i = header + 1; i < static_cast<int>(lines_.size()); ++i) {
      const std::vector<std::string> words = tokens(lines_[i]);
      if (words.empty() && rows.empty()) continue;
      if (words.empty() || words[0] != "b" + std::to_string(rows.size() + 1)) break;
      if (words.size() != 6 || words[1] != "=")
        fail(i, "a parameter line needs 'bK = start1 start2 certified deviation'");
      rows.push_back({number(words[2], i), number(words[3], i), number(words[4], i)});
    }
    if (rows.empty()) fail(header, "no parameter lines after the starting values' header");
    const int n = static_cast<int>(rows.size());
    problem.starts = {Eigen::VectorXd(n), Eigen::VectorXd(n)};
    problem.certified.resize(n);
    for (int k = 0; k < n; ++k) {
      problem.starts[0][k] = rows[k][0];
      problem.starts[1][k] = rows[k][1];
      problem.certified[k] = rows[k][2];
    }
  }

  // The last "Data:" line names the columns (y, then the predictors); the rows follow.
  void parseData(NistProblem& problem, int observations) const {
    int header = -1;
    for (std::size_t i = 0; i < lines_.size(); ++i)
      if (startsWith(lines_[i], "Data:")) header = static_cast<int>(i);
    if (header < 0) fail(static_cast<int>(lines_.size()) - 1, "no data section ('Data:')");
    const std::vector<std::string> columns = tokens(lines_[header].substr(5));
    if (columns.size() < 2 || columns[0] != "y") fail(header, "the data header must name y and the predictors");
    const int predictors = static_cast<int>(columns.size()) - 1;
    problem.response.resize(observations);
    problem.predictors.resize(observations, predictors);
    int row = 0;
    for (int i = header + 1; i < static_cast<int>(lines_.size()); ++i) {
      const std::vector<std::string> words = tokens(lines_[i]);
      if (words.empty()) continue;
      if (row == observations)
        fail(i, "more data rows than the " + std::to_string(observations) + " observations stated");
      if (static_cast<int>(words.size()) != predictors + 1)
        fail(i, "a data row needs " + std::to_string(predictors + 1) + " numbers");
      problem.response[row] = number(words[0], i);
      for (int p = 0; p < predictors; ++p) problem.predictors(row, p) = number(words[p + 1], i);
      ++row;
    }
    if (row != observations)
      fail(static_cast<int>(lines_.size()) - 1,
           "the data ends after " + std::to_string(row) + " of " + std::to_string(observations) + " observations");
  }

  std::vector<std::string> lines_;
  std::string source_;
};

}  // namespace

NistProblem parseNistProblem(const std::string& text, const std::string& sourceName) {
  return Parser(text, sourceName).parse();
}

NistProblem readNistProblem(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open NIST problem file " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return parseNistProblem(text.str(), path);
}

}  // namespace lrsvo

// The one line the program prints when a failure ends a subcommand: every kind
// of exception the libraries and their dependencies throw is named, on one
// line, with the subcommand.
#include <filesystem>
#include <new>
#include <stdexcept>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "apps/failure_report.h"
#include "lrsvo/graph/error.h"

namespace lrsvo::cli {
namespace {

template <typename Throw>
std::string lineFor(const std::string& command, Throw&& thrower) {
  try {
    thrower();
  } catch (...) {
    return failureLine(command, std::current_exception());
  }
  ADD_FAILURE() << "nothing was thrown";
  return {};
}

void expectOneLine(const std::string& line, const std::string& start, const std::string& part) {
  EXPECT_EQ(line.rfind(start, 0), 0u) << line;
  EXPECT_NE(line.find(part), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
}

TEST(FailureReport, NamesEveryKindOfFailureOnOneLine) {
  expectOneLine(lineFor("run", [] { throw Error("euroc: no mav0 in /data/x"); }),
                "lrsvo run: error: ", "no mav0 in /data/x");
  expectOneLine(lineFor("run",
                        [] {
                          cv::Mat sum;
                          cv::add(cv::Mat(2, 2, CV_8U), cv::Mat(3, 3, CV_8U), sum);
                        }),
                "lrsvo run: OpenCV error: ", "");
  expectOneLine(lineFor("eval",
                        [] {
                          throw std::filesystem::filesystem_error("cannot create directories",
                                                                  std::filesystem::path("/dev/null/out"),
                                                                  std::make_error_code(std::errc::not_a_directory));
                        }),
                "lrsvo eval: file system error: ", "/dev/null/out");
  expectOneLine(lineFor("bal",
                        [] {
                          const nlohmann::json parsed = nlohmann::json::parse("{ broken");
                          ADD_FAILURE() << parsed.dump();
                        }),
                "lrsvo bal: JSON error: ", "parse");
  expectOneLine(lineFor("bench", [] { throw std::bad_alloc(); }), "lrsvo bench: out of memory", "");
  expectOneLine(lineFor("study", [] { throw std::runtime_error("first line\nsecond line\n"); }),
                "lrsvo study: error: ", "first line second line");
  expectOneLine(lineFor("", [] { throw 42; }), "lrsvo: unknown error", "");
}

}  // namespace
}  // namespace lrsvo::cli

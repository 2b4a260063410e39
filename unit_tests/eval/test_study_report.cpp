#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "lrsvo/eval/study.h"
#include "lrsvo/eval/study_index.h"
#include "lrsvo/graph/error.h"
#include "unit_tests/temp_folder.h"

namespace lrsvo {
namespace {

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

using test::freshFolder;

StudyReport sampleReport() {
  StudyReport report("sample", "Fig. 0", "A sample study");
  StudyTable& table = report.addTable("values.csv", {"name", "value, in m"});
  table.addRow(std::vector<std::string>{"plain", "1.5"});
  table.addRow(std::vector<std::string>{"say \"hi\"", "line\nbreak"});
  StudyTable& numbers = report.addTable("numbers.csv", {"a", "b"});
  numbers.addRow({0.25, std::nan("")});
  report.addSetting("trials", 100.0);
  report.addSetting("rig", "two cameras");
  report.addCheck({"with paper", 2.5, 3.0, "m", "note"});
  report.addCheck({"without paper", 1.0, std::nan(""), "", "qualitative"});
  report.setSeconds(0.5);
  return report;
}

TEST(StudyReport, WritesCsvWithHeaderAndQuoting) {
  StudyOptions options;
  options.outDir = freshFolder("report_csv");
  options.plot = false;
  sampleReport().write(options);
  EXPECT_EQ(readText(options.outDir / "values.csv"),
            "name,\"value, in m\"\nplain,1.5\n\"say \"\"hi\"\"\",\"line\nbreak\"\n");
  EXPECT_EQ(readText(options.outDir / "numbers.csv"), "a,b\n0.25,\n");  // NaN is an empty cell
  std::filesystem::remove_all(options.outDir);
}

TEST(StudyReport, SummaryHasChecksWithNanAsNull) {
  StudyOptions options;
  options.outDir = freshFolder("report_summary");
  options.plot = false;
  options.seed = 7;
  sampleReport().write(options);
  const nlohmann::json summary = nlohmann::json::parse(readText(options.outDir / "summary.json"));
  EXPECT_EQ(summary["study"], "sample");
  EXPECT_EQ(summary["seed"], 7);
  EXPECT_EQ(summary["settings"]["trials"], "100");
  ASSERT_EQ(summary["checks"].size(), 2u);
  EXPECT_EQ(summary["checks"][0]["paper"], 3.0);
  EXPECT_TRUE(summary["checks"][1]["paper"].is_null());
  EXPECT_EQ(summary["checks"][1]["ours"], 1.0);
  EXPECT_EQ(summary["files"], nlohmann::json({"values.csv", "numbers.csv"}));
  std::filesystem::remove_all(options.outDir);
}

TEST(StudyReport, RowOfWrongLengthThrows) {
  StudyTable table("t.csv", {"a", "b", "c"});
  EXPECT_THROW(table.addRow({1.0, 2.0}), Error);
  EXPECT_THROW(table.addRow(std::vector<std::string>{"1", "2", "3", "4"}), Error);
  EXPECT_NO_THROW(table.addRow({1.0, 2.0, 3.0}));
}

TEST(StudyReport, WriteWithoutFolderThrows) { EXPECT_THROW(sampleReport().write(StudyOptions{}), Error); }

TEST(StudyRegistry, UnknownNameThrowsWithTheList) {
  try {
    findStudy("no-such-study");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no-such-study"), std::string::npos);
    for (const char* known : {"disparity", "epipolar", "triangulation", "range-bias", "depth-distribution"})
      EXPECT_NE(message.find(known), std::string::npos) << known << " missing from: " << message;
  }
}

TEST(StudyIndex, ShowsChecksOfSucceededAndReasonOfFailedStudies) {
  const std::filesystem::path folder = freshFolder("index");
  StudyOptions options;
  options.outDir = folder / "sample";
  options.plot = false;
  sampleReport().write(options);
  const std::filesystem::path index =
      writeStudyIndex(folder, {{"sample", "Fig. 0", "A sample study", 0.6, ""},
                               {"broken", "Fig. 9", "A <broken> study", 0.1, "it threw & stopped"}});
  const std::string html = readText(index);
  EXPECT_NE(html.find("<td>with paper</td><td class=\"number\">2.5</td><td class=\"number\">3</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>without paper</td><td class=\"number\">1</td><td class=\"number\">&ndash;</td>"),
            std::string::npos);
  EXPECT_NE(html.find("failed: it threw &amp; stopped"), std::string::npos);
  EXPECT_NE(html.find("A &lt;broken&gt; study"), std::string::npos);
  EXPECT_NE(html.find("<th>rig</th><td>two cameras</td>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST(StudyIndex, StudyWithoutSummaryShowsAsFailed) {
  const std::filesystem::path folder = freshFolder("index_missing");
  const std::string html = readText(writeStudyIndex(folder, {{"ghost", "Fig. 1", "Never written", 0.0, ""}}));
  EXPECT_NE(html.find("failed: no "), std::string::npos);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace lrsvo

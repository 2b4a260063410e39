#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/eval/study.h"
#include "unit_tests/temp_folder.h"

namespace lrsvo {
namespace {

constexpr const char* kGeometryStudies[] = {"disparity", "epipolar", "triangulation", "range-bias",
                                            "depth-distribution"};

StudyOptions tinyRun(std::uint64_t seed = 3) {
  StudyOptions options;
  options.seed = seed;
  options.trials = 300;
  options.plot = false;
  return options;
}

TEST(StudyRuns, TinyRunOfEachGeometryStudyGivesFiniteChecks) {
  for (const char* name : kGeometryStudies) {
    const Study& study = findStudy(name);
    double lastFraction = -1.0;
    StudyOptions options = tinyRun();
    options.progress = [&](double fraction, const std::string&) {
      EXPECT_GE(fraction, lastFraction) << name;
      EXPECT_LE(fraction, 1.0) << name;
      lastFraction = fraction;
    };
    const StudyReport report = study.run(options);
    EXPECT_EQ(report.study(), name);
    EXPECT_DOUBLE_EQ(lastFraction, 1.0) << name;
    ASSERT_FALSE(report.checks().empty()) << name;
    for (const StudyCheck& check : report.checks())
      EXPECT_TRUE(std::isfinite(check.ours)) << name << ": " << check.name;
    EXPECT_FALSE(report.tables().empty()) << name;
  }
}

TEST(StudyRuns, MonteCarloStudiesAreSeeded) {
  for (const char* name : {"range-bias", "depth-distribution"}) {
    const Study& study = findStudy(name);
    const StudyReport a = study.run(tinyRun(3)), b = study.run(tinyRun(3)), c = study.run(tinyRun(4));
    ASSERT_EQ(a.checks().size(), c.checks().size());
    bool anyDifferent = false;
    for (std::size_t i = 0; i < a.checks().size(); ++i) {
      EXPECT_EQ(a.checks()[i].ours, b.checks()[i].ours) << name << ": " << a.checks()[i].name;
      anyDifferent = anyDifferent || a.checks()[i].ours != c.checks()[i].ours;
    }
    EXPECT_TRUE(anyDifferent) << name << ": another seed gave the same numbers";
  }
}

TEST(StudyRuns, GeometryChecksMatchHandComputedValues) {
  // disparity: f b / Z at f 1200 px and 1280 px; epipolar: f tan(0.2 deg) about y;
  // triangulation: Z - b (Z cos t - b sin t) / (b cos t + Z sin t) for t = 0.2 deg about x.
  const double t = 0.2 * M_PI / 180.0, b = 0.7, z = 100.0;
  EXPECT_NEAR(findStudy("disparity").run(tinyRun()).checks()[0].ours, 8.4, 1e-12);
  EXPECT_NEAR(findStudy("disparity").run(tinyRun()).checks()[1].ours, 8.96, 1e-12);
  const StudyReport epipolar = findStudy("epipolar").run(tinyRun());
  EXPECT_NE(epipolar.checks()[0].name.find("about y"), std::string::npos);  // the most sensitive axis
  EXPECT_NEAR(epipolar.checks()[0].ours, 1280.0 * std::tan(t), 1e-9);
  EXPECT_NEAR(epipolar.checks()[1].ours, 860.0 * std::tan(t), 1e-9);
  const double depth = b * (z * std::cos(t) - b * std::sin(t)) / (b * std::cos(t) + z * std::sin(t));
  EXPECT_NEAR(findStudy("triangulation").run(tinyRun()).checks()[0].ours, z - depth, 1e-5);
}

using test::freshFolder;

TEST(StudyRuns, PlotScriptsWriteAPngForEachStudy) {
  if (plottingPython().empty()) GTEST_SKIP() << "no python3 with matplotlib";
  const std::filesystem::path folder = freshFolder("plots");
  for (const char* name : kGeometryStudies) {
    StudyOptions options = tinyRun();
    options.trials = 50;
    options.plot = true;
    options.outDir = folder / name;
    findStudy(name).run(options).write(options);
    const std::filesystem::path png = options.outDir / (std::string(name) + ".png");
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    EXPECT_GT(std::filesystem::file_size(png), 10000u) << png;
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace lrsvo

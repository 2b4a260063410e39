#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "eval/odometry_run.h"
#include "eval/run_report.h"
#include "frontend/euroc_reader.h"
#include "sim/scenario.h"
#include "sim/sim_frame_source.h"
#include "unit_tests/shared_data.h"

namespace lrsvo {
namespace {

using test::kEuroc;

// Real EuRoC frames of a nearly still vehicle (~2 mm in 4.7 s): too little
// parallax to initialise. The odometry must neither crash nor invent motion:
// every frame it poses lies within centimetres of the first.
TEST(OdometryRunEuroc, NearlyStillSequenceInventsNoMotion) {
  EurocSource source(kEuroc);
  const std::filesystem::path out = std::filesystem::path(testing::TempDir()) / "lrsvo_run_euroc";
  std::filesystem::remove_all(out);
  RunOptions options;
  options.outDir = out;
  options.frontEnd.stereo.minDepth_m = 0.5;  // a room, not a flight at 30-120 m
  const RunResult run = runOdometry(source, options);
  EXPECT_EQ(run.totals.frames, source.frameCount());
  EXPECT_EQ(static_cast<int>(run.segments.size()), run.totals.frames);
  EXPECT_GT(run.totals.frontEnd.tracked, 0);
  for (const Eigen::Isometry3d& pose : run.trajectory.worldFromCamera)
    EXPECT_LT((pose.translation() - run.trajectory.worldFromCamera.front().translation()).norm(), 0.05);

  const RunReport report = writeRunReport(out, run, source.groundTruth(), false);
  EXPECT_EQ(report.metrics["frames"], run.totals.frames);
  EXPECT_EQ(report.metrics["frames_tracked"], run.totals.tracked);
  for (const char* file : {"trajectory.tum", "frames.csv", "extrinsics.csv", "rig.json", "metrics.json"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  // frames.csv: a header and one line per frame.
  std::ifstream frames(out / "frames.csv");
  int lines = 0;
  for (std::string line; std::getline(frames, line);) ++lines;
  EXPECT_EQ(lines, run.totals.frames + 1);
}

// The whole pipeline on a short rendered flight (the demo's world and rig
// flex, 640x480 to keep it quick, at 50 m so that the disparity, 11.7 px, is
// the full-size camera's at 100 m): every frame gets a pose once the
// initialisation has its 28 frames, and the end point stays within 5 % of
// the distance flown.
TEST(OdometryRunSim, ShortRenderedFlightIsTrackedToTheEnd) {
  SimScenario scenario = demoScenario();
  scenario.rig = paperRig(0.7, 640, 480);
  scenario.flight.altitude_m = 50.0;
  SimFrameSource source(scenario);
  RunOptions options;
  options.maxFrames = 75;
  const RunResult run = runOdometry(source, options);
  EXPECT_EQ(run.totals.frames, 75);
  EXPECT_EQ(run.totals.tracked, 75);
  EXPECT_EQ(run.totals.segments, 1);
  const RunReport report = writeRunReport({}, run, source.groundTruth(), false);
  ASSERT_TRUE(report.metrics.contains("final_position_error_m"));
  const double distance = report.metrics["distance_m"].get<double>();
  EXPECT_NEAR(distance, 74.0 / 30.0 * 20.0, 0.5);
  EXPECT_LT(report.metrics["final_position_error_m"].get<double>(), 0.05 * distance);
}

// The sim source renders a frame's secondary image only when the odometry
// asks for it (keyframes, initialisation): the run is the same, bit for bit,
// as on frames rendered whole, with most secondary images never rendered.
TEST(OdometryRunSim, DeferredSecondaryImagesGiveTheRunOfWholeFrames) {
  SimScenario scenario = demoScenario();
  scenario.rig = paperRig(0.7, 640, 480);
  scenario.flight.altitude_m = 50.0;
  constexpr int kFrames = 40;
  SimFrameSource deferredSource(scenario);
  const SimFrameSource wholeSource(scenario);
  const RunOptions options;
  OdometryPipeline deferred(deferredSource, options), whole(wholeSource, options);
  int rendered = 0;
  for (int i = 0; i < kFrames; ++i) {
    const std::optional<StereoFrame> frame = deferredSource.next();
    ASSERT_TRUE(frame.has_value());
    deferred.process(*frame);
    rendered += frame->deferred->made(1);
    whole.process(wholeSource.render(i));
  }
  const RunResult a = deferred.finish(), b = whole.finish();
  EXPECT_EQ(a.totals.tracked, kFrames);
  EXPECT_GT(rendered, 0);
  EXPECT_LT(rendered, kFrames * 3 / 4);
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (std::size_t i = 0; i < a.trajectory.size(); ++i)
    EXPECT_TRUE(a.trajectory.worldFromCamera[i].matrix() == b.trajectory.worldFromCamera[i].matrix()) << "frame " << i;
}

}  // namespace
}  // namespace lrsvo

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lrsvo/eval/run_report.h"
#include "lrsvo/frontend/datasets/euroc_reader.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/sim/feature_simulator.h"
#include "lrsvo/sim/scenario.h"
#include "lrsvo/sim/sim_frame_source.h"
#include "unit_tests/shared_data.h"

namespace lrsvo {
namespace {

using test::kEuroc;

// Real EuRoC frames of a nearly still vehicle (~2 mm in 4.7 s), 1-5 m from a
// room's walls: no parallax for a monocular start, but depths of 10-50
// baselines that stereo sees well, so the odometry starts from the first
// frame's stereo structure. At least 90 % of the frames are posed, and none
// farther than 1 cm from the first: the 2 mm moved plus a pose's noise (170
// points at ~3 m, 0.5 px at f = 458 px: about 3 m x 0.5 / 458 / sqrt(170),
// 0.1 mm per axis, times a few for the geometry), with room to spare; an
// invented motion or a drifting scale shows as centimetres.
TEST(OdometryRunEuroc, NearlyStillSequenceIsPosedWithoutInventedMotion) {
  EurocSource source(kEuroc);
  const std::filesystem::path out = std::filesystem::path(testing::TempDir()) / "lrsvo_run_euroc";
  std::filesystem::remove_all(out);
  RunOptions options;
  options.outDir = out;
  options.frontEnd.stereo.minDepth_m = 0.5;  // a room, not a flight at 30-120 m
  const RunResult run = runOdometry(source, options);
  EXPECT_EQ(run.totals.frames, source.frameCount());
  EXPECT_EQ(static_cast<int>(run.segments.size()), run.totals.frames);
  EXPECT_GE(run.totals.tracked, 0.9 * run.totals.frames);
  EXPECT_EQ(run.totals.segments, 1);
  EXPECT_EQ(run.segments.front(), 0);  // posed from the first frame
  for (const Eigen::Isometry3d& pose : run.trajectory.worldFromCamera)
    EXPECT_LT((pose.translation() - run.trajectory.worldFromCamera.front().translation()).norm(), 0.01);

  const RunReport report = writeRunReport(out, run, source.groundTruth(), false);
  EXPECT_EQ(report.metrics["frames"], run.totals.frames);
  EXPECT_EQ(report.metrics["frames_tracked"], run.totals.tracked);
  for (const char* file : {"trajectory.tum", "frames.csv", "extrinsics.csv", "rig.json", "metrics.json"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  // frames.csv: a header and one line per frame; the first frame's says the segment started from stereo.
  std::ifstream frames(out / "frames.csv");
  int lines = 0;
  std::string first;
  for (std::string line; std::getline(frames, line);)
    if (++lines == 2) first = line;
  EXPECT_EQ(lines, run.totals.frames + 1);
  EXPECT_NE(first.find(",stereo start at a median depth of "), std::string::npos) << first;
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

// Columns of a run's CSV file (the header skipped), as numbers (empty, or a
// word such as frames.csv's status: 0).
std::vector<std::vector<double>> csvRows(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<double>> table;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::vector<double> row;
    for (std::string field; std::getline(fields, field, ',');) {
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      row.push_back(end == field.c_str() ? 0.0 : value);
    }
    table.push_back(row);
  }
  return table;
}

// A rig rolled about its baseline by 9.5 mrad (inside its 10 mrad box) puts
// the matches 7.9 px off the calibrated epipolar lines, outside a 4 px band.
// The initialisation searches a band widened to the box and estimates S; from
// then on the run centres the band on the estimate, and the keyframes keep
// their stereo matches.
TEST(OdometryRunSim, StereoBandFollowsTheEstimatedExtrinsic) {
  SimScenario scenario = demoScenario();
  scenario.rig = paperRig(0.7, 640, 480);
  scenario.flight.altitude_m = 50.0;
  scenario.deformation.drift.setZero();
  scenario.deformation.offset[3] = 0.0095;
  SimFrameSource source(scenario);
  const std::filesystem::path out = std::filesystem::path(testing::TempDir()) / "lrsvo_run_rolled_rig";
  std::filesystem::remove_all(out);
  RunOptions options;
  options.frontEnd.stereo.bandWidth_px = 4.0;
  options.maxFrames = 75;
  options.outDir = out;
  const RunResult run = runOdometry(source, options);
  EXPECT_EQ(run.totals.tracked, 75);
  double features = 0.0, matched = 0.0;
  for (const std::vector<double>& row : csvRows(out / "frames.csv"))
    if (row[0] >= 40 && row[3] == 1.0) {  // keyframes after the initialisation
      features += row[5];
      matched += row[8];
    }
  ASSERT_GT(features, 0.0);
  EXPECT_GE(matched, 0.7 * features);
  const std::vector<double> last = csvRows(out / "extrinsics.csv").back();
  EXPECT_NEAR(last[6], 0.0095, 0.002) << "the estimated roll of S";
}

// A run may start part-way through a sequence (RunOptions::firstFrame): its
// outputs number frames as the source does, and pair them with the truth of
// those frames.
TEST(OdometryRunFeatureLevel, StartsPartWayAndNumbersFramesAsTheSource) {
  const SimulatedSequence sequence = simulateSequence(featureSimulationOptions(demoScenario()));
  GroundTruth truth;
  for (std::size_t i = 0; i < sequence.trueCameraFromWorld.size(); ++i)
    truth.poses.push_back({sequence.frames[i].time_s, sequence.trueCameraFromWorld[i].inverse()});
  truth.extrinsics = sequence.trueExtrinsics;
  const std::filesystem::path out = std::filesystem::path(testing::TempDir()) / "lrsvo_run_part_way";
  std::filesystem::remove_all(out);
  RunOptions options;
  options.firstFrame = 300;
  options.maxFrames = 60;
  options.outDir = out;
  const RunResult run = runOdometry(sequence.rig, sequence.frames, truth, {options}).front();
  EXPECT_EQ(run.totals.frames, 60);
  EXPECT_GT(run.totals.tracked, 0);
  EXPECT_DOUBLE_EQ(run.trajectory.times_s.front(), sequence.frames[300].time_s);

  const auto frames = csvRows(out / "frames.csv");
  ASSERT_EQ(frames.size(), 60u);
  EXPECT_EQ(frames.front()[0], 300.0);
  EXPECT_EQ(frames.back()[0], 359.0);
  const auto extrinsics = csvRows(out / "extrinsics.csv");
  ASSERT_FALSE(extrinsics.empty());
  for (const std::vector<double>& row : extrinsics) {
    const std::size_t frame = static_cast<std::size_t>(row[0]);
    ASSERT_GE(frame, 300u);
    EXPECT_NEAR(row[1], sequence.frames[frame].time_s, 1e-3);  // as written, to 6 digits
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(row[9 + i], truth.extrinsics[frame][0][i], 1e-6) << "frame " << frame;
  }
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

// The stresses a scenario can bring: gusts (attitude steps) in the flight,
// and what the camera link does to the frames (exposure jumps, blank, corrupt
// and dropped frames).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "lrsvo/frontend/features/frame_check.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/sim/scenario.h"
#include "lrsvo/sim/sim_frame_source.h"

namespace lrsvo {
namespace {

TEST(SimGust, StepsTheAttitudeWithinItsRiseHoldsAndReturns) {
  FlightOptions flight;
  flight.frameRate_hz = 10.0;
  flight.legs = {{FlightLeg::Kind::Straight, 100.0}};
  const std::vector<FlightPose> still = simulateFlight(flight);
  flight.gusts = {{1.0, Eigen::Vector3d(0.2, 0.0, 0.0), 0.1, 1.0}};
  const std::vector<FlightPose> gusty = simulateFlight(flight);
  ASSERT_EQ(still.size(), gusty.size());
  auto rollBetween = [&](int frame) {
    return Eigen::AngleAxisd(still[frame].cameraFromWorld.linear() * gusty[frame].cameraFromWorld.linear().transpose())
        .angle();
  };
  EXPECT_NEAR(rollBetween(10), 0.0, 1e-12);  // t = 1.0: the step starts
  EXPECT_NEAR(rollBetween(11), 0.2, 1e-12);  // one frame later: all of it
  EXPECT_NEAR(rollBetween(20), 0.2, 1e-12);  // held
  EXPECT_NEAR(rollBetween(22), 0.0, 1e-12);  // back after hold + 2 rises
  // A gust turns the aircraft; it does not move it.
  const Eigen::Vector3d stillCentre = still[11].cameraFromWorld.inverse().translation();
  const Eigen::Vector3d gustyCentre = gusty[11].cameraFromWorld.inverse().translation();
  EXPECT_LT((stillCentre - gustyCentre).norm(), 1e-9) << stillCentre.transpose() << " / " << gustyCentre.transpose();
  flight.gusts.front().rise_s = -1.0;
  EXPECT_THROW(simulateFlight(flight), Error);
}

SimScenario smallFaultyScenario() {
  SimScenario s = demoScenario();
  s.rig = paperRig(0.7, 320, 240);
  s.flight.legs = {{FlightLeg::Kind::Straight, 10.0}};
  s.faults.exposureJumps = {{3, 1.3}, {5, 1.0}};
  s.faults.blankFrames = {6};
  s.faults.corruptFrames = {8};
  s.faults.droppedFrames = {2, 9};
  return s;
}

TEST(SimFaults, ShapeTheStreamAsTheScenarioSays) {
  const SimScenario scenario = smallFaultyScenario();
  SimFrameSource faulty(scenario);
  SimScenario clean = scenario;
  clean.faults = {};
  SimFrameSource reference(clean);
  ASSERT_EQ(faulty.frameCount(), reference.frameCount() - 2);
  // Delivered frame i is flight frame flight[i]: 2 and 9 are dropped.
  const std::vector<int> flight = {0, 1, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15};
  for (int i = 0; i < static_cast<int>(flight.size()) && i < faulty.frameCount(); ++i) {
    const std::optional<StereoFrame> frame = faulty.next();
    const StereoFrame truth = reference.render(flight[i]);
    ASSERT_TRUE(frame.has_value());
    EXPECT_EQ(frame->index, i);
    EXPECT_DOUBLE_EQ(frame->time_s, truth.time_s);
    const std::string defect = frameDefect(*frame, faulty.rig());
    if (flight[i] == 6) {
      EXPECT_NE(defect.find("blank"), std::string::npos) << defect;
    } else if (flight[i] == 8) {
      EXPECT_NE(defect.find("corrupt"), std::string::npos) << defect;
    } else {
      EXPECT_EQ(defect, "") << "frame " << flight[i];
      const double gain = flight[i] == 3 || flight[i] == 4 ? 1.3 : 1.0;
      for (int k = 0; k < 2; ++k) {
        cv::Mat expected;
        truth.images[k].convertTo(expected, CV_8U, gain);
        EXPECT_EQ(cv::norm(frame->image(k), expected, cv::NORM_INF), 0.0) << "frame " << flight[i] << " camera " << k;
      }
    }
  }
  EXPECT_EQ(faulty.groundTruth().poses.size(), static_cast<std::size_t>(faulty.frameCount()));
}

TEST(SimFaults, StressScenarioRoundTripsThroughYaml) {
  const SimScenario s = stressScenario();
  const std::string path = (std::filesystem::temp_directory_path() / "lrsvo_scenario_stress.yaml").string();
  writeScenarioYaml(s, path);
  const SimScenario r = loadScenario(path);
  ASSERT_EQ(r.flight.gusts.size(), s.flight.gusts.size());
  for (std::size_t i = 0; i < s.flight.gusts.size(); ++i) {
    EXPECT_DOUBLE_EQ(r.flight.gusts[i].time_s, s.flight.gusts[i].time_s);
    EXPECT_TRUE(r.flight.gusts[i].size_rad.isApprox(s.flight.gusts[i].size_rad, 1e-15));
    EXPECT_DOUBLE_EQ(r.flight.gusts[i].rise_s, s.flight.gusts[i].rise_s);
    EXPECT_DOUBLE_EQ(r.flight.gusts[i].hold_s, s.flight.gusts[i].hold_s);
  }
  ASSERT_EQ(r.faults.exposureJumps.size(), s.faults.exposureJumps.size());
  for (std::size_t i = 0; i < s.faults.exposureJumps.size(); ++i) {
    EXPECT_EQ(r.faults.exposureJumps[i].frame, s.faults.exposureJumps[i].frame);
    EXPECT_DOUBLE_EQ(r.faults.exposureJumps[i].gain, s.faults.exposureJumps[i].gain);
  }
  EXPECT_EQ(r.faults.blankFrames, s.faults.blankFrames);
  EXPECT_EQ(r.faults.corruptFrames, s.faults.corruptFrames);
  EXPECT_EQ(r.faults.droppedFrames, s.faults.droppedFrames);
  EXPECT_DOUBLE_EQ(r.flight.frameRate_hz, 15.0);
  std::filesystem::remove(path);
}

// Each stress flight the docs point to loads, flies above its terrain, and
// brings what its name says.
TEST(SimFaults, ShippedStressScenariosLoadAndFly) {
  const std::filesystem::path folder = std::filesystem::path(LRSVO_SOURCE_DIR) / "sim" / "scenarios";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const SimScenario scenario = loadScenario(entry.path().string());
    EXPECT_EQ(scenario.name, entry.path().stem().string());
    EXPECT_NO_THROW(SimFrameSource{scenario}) << entry.path();
  }
  EXPECT_GE(files, 7);
  EXPECT_EQ(loadScenario((folder / "gust.yaml").string()).flight.gusts.size(), 2u);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "rate10.yaml").string()).flight.frameRate_hz, 10.0);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "high150.yaml").string()).flight.altitude_m, 150.0);
  EXPECT_EQ(loadScenario((folder / "bad_frames.yaml").string()).faults.droppedFrames.size(), 5u);
  const SimScenario gap = loadScenario((folder / "gap.yaml").string());
  EXPECT_EQ(gap.faults.droppedFrames.size(), 90u);
  EXPECT_EQ(gap.faults.blankFrames.size(), 90u);
  EXPECT_EQ(loadScenario((folder / "strong_gusts.yaml").string()).flight.gusts.size(), 3u);
  const SimScenario low = loadScenario((folder / "low30_10hz.yaml").string());
  EXPECT_DOUBLE_EQ(low.flight.frameRate_hz, 10.0);
  EXPECT_DOUBLE_EQ(low.flight.altitude_m, 30.0);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "low30_30hz.yaml").string()).flight.frameRate_hz, 30.0);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "high150_10hz.yaml").string()).flight.altitude_m, 150.0);
  const SimScenario vga = loadScenario((folder / "sensor_vga.yaml").string());
  EXPECT_EQ(vga.rig.cameras[0].width, 640);
  EXPECT_EQ(vga.rig.cameras[1].height, 480);
  EXPECT_EQ(loadScenario((folder / "sensor_wide.yaml").string()).rig.cameras[0].width, 752);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "sensor_noisy.yaml").string()).render.noiseSigma_grey, 6.0);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "hills.yaml").string()).terrain.relief_m, 30.0);
  EXPECT_DOUBLE_EQ(loadScenario((folder / "fast.yaml").string()).flight.speed_m_s, 35.0);
}

TEST(SimFaults, BadFaultsAreNamed) {
  const std::string path = (std::filesystem::temp_directory_path() / "lrsvo_scenario_bad_faults.yaml").string();
  for (const char* text : {"faults: {exposureJumps: [{frame: 3, gain: -1}]}", "faults: {blankFrames: [1.5]}",
                           "faults: {droppedFrames: [-2]}",
                           "faults: {exposureJumps: [{frame: 5, gain: 1.1}, {frame: 2, "
                           "gain: 1}]}",
                           "faults: {dropped: [3]}", "flight: {gusts: [{time_s: 1, rol_rad: 0.2}]}"}) {
    std::ofstream(path) << "%YAML:1.0\n" << text << "\n";
    try {
      loadScenario(path);
      ADD_FAILURE() << text << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("scenario"), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace lrsvo

#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/frontend/odometry/outlier_threshold.h"

namespace lrsvo::cli {

// The odometry settings a user picks on the command line (`lrsvo run`,
// `lrsvo bench run`), with the library's defaults.
struct OdometrySettings {
  std::string constraint = OdometryOptions{}.constraintMethod;
  bool rigid = false;
  int window = 15;
  int anchors = 5;
  double scaleDrift = 3e-4;
  double extrinsicRate = 1.0;
  double maxKeyframeRate_hz = 1.0 / KeyframePolicyOptions{}.minInterval_s;
  std::string detector = "gftt";
  int features = 300;
  double band_px = 8.0;
  double outlierSigmas = OutlierTestOptions{}.sigmas;
  double minDepth_m = 20.0;
  std::string solver = OdometryOptions{}.solver.name();
  int threads = OdometryOptions{}.solver.threads;
  std::uint64_t seed = 1;
  std::string onBadFrame = "skip";

  void addOptions(CLI::App& command);
  // The odometry and front-end options these settings stand for.
  RunOptions runOptions() const;
};

// "sim:demo", "sim:paper", "sim:FILE.yaml" (rendered on the fly), or a data
// set on disk: "DIR", "euroc:DIR", "kitti:DIR".
std::unique_ptr<FrameSource> openSource(const std::string& spec);

// A `sim:` source simulated at the feature level instead of rendered: the
// same world, flight and flexing rig, observations without images.
struct FeatureLevelFlight {
  std::string name;
  Rig rig;
  std::vector<FrameObservations> frames;
  GroundTruth truth;
};
FeatureLevelFlight simulateFeatureLevel(const std::string& spec);

// One pass of the odometry over a source spec: rendered or read images
// (openSource), or with `featureLevel` the feature-level simulation of a sim:
// source. `onStart` hears the source's name, its frames in this run and its rig
// before the first frame.
struct SourceRun {
  RunResult run;
  GroundTruth truth;
};
SourceRun runSource(const std::string& spec, const RunOptions& options, bool featureLevel,
                    const std::function<void(const std::string& name, int frames, const Rig& rig)>& onStart = {});

// A name for the output folder made from a source spec ("sim:demo" -> "sim_demo").
std::string folderName(const std::string& spec);

}  // namespace lrsvo::cli

#pragma once

#include <deque>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "frontend/frame_estimate.h"
#include "frontend/frame_source.h"
#include "frontend/image_front_end.h"
#include "frontend/odometry_options.h"
#include "frontend/pose_file.h"

namespace lrsvo {

class Odometry;
class RunWriter;

struct RunOptions {
  OdometryOptions odometry;
  ImageFrontEndOptions frontEnd;
  int firstFrame = 0;                // the source's frames before this one are skipped
  int maxFrames = -1;                // < 0: every frame of the source (from firstFrame)
  std::filesystem::path outDir;      // empty: write nothing
  std::ostream* progress = nullptr;  // one updating line: frame, fps, ETA (of the first variant's options)
};

// Sums over a run; the odometry's own time excludes reading or rendering frames.
struct RunTotals {
  int frames = 0;
  int tracked = 0;
  int keyframes = 0;
  int segments = 0;
  double frontEndSeconds = 0.0;  // features, tracking, stereo matching
  double backEndSeconds = 0.0;   // initialisation, pose, triangulation, window adjustment
  double sourceSeconds = 0.0;    // reading or rendering frames (not the odometry's), deferred images included
  FrontEndTimings frontEnd;      // per-stage sums (ms) and counts
  StageTimes backEnd;            // per-stage sums (ms)
  double odometrySeconds() const { return frontEndSeconds + backEndSeconds; }
  double fps() const { return odometrySeconds() > 0.0 ? frames / odometrySeconds() : 0.0; }
};

struct RunResult {
  RunTotals totals;
  Trajectory trajectory;  // base camera, world-from-camera, tracked frames only
  // Per input frame, whether it was tracked and its segment (gaps show as -1).
  std::vector<int> segments;
};

// The image front end and the odometry for one source, fed frame by frame.
// With an output folder, it streams trajectory.tum, extrinsics.csv and
// frames.csv into it as frames are estimated (memory stays flat).
class OdometryPipeline {
 public:
  OdometryPipeline(const FrameSource& source, const RunOptions& options);
  // Without a source: the rig, its lens distortion and what is known of the truth.
  OdometryPipeline(const Rig& rig, const std::vector<LensDistortion>& distortion, const GroundTruth& truth,
                   const RunOptions& options);
  ~OdometryPipeline();
  // Images through the front end, then the odometry.
  void process(const StereoFrame& frame);
  // Observations straight into the odometry (a feature-level simulation: no front end).
  void process(const FrameObservations& observations, const FrontEndTimings& frontEnd = {});
  // Ends the run (frames still buffered for an initialisation stay untracked).
  RunResult finish();
  const RunTotals& totals() const { return result_.totals; }

 private:
  void run(const FrameObservations& observations, const FrontEndTimings& frontEnd,
           const SecondaryObservations& secondary);
  void record(const std::vector<FrameEstimate>& estimates);

  std::unique_ptr<Odometry> odometry_;
  std::unique_ptr<ImageFrontEnd> frontEnd_;
  std::unique_ptr<RunWriter> writer_;
  std::deque<FrontEndTimings> pendingTimings_;  // wait with their frame while the odometry buffers it
  RunResult result_;
};

// How many frames a pass over a source of `sourceFrames` frames (-1: not
// known) takes when it starts at `firstFrame` (>= 0) and stops after
// `maxFrames` (< 0: at the end); -1 when not known.
int framesInRun(int sourceFrames, int firstFrame, int maxFrames);

// Runs one pipeline over a source, or several over the same frames (each
// frame read or rendered once); the source's time is added to every totals.
RunResult runOdometry(FrameSource& source, const RunOptions& options);
std::vector<RunResult> runOdometry(FrameSource& source, const std::vector<RunOptions>& variants);
// The odometry over observations given in advance (a feature-level
// simulation), one variant after the other; fps counts the odometry alone.
std::vector<RunResult> runOdometry(const Rig& rig, const std::vector<FrameObservations>& frames,
                                   const GroundTruth& truth, const std::vector<RunOptions>& variants);

}  // namespace lrsvo

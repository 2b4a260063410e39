#pragma once

#include <atomic>
#include <deque>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/frontend/features/image_front_end.h"
#include "lrsvo/frontend/odometry/frame_estimate.h"
#include "lrsvo/frontend/odometry/odometry_options.h"

namespace lrsvo {

class Odometry;
class RunWriter;

enum class BadFramePolicy { kSkip, kStop };
// Parses "skip" | "stop"; throws lrsvo::Error otherwise.
BadFramePolicy badFramePolicyFromName(const std::string& name);

struct RunOptions {
  OdometryOptions odometry;
  ImageFrontEndOptions frontEnd;
  int firstFrame = 0;            // the source's frames before this one are skipped
  int maxFrames = -1;            // < 0: every frame of the source (from firstFrame)
  std::filesystem::path outDir;  // empty: write nothing
  // One updating line: frame, fps, ETA (of the first variant's options); a
  // line of its own for each bad frame, segment start and relocalisation.
  std::ostream* progress = nullptr;
  // Set (e.g. by a signal handler) to end the run after the current frame, as
  // if the source had ended there: every output is still written whole.
  const std::atomic<bool>* stop = nullptr;
  // A frame whose images cannot be used (unreadable, blank, wrongly sized):
  // kSkip gives it no pose, says why in frames.csv and goes on; kStop ends the
  // run with an lrsvo::Error naming the frame.
  BadFramePolicy onBadFrame = BadFramePolicy::kSkip;
  // Called with every frame's estimate, in frame order, as it is written (bad
  // frames included); a caller's own loop reads its poses here.
  std::function<void(const FrameEstimate&)> onFrame;
};

// Sums over a run; the odometry's own time excludes reading or rendering frames.
struct RunTotals {
  int frames = 0;
  int tracked = 0;
  int keyframes = 0;
  int segments = 0;
  int badFrames = 0;             // frames skipped for unusable images
  int predicted = 0;             // frames posed by the constant-velocity prediction through a loss
  int relocalised = 0;           // frames that took up a lost segment again (FrameEstimate::relocalised)
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
  Trajectory trajectory;  // base camera, world-from-camera, tracked and predicted frames
  // Per input frame, whether it was tracked and its segment (gaps show as -1).
  std::vector<int> segments;
  bool stopped = false;  // RunOptions::stop ended it before the source's end
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
  void skipBadFrame(const StereoFrame& frame, const std::string& defect);
  void record(const std::vector<FrameEstimate>& estimates);
  // Writes the bad frames at the head of pending_ (they wait for the frames before them).
  void recordBadFrames();
  void write(const FrameEstimate& estimate, const FrontEndTimings& timings);
  // On the progress stream, a line of its own for each segment's first pose
  // and each relocalisation, with the frame's note (how the segment started,
  // why tracking was lost).
  void announce(const FrameEstimate& estimate);

  // A frame on its way to the outputs, in frame order: the odometry's frames
  // wait here while it buffers them (with their front-end timings), a bad
  // frame with its estimate, already known.
  struct PendingFrame {
    FrontEndTimings timings;
    std::optional<FrameEstimate> badFrame;
  };

  Rig rig_;
  BadFramePolicy onBadFrame_;
  std::ostream* progress_;
  int firstFrame_;  // the source's number of the odometry's frame 0
  int lastAnnouncedSegment_ = -1;
  std::function<void(const FrameEstimate&)> onFrame_;
  std::unique_ptr<Odometry> odometry_;
  std::unique_ptr<ImageFrontEnd> frontEnd_;
  std::unique_ptr<RunWriter> writer_;
  std::deque<PendingFrame> pending_;
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

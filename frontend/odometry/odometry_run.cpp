#include "lrsvo/frontend/odometry/odometry_run.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include "lrsvo/frontend/features/frame_check.h"
#include "lrsvo/frontend/odometry/odometry.h"
#include "lrsvo/frontend/odometry/run_writer.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

void addTimings(FrontEndTimings& sum, const FrontEndTimings& t) {
  sum.detect_ms += t.detect_ms;
  sum.track_ms += t.track_ms;
  sum.stereo_ms += t.stereo_ms;
  sum.undistort_ms += t.undistort_ms;
  sum.total_ms += t.total_ms;
  sum.tracked += t.tracked;
  sum.added += t.added;
  sum.rejected += t.rejected;
  sum.stereoMatched += t.stereoMatched;
  sum.realigned += t.realigned;
  sum.revived += t.revived;
}

void addTimes(StageTimes& sum, const StageTimes& t) {
  sum.initialize_ms += t.initialize_ms;
  sum.pose_ms += t.pose_ms;
  sum.triangulate_ms += t.triangulate_ms;
  sum.bundle_ms += t.bundle_ms;
}

void showProgress(std::ostream& out, const RunTotals& totals, double wall_s, int frameCount, bool last) {
  char line[160];
  if (frameCount > 0)
    std::snprintf(line, sizeof line, "\rframe %d/%d  tracked %d  odometry %.1f fps  ETA %.0f s   ", totals.frames,
                  frameCount, totals.tracked, totals.fps(), wall_s / totals.frames * (frameCount - totals.frames));
  else
    std::snprintf(line, sizeof line, "\rframe %d  tracked %d  odometry %.1f fps   ", totals.frames, totals.tracked,
                  totals.fps());
  out << line << (last ? "\n" : "") << std::flush;
}

}  // namespace

BadFramePolicy badFramePolicyFromName(const std::string& name) {
  if (name == "skip") return BadFramePolicy::kSkip;
  if (name == "stop") return BadFramePolicy::kStop;
  throw Error("unknown bad-frame policy '" + name + "' (skip | stop)");
}

OdometryPipeline::OdometryPipeline(const FrameSource& source, const RunOptions& options)
    : OdometryPipeline(source.rig(), source.distortion(), source.groundTruth(), options) {}

OdometryPipeline::OdometryPipeline(const Rig& rig, const std::vector<LensDistortion>& distortion,
                                   const GroundTruth& truth, const RunOptions& options)
    : rig_(rig),
      onBadFrame_(options.onBadFrame),
      progress_(options.progress),
      firstFrame_(options.firstFrame),
      onFrame_(options.onFrame),
      odometry_(std::make_unique<Odometry>(rig, options.odometry)),
      frontEnd_(std::make_unique<ImageFrontEnd>(rig, distortion, options.frontEnd)) {
  if (!options.outDir.empty()) writer_ = std::make_unique<RunWriter>(options.outDir, rig, truth, options.firstFrame);
}

OdometryPipeline::~OdometryPipeline() = default;

void OdometryPipeline::process(const StereoFrame& frame) {
  const std::string defect = frameDefect(frame, rig_);
  if (!defect.empty()) return skipBadFrame(frame, defect);
  const Stopwatch start;
  const FrameObservations observations = frontEnd_->track(frame);
  result_.totals.frontEndSeconds += start.seconds();
  // Stereo matching runs only for the frames the odometry keeps; its time is
  // the front end's, and rendering a source's deferred images is the source's.
  double stereoSeconds = 0.0, deferredSeconds = 0.0;
  run(observations, frontEnd_->lastTimings(), [&] {
    const Stopwatch produceStart;
    for (int k = 1; k < frame.cameraCount(); ++k) frame.image(k);
    deferredSeconds = produceStart.seconds();
    const Stopwatch matchStart;
    // Matches are looked for around the S the odometry holds now; before it
    // has one, around the calibration, widened to the rig's bounds.
    if (odometry_->tracking())
      frontEnd_->centreBandsOn(odometry_->window().extrinsicsAt(observations.time_s));
    else
      frontEnd_->centreBandsOnCalibration();
    std::vector<Observation> secondary = frontEnd_->matchAcrossRig();
    stereoSeconds = matchStart.seconds();
    pending_.back().timings = frontEnd_->lastTimings();
    return secondary;
  });
  result_.totals.frontEndSeconds += stereoSeconds;
  result_.totals.backEndSeconds -= stereoSeconds + deferredSeconds;
  result_.totals.sourceSeconds += deferredSeconds;
}

void OdometryPipeline::process(const FrameObservations& observations, const FrontEndTimings& frontEnd) {
  run(observations, frontEnd, {});
}

void OdometryPipeline::run(const FrameObservations& observations, const FrontEndTimings& frontEnd,
                           const SecondaryObservations& secondary) {
  RunTotals& totals = result_.totals;
  pending_.push_back({frontEnd, std::nullopt});

  const Stopwatch start;
  const std::vector<FrameEstimate> estimates = odometry_->process(observations, secondary);
  frontEnd_->dropTracks(odometry_->takeRejectedTracks());
  totals.backEndSeconds += start.seconds();
  ++totals.frames;
  record(estimates);
}

void OdometryPipeline::skipBadFrame(const StereoFrame& frame, const std::string& defect) {
  if (onBadFrame_ == BadFramePolicy::kStop)
    throw Error("frame " + std::to_string(frame.index) + ": " + defect + " (--on-bad-frame skip goes on without it)");
  FrameEstimate estimate;
  estimate.frame = odometry_->skipFrame();
  estimate.time_s = frame.time_s;
  estimate.badFrame = true;
  estimate.note = defect;
  pending_.push_back({{}, std::move(estimate)});
  ++result_.totals.frames;
  ++result_.totals.badFrames;
  if (progress_) *progress_ << "\nframe " << frame.index << " skipped: " << defect << '\n' << std::flush;
  recordBadFrames();
}

RunResult OdometryPipeline::finish() {
  record(odometry_->finish());
  recordBadFrames();
  writer_.reset();  // flushes and closes the files
  return std::move(result_);
}

void OdometryPipeline::record(const std::vector<FrameEstimate>& estimates) {
  for (const FrameEstimate& estimate : estimates) {
    recordBadFrames();
    if (pending_.empty()) throw Error("odometry pipeline: an estimate for a frame never processed");
    const FrontEndTimings timings = pending_.front().timings;
    pending_.pop_front();
    write(estimate, timings);
  }
}

void OdometryPipeline::recordBadFrames() {
  while (!pending_.empty() && pending_.front().badFrame) {
    write(*pending_.front().badFrame, pending_.front().timings);
    pending_.pop_front();
  }
}

void OdometryPipeline::write(const FrameEstimate& estimate, const FrontEndTimings& timings) {
  RunTotals& totals = result_.totals;
  addTimings(totals.frontEnd, timings);
  addTimes(totals.backEnd, estimate.times);
  totals.tracked += estimate.tracked;
  totals.predicted += estimate.predicted;
  totals.relocalised += estimate.relocalised;
  totals.keyframes += estimate.keyframe;
  totals.segments = std::max(totals.segments, estimate.segment + 1);
  result_.segments.push_back(estimate.tracked ? estimate.segment : -1);
  if (estimate.tracked || estimate.predicted)
    result_.trajectory.add(estimate.time_s, estimate.cameraFromWorld.inverse());
  if (writer_) writer_->write(estimate, timings);
  if (onFrame_) onFrame_(estimate);
  if (progress_) announce(estimate);
}

void OdometryPipeline::announce(const FrameEstimate& estimate) {
  const bool startsSegment = estimate.tracked && estimate.segment > lastAnnouncedSegment_;
  if (!startsSegment && !estimate.relocalised) return;
  lastAnnouncedSegment_ = std::max(lastAnnouncedSegment_, estimate.segment);
  *progress_ << "\nframe " << firstFrame_ + estimate.frame << ": " << estimate.note << '\n' << std::flush;
}

int framesInRun(int sourceFrames, int firstFrame, int maxFrames) {
  if (firstFrame < 0) throw Error("the first frame must be >= 0, got " + std::to_string(firstFrame));
  int count = sourceFrames < 0 ? -1 : std::max(0, sourceFrames - firstFrame);
  if (maxFrames >= 0 && (count < 0 || maxFrames < count)) count = maxFrames;
  return count;
}

std::vector<RunResult> runOdometry(FrameSource& source, const std::vector<RunOptions>& variants) {
  if (variants.empty()) throw Error("runOdometry: no variant to run");
  std::vector<std::unique_ptr<OdometryPipeline>> pipelines;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    // The variants see the same frames: the first one's progress stream speaks for all.
    RunOptions options = variants[i];
    if (i > 0) options.progress = nullptr;
    pipelines.push_back(std::make_unique<OdometryPipeline>(source, options));
  }
  const RunOptions& first = variants.front();
  const int frameCount = framesInRun(source.frameCount(), first.firstFrame, first.maxFrames);
  source.skip(first.firstFrame);

  const Stopwatch start;
  double sourceSeconds = 0.0;
  bool stopped = false;
  for (int frames = 0; frameCount < 0 || frames < frameCount; ++frames) {
    if (first.stop && first.stop->load()) {
      stopped = true;
      break;
    }
    const Stopwatch read;
    std::optional<StereoFrame> frame = source.next();
    sourceSeconds += read.seconds();
    if (!frame) break;
    for (auto& pipeline : pipelines) pipeline->process(*frame);
    if (first.progress && (frames + 1) % 10 == 0)
      showProgress(*first.progress, pipelines.front()->totals(), start.seconds(), frameCount, false);
  }
  if (first.progress) showProgress(*first.progress, pipelines.front()->totals(), start.seconds(), frameCount, true);
  std::vector<RunResult> results;
  for (auto& pipeline : pipelines) {
    results.push_back(pipeline->finish());
    results.back().totals.sourceSeconds += sourceSeconds;
    results.back().stopped = stopped;
  }
  return results;
}

std::vector<RunResult> runOdometry(const Rig& rig, const std::vector<FrameObservations>& frames,
                                   const GroundTruth& truth, const std::vector<RunOptions>& variants) {
  std::vector<RunResult> results;
  const std::vector<LensDistortion> none(rig.cameras.size());
  for (const RunOptions& options : variants) {
    OdometryPipeline pipeline(rig, none, truth, options);
    const int count = framesInRun(static_cast<int>(frames.size()), options.firstFrame, options.maxFrames);
    const int first = std::min(options.firstFrame, static_cast<int>(frames.size()));
    const Stopwatch start;
    bool stopped = false;
    for (int i = 0; i < count; ++i) {
      if (options.stop && options.stop->load()) {
        stopped = true;
        break;
      }
      pipeline.process(frames[static_cast<std::size_t>(first + i)]);
      if (options.progress && (i + 1) % 100 == 0)
        showProgress(*options.progress, pipeline.totals(), start.seconds(), count, false);
    }
    if (options.progress) showProgress(*options.progress, pipeline.totals(), start.seconds(), count, true);
    results.push_back(pipeline.finish());
    results.back().stopped = stopped;
    if (stopped) break;
  }
  return results;
}

RunResult runOdometry(FrameSource& source, const RunOptions& options) {
  return std::move(runOdometry(source, std::vector<RunOptions>{options}).front());
}

}  // namespace lrsvo

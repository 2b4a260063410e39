#include "lrsvo/frontend/features/image_front_end.h"

#include <algorithm>
#include <string>
#include <unordered_set>

#include "lrsvo/frontend/features/frame_check.h"
#include "lrsvo/frontend/features/fundamental_check.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
ImageFrontEnd::ImageFrontEnd(const Rig& rig, const std::vector<LensDistortion>& distortion,
                             const ImageFrontEndOptions& options)
    : rig_(rig),
      options_(options),
      tracker_(options.tracker),
      baseUndistorter_(rig.cameras.at(0).intrinsics, distortion.at(0)),
      rng_(options.seed) {
  rig.validate();
  if (distortion.size() != rig.cameras.size())
    throw Error("image front end: " + std::to_string(rig.cameras.size()) + " cameras need as many lens models, got " +
                std::to_string(distortion.size()));
  for (int k = 1; k <= rig.secondaryCount(); ++k) matchers_.emplace_back(rig, k, distortion, options.stereo);
  centreBandsOnCalibration();
  // The base pyramid serves both tracking in time and stereo matching: its
  // border and depth must suit the larger window and the deeper pyramid.
  pyramid_.window_px = std::max(options.tracker.klt.window_px, options.stereo.klt.window_px);
  pyramid_.levels = std::max(options.tracker.klt.levels, options.stereo.klt.levels);
}

void ImageFrontEnd::checkFrame(const StereoFrame& frame) const {
  if (frame.cameraCount() != static_cast<int>(rig_.cameras.size()))
    throw Error("image front end: frame " + std::to_string(frame.index) + " has " +
                std::to_string(frame.cameraCount()) + " images, the rig " + std::to_string(rig_.cameras.size()) +
                " cameras");
  // The base image is checked when track() takes it, a deferred one when
  // matchAcrossRig() asks for it.
  for (int c = 1; c < frame.cameraCount(); ++c)
    if (!frame.deferred || !frame.images[c].empty()) checkImage(frame.index, c, frame.images[c]);
}

void ImageFrontEnd::checkImage(int frameIndex, int camera, const cv::Mat& image) const {
  const std::string defect = imageShapeDefect(image, rig_.cameras[static_cast<std::size_t>(camera)]);
  if (!defect.empty())
    throw Error("image front end: frame " + std::to_string(frameIndex) + ", camera " + std::to_string(camera) + ": " +
                defect);
}

int ImageFrontEnd::rejectOutliers(const std::vector<Track>& tracks, const std::vector<Eigen::Vector2d>& pixels) {
  std::vector<int> ids;
  std::vector<Eigen::Vector2d> before, after;
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const auto previous = previousPixel_.find(tracks[i].id);
    if (previous == previousPixel_.end()) continue;
    ids.push_back(tracks[i].id);
    before.push_back(previous->second);
    after.push_back(pixels[i]);
  }
  const std::vector<bool> inlier = fundamentalInliers(before, after, options_.fundamentalThreshold_px, rng_);
  std::vector<int> outliers;
  for (std::size_t j = 0; j < ids.size(); ++j)
    if (!inlier[j]) outliers.push_back(ids[j]);
  tracker_.drop(outliers);
  return static_cast<int>(outliers.size());
}

FrameObservations ImageFrontEnd::track(const StereoFrame& frame) {
  checkFrame(frame);
  const cv::Mat& baseImage = frame.image(0);
  checkImage(frame.index, 0, baseImage);
  timings_ = {};
  const Stopwatch start;
  base_ = makeKltImage(baseImage, pyramid_);
  const double pyramid_ms = start.milliseconds();
  tracker_.track(base_, frame.time_s);
  const TrackerStatistics& statistics = tracker_.lastStatistics();
  timings_.detect_ms = statistics.detect_ms;
  timings_.track_ms = pyramid_ms + statistics.track_ms;
  timings_.added = statistics.added;
  timings_.realigned = statistics.realigned;
  timings_.revived = statistics.revived;

  Stopwatch stage;
  raw_.clear();
  for (const Track& t : tracker_.tracks()) raw_.push_back(t.pixel);
  pixels_ = baseUndistorter_.undistort(raw_);
  timings_.undistort_ms = stage.milliseconds();

  stage.restart();
  if (options_.fundamentalCheck && (timings_.rejected = rejectOutliers(tracker_.tracks(), pixels_)) > 0) {
    raw_.clear();
    for (const Track& t : tracker_.tracks()) raw_.push_back(t.pixel);
    pixels_ = baseUndistorter_.undistort(raw_);
  }
  timings_.track_ms += stage.milliseconds();
  const std::vector<Track>& tracks = tracker_.tracks();
  timings_.tracked = static_cast<int>(tracks.size()) - timings_.added;

  FrameObservations observations;
  observations.time_s = frame.time_s;
  ids_.clear();
  previousPixel_.clear();
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    ids_.push_back(tracks[i].id);
    observations.observations.push_back({tracks[i].id, 0, pixels_[i]});
    previousPixel_[tracks[i].id] = pixels_[i];
  }
  trackedFrame_ = frame;  // shares the images (and any deferred ones) with the caller's frame
  matched_ = false;
  timings_.total_ms = start.milliseconds();
  return observations;
}

std::vector<Observation> ImageFrontEnd::matchAcrossRig() {
  if (matched_) throw Error("image front end: matchAcrossRig() runs once per tracked frame, after track()");
  matched_ = true;
  const Stopwatch start;
  std::vector<Observation> observations;
  std::unordered_set<int> matchedSomewhere;
  for (std::size_t k = 0; k < matchers_.size(); ++k) {
    // KLT compares raw intensities: the cameras' exposures must agree first.
    const int camera = static_cast<int>(k + 1);
    const cv::Mat& image = trackedFrame_.image(camera);
    checkImage(trackedFrame_.index, camera, image);
    const KltImage secondary = makeKltImage(withBrightnessOf(image, base_.image), pyramid_);
    for (const StereoMatch& m : matchers_[k].match(base_, secondary, ids_, raw_, pixels_)) {
      observations.push_back({m.track, static_cast<int>(k + 1), m.pixel});
      matchedSomewhere.insert(m.track);
    }
  }
  trackedFrame_ = {};
  timings_.stereo_ms = start.milliseconds();
  timings_.total_ms += timings_.stereo_ms;
  timings_.stereoMatched = static_cast<int>(matchedSomewhere.size());
  return observations;
}

FrameObservations ImageFrontEnd::process(const StereoFrame& frame) {
  FrameObservations observations = track(frame);
  const std::vector<Observation> secondary = matchAcrossRig();
  observations.observations.insert(observations.observations.end(), secondary.begin(), secondary.end());
  return observations;
}

void ImageFrontEnd::centreBandsOn(const std::vector<VertexStereoExtrinsic::Vector6>& extrinsics) {
  if (extrinsics.size() != matchers_.size())
    throw Error("image front end: " + std::to_string(matchers_.size()) +
                " secondary cameras need as many extrinsics, got " + std::to_string(extrinsics.size()));
  for (std::size_t k = 0; k < matchers_.size(); ++k) matchers_[k].centreOn(extrinsics[k]);
}

void ImageFrontEnd::centreBandsOnCalibration() {
  for (std::size_t k = 0; k < matchers_.size(); ++k)
    matchers_[k].centreOn(rig_.extrinsics[k], matchers_[k].toleranceSpread_px());
}

void ImageFrontEnd::dropTracks(const std::vector<int>& trackIds) {
  tracker_.drop(trackIds);
  for (int id : trackIds) previousPixel_.erase(id);
}

void ImageFrontEnd::reset() {
  tracker_.reset();
  trackedFrame_ = {};
  matched_ = true;
  for (StereoMatcher& matcher : matchers_) matcher.reset();
  centreBandsOnCalibration();
  previousPixel_.clear();
}

}  // namespace lrsvo

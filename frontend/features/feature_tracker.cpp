#include "lrsvo/frontend/features/feature_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

std::vector<cv::Point2f> pixelsOf(const std::vector<Track>& tracks) {
  std::vector<cv::Point2f> pixels;
  pixels.reserve(tracks.size());
  for (const Track& t : tracks) pixels.push_back(t.pixel);
  return pixels;
}

// Per axis, the median motion of the tracks that have one (age > 1 once
// track() has aged them); zero when none has.
cv::Point2f medianMotion(const std::vector<Track>& tracks) {
  std::vector<float> x, y;
  for (const Track& t : tracks) {
    if (t.age <= 1) continue;
    x.push_back(t.motion.x);
    y.push_back(t.motion.y);
  }
  if (x.empty()) return {0.0f, 0.0f};
  const auto middle = static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), x.begin() + middle, x.end());
  std::nth_element(y.begin(), y.begin() + middle, y.end());
  return {x[static_cast<std::size_t>(middle)], y[static_cast<std::size_t>(middle)]};
}

}  // namespace

KltImage FeatureTracker::previousWithBrightnessOf(const KltImage& next, double nextMean) const {
  if (std::abs(nextMean - previousMean_) <= options_.brightnessTolerance * previousMean_) return previous_;
  return makeKltImage(withBrightnessOf(previous_.image, next.image), options_.klt);
}

FeatureTracker::FeatureTracker(const FeatureTrackerOptions& options) : options_(options), detector_(options.detector) {
  if (options.targetFeatures < 1) throw Error("feature tracker: targetFeatures must be at least 1");
  if (!(options.topUpFraction >= 0.0 && options.topUpFraction <= 1.0))
    throw Error("feature tracker: topUpFraction must lie in [0, 1]");
  if (!(options.realignBelowFraction >= 0.0 && options.realignBelowFraction <= 1.0))
    throw Error("feature tracker: realignBelowFraction must lie in [0, 1]");
  if (!(options.brightnessTolerance >= 0.0)) throw Error("feature tracker: brightnessTolerance must be >= 0");
  if (!(options.descriptorRatio > 0.0 && options.descriptorRatio <= 1.0))
    throw Error("feature tracker: descriptorRatio must lie in (0, 1]");
  if (!(options.minReviveOverlap >= 0.0 && options.minReviveOverlap <= 1.0))
    throw Error("feature tracker: minReviveOverlap must lie in [0, 1]");
  if (!(options.reviveWithin_s >= 0.0)) throw Error("feature tracker: reviveWithin_s must be >= 0");
}

const std::vector<Track>& FeatureTracker::track(const KltImage& image, double time_s) {
  statistics_ = {};
  for (Track& t : tracks_) ++t.age;
  if (detector_.hasDescriptors()) {
    const Stopwatch detectStart;
    DetectedFeatures candidates = detector_.detect(image.image, {}, 2 * options_.targetFeatures);
    statistics_.detect_ms = detectStart.milliseconds();
    const Stopwatch trackStart;
    followByDescriptor(candidates);
    statistics_.track_ms = trackStart.milliseconds();
    statistics_.tracked = static_cast<int>(tracks_.size());
    addNew(std::move(candidates), options_.targetFeatures - statistics_.tracked);
  } else {
    const Stopwatch trackStart;
    const double mean = cv::mean(image.image)[0];
    followByKlt(image, mean);
    if (broken_) revive(image, mean, time_s);
    previousMean_ = mean;
    statistics_.track_ms = trackStart.milliseconds();
    statistics_.tracked = static_cast<int>(tracks_.size());
    const int wanted = options_.targetFeatures - statistics_.tracked;
    if (wanted > 0 && wanted >= options_.topUpFraction * options_.targetFeatures) {
      const Stopwatch detectStart;
      addNew(detector_.detect(image.image, pixelsOf(tracks_), wanted), wanted);
      statistics_.detect_ms = detectStart.milliseconds();
    }
  }
  previousInterval_s_ = previous_.image.empty() ? 0.0 : time_s - previousTime_;
  previous_ = image;
  previousTime_ = time_s;
  return tracks_;
}

double FeatureTracker::predictedOverlap(const Broken& broken, cv::Size imageSize, double time_s) const {
  const cv::Point2f shift = broken.velocity_px_s * static_cast<float>(time_s - broken.time_s);
  return std::max(0.0, 1.0 - std::abs(shift.x) / imageSize.width) *
         std::max(0.0, 1.0 - std::abs(shift.y) / imageSize.height);
}

std::vector<cv::Point2f> FeatureTracker::predictedPixels() const {
  const cv::Point2f typical = medianMotion(tracks_);
  std::vector<cv::Point2f> predicted;
  predicted.reserve(tracks_.size());
  for (const Track& t : tracks_) predicted.push_back(t.pixel + (t.age > 1 ? t.motion : typical));
  return predicted;
}

void FeatureTracker::followByKlt(const KltImage& image, double imageMean) {
  if (tracks_.empty()) return;
  const KltImage from = previousWithBrightnessOf(image, imageMean);
  const std::vector<cv::Point2f> points = pixelsOf(tracks_);
  std::vector<cv::Point2f> positions = predictedPixels();
  std::vector<bool> found = trackKlt(from, image, points, positions, options_.klt);
  const auto count = [](const std::vector<bool>& flags) { return std::count(flags.begin(), flags.end(), true); };
  const auto followed = count(found);
  if (static_cast<double>(followed) < options_.realignBelowFraction * static_cast<double>(points.size())) {
    const cv::Point2f shift = globalShift(from, image).shift;
    std::vector<cv::Point2f> shifted;
    shifted.reserve(points.size());
    for (const cv::Point2f& p : points) shifted.push_back(p + shift);
    std::vector<bool> foundShifted = trackKlt(from, image, points, shifted, options_.klt);
    if (count(foundShifted) > followed) {
      positions = std::move(shifted);
      found = std::move(foundShifted);
      statistics_.realigned = true;
    }
  }
  // A break within a break (a second unusable image) keeps the last good image.
  if (!broken_ &&
      static_cast<double>(count(found)) < options_.realignBelowFraction * static_cast<double>(points.size())) {
    const cv::Point2f velocity = previousInterval_s_ > 0.0
                                     ? medianMotion(tracks_) * static_cast<float>(1.0 / previousInterval_s_)
                                     : cv::Point2f(0.0f, 0.0f);
    broken_ = Broken{previous_.image, previousMean_, previousTime_, tracks_, nextId_, velocity, std::nullopt};
  }
  std::vector<Track> kept;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    if (!found[i]) continue;
    kept.push_back(tracks_[i]);
    kept.back().pixel = positions[i];
    kept.back().motion = positions[i] - points[i];
  }
  tracks_ = std::move(kept);
}

void FeatureTracker::revive(const KltImage& image, double imageMean, double time_s) {
  Broken& broken = *broken_;
  const double overlap = predictedOverlap(broken, image.image.size(), time_s);
  if (time_s - broken.time_s > options_.reviveWithin_s || overlap <= 0.0 || overlap < options_.minReviveOverlap) {
    broken_.reset();
    return;
  }
  if (!broken.described) broken.described = describeImage(broken.image, options_.alignment);
  const ImageAlignment alignment =
      alignByDescriptors(*broken.described, describeImage(image.image, options_.alignment), options_.alignment);
  if (!alignment.found) return;
  // KLT from the old image warped onto the new one: the patches then agree in
  // rotation and scale, which KLT's translation-only model needs.
  const cv::Mat source = std::abs(imageMean - broken.mean) <= options_.brightnessTolerance * broken.mean
                             ? broken.image
                             : withBrightnessOf(broken.image, image.image);
  cv::Mat warped;
  cv::warpPerspective(source, warped, cv::Mat(alignment.homography), image.image.size(), cv::INTER_LINEAR,
                      cv::BORDER_REPLICATE);
  std::vector<cv::Point2f> points = transformedPixels(alignment.homography, pixelsOf(broken.tracks));
  std::vector<cv::Point2f> positions = points;
  const std::vector<bool> found = trackKlt(makeKltImage(warped, options_.klt), image, points, positions, options_.klt);
  std::vector<Track> revived;
  for (std::size_t i = 0; i < broken.tracks.size(); ++i) {
    if (!found[i]) continue;
    revived.push_back(broken.tracks[i]);
    revived.back().pixel = positions[i];
    revived.back().motion = cv::Point2f(0.0f, 0.0f);
  }
  // Every track of the old image takes the aligned position or is dropped:
  // where most tracks broke, the few KLT kept may have locked onto the wrong
  // spot. A track born since the break on the same spot as a revived one
  // follows the same scene point under a new id: the revived one, which the
  // map knows, replaces it.
  std::unordered_set<int> old;
  for (const Track& t : broken.tracks) old.insert(t.id);
  const double min2 = options_.detector.minDistance_px * options_.detector.minDistance_px;
  std::erase_if(tracks_, [&](const Track& t) {
    if (old.count(t.id)) return true;
    return t.id >= broken.firstNewId && std::any_of(revived.begin(), revived.end(), [&](const Track& r) {
             const cv::Point2f d = r.pixel - t.pixel;
             return d.dot(d) < min2;
           });
  });
  statistics_.revived = static_cast<int>(revived.size());
  tracks_.insert(tracks_.end(), revived.begin(), revived.end());
  std::sort(tracks_.begin(), tracks_.end(), [](const Track& a, const Track& b) { return a.id < b.id; });
  // Once the images align the search is over, however many were found: the
  // overlap only shrinks from here, and a later find would replace tracks the
  // odometry may by then have started a new map from.
  broken_.reset();
}

// Each track takes the candidate with the nearest descriptor inside the search
// radius around its predicted pixel when it passes the ratio test; a candidate
// claimed by several tracks goes to the closest in descriptor distance.
// Matched candidates leave the pool.
void FeatureTracker::followByDescriptor(const DetectedFeatures& candidates) {
  const double radius2 = options_.descriptorSearch_px * options_.descriptorSearch_px;
  const std::vector<cv::Point2f> predicted = predictedPixels();
  std::vector<int> bestCandidate(tracks_.size(), -1);
  std::vector<int> bestDistance(tracks_.size(), std::numeric_limits<int>::max());
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    int best = std::numeric_limits<int>::max(), second = std::numeric_limits<int>::max(), bestIndex = -1;
    for (int c = 0; c < static_cast<int>(candidates.points.size()); ++c) {
      const cv::Point2f d = candidates.points[static_cast<std::size_t>(c)] - predicted[t];
      if (d.dot(d) > radius2) continue;
      const int distance =
          static_cast<int>(cv::norm(tracks_[t].descriptor, candidates.descriptors.row(c), cv::NORM_HAMMING));
      if (distance < best) {
        second = best;
        best = distance;
        bestIndex = c;
      } else if (distance < second) {
        second = distance;
      }
    }
    if (bestIndex < 0 || best > options_.maxHamming) continue;
    if (second != std::numeric_limits<int>::max() && best >= options_.descriptorRatio * second) continue;
    bestCandidate[t] = bestIndex;
    bestDistance[t] = best;
  }
  std::vector<int> owner(candidates.points.size(), -1);
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    const int c = bestCandidate[t];
    if (c < 0) continue;
    int& o = owner[static_cast<std::size_t>(c)];
    if (o < 0 || bestDistance[t] < bestDistance[static_cast<std::size_t>(o)]) o = static_cast<int>(t);
  }
  std::vector<Track> kept;
  for (std::size_t c = 0; c < owner.size(); ++c) {
    if (owner[c] < 0) continue;
    Track t = tracks_[static_cast<std::size_t>(owner[c])];
    t.motion = candidates.points[c] - t.pixel;
    t.pixel = candidates.points[c];
    t.descriptor = candidates.descriptors.row(static_cast<int>(c)).clone();
    kept.push_back(std::move(t));
  }
  // Keep the order of ids so that output does not depend on candidate order.
  std::sort(kept.begin(), kept.end(), [](const Track& a, const Track& b) { return a.id < b.id; });
  tracks_ = std::move(kept);
}

// New tracks from `features` (strongest first), skipping any within the
// detector's minimum distance of a live track.
void FeatureTracker::addNew(DetectedFeatures features, int wanted) {
  if (wanted <= 0) return;
  const double min2 = options_.detector.minDistance_px * options_.detector.minDistance_px;
  const std::size_t live = tracks_.size();
  for (std::size_t i = 0; i < features.points.size() && statistics_.added < wanted; ++i) {
    const cv::Point2f& p = features.points[i];
    const bool crowded =
        std::any_of(tracks_.begin(), tracks_.begin() + static_cast<std::ptrdiff_t>(live), [&](const Track& t) {
          const cv::Point2f d = t.pixel - p;
          return d.dot(d) < min2;
        });
    if (crowded) continue;
    Track t;
    t.id = nextId_++;
    t.pixel = p;
    if (!features.descriptors.empty()) t.descriptor = features.descriptors.row(static_cast<int>(i)).clone();
    tracks_.push_back(std::move(t));
    ++statistics_.added;
  }
}

void FeatureTracker::drop(const std::vector<int>& ids) {
  const std::unordered_set<int> gone(ids.begin(), ids.end());
  const auto dropped = [&](const Track& t) { return gone.count(t.id) > 0; };
  std::erase_if(tracks_, dropped);
  if (broken_) std::erase_if(broken_->tracks, dropped);
}

void FeatureTracker::reset() {
  tracks_.clear();
  previous_ = {};
  broken_.reset();
}

}  // namespace lrsvo

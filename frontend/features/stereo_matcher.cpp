#include "lrsvo/frontend/features/stereo_matcher.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_set>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// Pyramid levels above the full image for KLT from last frame's offset: a
// stereo match barely moves between frames, so the coarse levels add nothing.
constexpr int kFollowLevels = 1;

Eigen::Vector2d project(const PinholeIntrinsics& k, const Eigen::Vector3d& p) {
  return {k.fx * p.x() / p.z() + k.cx, k.fy * p.y() / p.z() + k.cy};
}

// Clips the segment a + t (b - a), t in [0, 1], to the box [low, high]; false when none of it is inside.
bool clipToBox(const Eigen::Vector2d& low, const Eigen::Vector2d& high, Eigen::Vector2d& a, Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < low[axis] || a[axis] > high[axis]) return false;
      continue;
    }
    double ta = (low[axis] - a[axis]) / d[axis], tb = (high[axis] - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return false;
  const Eigen::Vector2d start = a + t0 * d;
  b = a + t1 * d;
  a = start;
  return true;
}

// A square patch of an 8-bit image around the pixel nearest `centre`, as
// zero-mean values of unit norm; empty when it leaves the image or is flat.
std::vector<float> referencePatch(const cv::Mat& image, const cv::Point2f& centre, int side) {
  const int half = side / 2, x0 = cvRound(centre.x) - half, y0 = cvRound(centre.y) - half;
  if (x0 < 0 || y0 < 0 || x0 + side > image.cols || y0 + side > image.rows) return {};
  std::vector<float> patch;
  patch.reserve(static_cast<std::size_t>(side * side));
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) patch.push_back(image.at<unsigned char>(y0 + r, x0 + c));
  double mean = 0.0, norm2 = 0.0;
  for (float v : patch) mean += v;
  mean /= static_cast<double>(patch.size());
  for (float& v : patch) {
    v = static_cast<float>(v - mean);
    norm2 += v * v;
  }
  if (!(norm2 > 1e-6)) return {};
  for (float& v : patch) v = static_cast<float>(v / std::sqrt(norm2));
  return patch;
}

// Zero-mean normalised cross-correlation of `reference` (from referencePatch)
// with the patch of `image` around the pixel nearest `centre`; -1 off the image.
double correlation(const std::vector<float>& reference, const cv::Mat& image, const cv::Point2f& centre, int side) {
  const int half = side / 2, x0 = cvRound(centre.x) - half, y0 = cvRound(centre.y) - half;
  if (x0 < 0 || y0 < 0 || x0 + side > image.cols || y0 + side > image.rows) return -1.0;
  // sum r (c - mean c) = sum r c, as r has zero mean.
  double dot = 0.0, sum = 0.0, sum2 = 0.0;
  for (int r = 0; r < side; ++r) {
    const unsigned char* row = image.ptr<unsigned char>(y0 + r) + x0;
    const float* ref = reference.data() + r * side;
    for (int c = 0; c < side; ++c) {
      const double v = row[c];
      dot += ref[c] * v;
      sum += v;
      sum2 += v * v;
    }
  }
  const double variance = sum2 - sum * sum / (side * side);
  return variance > 1e-6 ? dot / std::sqrt(variance) : -1.0;
}

}  // namespace

StereoMatcher::StereoMatcher(const Rig& rig, int camera, const std::vector<LensDistortion>& distortion,
                             const StereoMatcherOptions& options)
    : base_(rig.cameras.at(0)),
      secondary_(rig.cameras.at(static_cast<std::size_t>(camera))),
      undistorter_(secondary_.intrinsics, distortion.at(static_cast<std::size_t>(camera))),
      options_(options) {
  if (camera < 1 || camera > rig.secondaryCount())
    throw Error("stereo matcher: camera " + std::to_string(camera) + " is not a secondary camera of the rig");
  if (!(options.bandWidth_px > 0.0) || !(options.minDepth_m > 0.0) || !(options.maxDepth_m > options.minDepth_m))
    throw Error("stereo matcher: need bandWidth_px > 0 and 0 < minDepth_m < maxDepth_m");
  if (options.searchPatch_px < 3 || options.searchLevel < 0)
    throw Error("stereo matcher: searchPatch_px must be >= 3 and searchLevel >= 0");
  // The captured image's border, undistorted: a lens with barrel distortion
  // sees beyond the pinhole image's rectangle.
  std::vector<cv::Point2f> border;
  const float w = static_cast<float>(secondary_.width - 1), h = static_cast<float>(secondary_.height - 1);
  for (float t = 0.0f; t <= 1.0f; t += 1.0f / 64.0f)
    for (const cv::Point2f& p :
         {cv::Point2f(t * w, 0), cv::Point2f(t * w, h), cv::Point2f(0, t * h), cv::Point2f(w, t * h)})
      border.push_back(p);
  const std::vector<Eigen::Vector2d> undistortedBorder = undistorter_.undistort(border);
  undistortedLow_ = undistortedHigh_ = undistortedBorder.front();
  for (const Eigen::Vector2d& p : undistortedBorder) {
    undistortedLow_ = undistortedLow_.cwiseMin(p);
    undistortedHigh_ = undistortedHigh_.cwiseMax(p);
  }
  toleranceSpread_px_ = spreadOfToleranceBox(rig, camera);
  centreOn(rig.extrinsics.at(static_cast<std::size_t>(camera - 1)));
}

void StereoMatcher::centreOn(const VertexStereoExtrinsic::Vector6& s, double widening_px) {
  if (!(widening_px >= 0.0)) throw Error("stereo matcher: the band's widening must be >= 0");
  const Eigen::Isometry3d transform = secondaryFromBase(s);
  rotation_ = transform.linear();
  centre_ = -rotation_.transpose() * transform.translation();
  band_px_ = options_.bandWidth_px + widening_px;
}

// Each of the six numbers moved to either end of its tolerance shifts a match
// across the calibrated line; the shifts of the six add up in the worst case.
// Checked at the image's corners and centre, at the nearest and farthest depth.
double StereoMatcher::spreadOfToleranceBox(const Rig& rig, int camera) const {
  const VertexStereoExtrinsic::Vector6 calibration = rig.extrinsics.at(static_cast<std::size_t>(camera - 1));
  const double far_m = std::isfinite(options_.maxDepth_m) ? options_.maxDepth_m : 1e6;
  const PinholeIntrinsics& k = base_.intrinsics;
  const double w = base_.width - 1.0, h = base_.height - 1.0;
  double worst = 0.0;
  for (const Eigen::Vector2d& pixel : {Eigen::Vector2d(0, 0), Eigen::Vector2d(w, 0), Eigen::Vector2d(0, h),
                                       Eigen::Vector2d(w, h), Eigen::Vector2d(w / 2, h / 2)}) {
    const Eigen::Vector3d ray((pixel.x() - k.cx) / k.fx, (pixel.y() - k.cy) / k.fy, 1.0);
    auto seen = [&](const VertexStereoExtrinsic::Vector6& s, double depth) -> std::optional<Eigen::Vector2d> {
      const Eigen::Vector3d p = secondaryFromBase(s) * (depth * ray);
      if (p.z() <= 0.0) return std::nullopt;
      return project(secondary_.intrinsics, p);
    };
    const auto near = seen(calibration, options_.minDepth_m), far = seen(calibration, far_m);
    if (!near || !far || (*far - *near).norm() < 1e-9) continue;
    const Eigen::Vector2d direction = (*far - *near).normalized();
    for (double depth : {options_.minDepth_m, far_m}) {
      const auto centre = seen(calibration, depth);
      double shift = 0.0;
      for (int i = 0; i < 6; ++i) {
        double largest = 0.0;
        for (double sign : {-1.0, 1.0}) {
          VertexStereoExtrinsic::Vector6 s = calibration;
          s[i] += sign * rig.tolerance[i];
          const auto moved = seen(s, depth);
          if (!moved) continue;
          const Eigen::Vector2d d = *moved - *centre;
          largest = std::max(largest, std::abs(direction.x() * d.y() - direction.y() * d.x()));
        }
        shift += largest;
      }
      worst = std::max(worst, shift);
    }
  }
  return worst;
}

StereoMatcher::Segment StereoMatcher::segmentOf(const Eigen::Vector2d& basePixel) const {
  const PinholeIntrinsics& k = base_.intrinsics;
  const Eigen::Vector3d ray((basePixel.x() - k.cx) / k.fx, (basePixel.y() - k.cy) / k.fy, 1.0);
  Segment segment;
  const Eigen::Vector3d nearPoint = rotation_ * (options_.minDepth_m * ray - centre_);
  const Eigen::Vector3d farPoint = std::isfinite(options_.maxDepth_m)
                                       ? Eigen::Vector3d(rotation_ * (options_.maxDepth_m * ray - centre_))
                                       : Eigen::Vector3d(rotation_ * ray);
  if (nearPoint.z() <= 0.0 || farPoint.z() <= 0.0) return segment;
  Eigen::Vector2d a = project(secondary_.intrinsics, nearPoint), b = project(secondary_.intrinsics, farPoint);
  const Eigen::Vector2d fullDirection = b - a;
  if (fullDirection.norm() < 1e-9 || !clipToBox(undistortedLow_, undistortedHigh_, a, b)) return segment;
  segment.start = a;
  segment.direction = fullDirection.normalized();
  segment.length = (b - a).norm();
  segment.valid = true;
  return segment;
}

bool StereoMatcher::inBand(const Segment& segment, const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d offset = pixel - segment.start;
  const double along = segment.direction.dot(offset);
  const double across = segment.direction.x() * offset.y() - segment.direction.y() * offset.x();
  const double band = band_px_;
  return std::abs(across) <= band && along >= -band && along <= segment.length + band;
}

bool StereoMatcher::search(const KltImage& base, const KltImage& secondary, const cv::Point2f& baseRaw,
                           const Segment& segment, cv::Point2f& found) const {
  const int level = std::min(options_.searchLevel, std::min(base.levels(), secondary.levels()) - 1);
  const double step = std::ldexp(1.0, level);  // one pixel of the search level
  const float scale = static_cast<float>(1.0 / step);
  const std::vector<float> reference = referencePatch(base.level(level), baseRaw * scale, options_.searchPatch_px);
  if (reference.empty()) return false;
  const Eigen::Vector2d normal(-segment.direction.y(), segment.direction.x());
  const int acrossSteps = static_cast<int>(std::floor(band_px_ / step));
  std::vector<Eigen::Vector2d> candidates;
  for (double along = 0.0; along <= segment.length; along += step)
    for (int across = -acrossSteps; across <= acrossSteps; ++across)
      candidates.push_back(segment.start + along * segment.direction + across * step * normal);
  const cv::Mat searched = secondary.level(level);
  double best = options_.minCorrelation;
  bool any = false;
  for (const cv::Point2f& candidate : undistorter_.distort(candidates)) {
    const double score = correlation(reference, searched, candidate * scale, options_.searchPatch_px);
    if (score > best) {
      best = score;
      found = candidate;
      any = true;
    }
  }
  return any;
}

std::vector<StereoMatch> StereoMatcher::match(const KltImage& base, const KltImage& secondary,
                                              const std::vector<int>& ids, const std::vector<cv::Point2f>& raw,
                                              const std::vector<Eigen::Vector2d>& undistorted) {
  if (ids.size() != raw.size() || ids.size() != undistorted.size())
    throw Error("stereo matcher: ids, raw and undistorted pixels must have one entry per feature");
  std::vector<Segment> segments(ids.size());
  std::vector<bool> matched(ids.size(), false);
  std::vector<cv::Point2f> positions(ids.size());
  std::vector<Eigen::Vector2d> pixels(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) segments[i] = segmentOf(undistorted[i]);

  // Refines the guesses of `which` by KLT and keeps those inside the band.
  auto refine = [&](const std::vector<std::size_t>& which, const std::vector<cv::Point2f>& guesses,
                    const KltOptions& klt) {
    std::vector<cv::Point2f> points, moved = guesses;
    for (std::size_t i : which) points.push_back(raw[i]);
    const std::vector<bool> found = trackKlt(base, secondary, points, moved, klt);
    const std::vector<Eigen::Vector2d> movedPixels = undistorter_.undistort(moved);
    for (std::size_t j = 0; j < which.size(); ++j) {
      const std::size_t i = which[j];
      if (!found[j] || !inBand(segments[i], movedPixels[j])) continue;
      matched[i] = true;
      positions[i] = moved[j];
      pixels[i] = movedPixels[j];
    }
  };

  std::vector<std::size_t> which;
  std::vector<cv::Point2f> guesses;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const auto previous = previousOffset_.find(ids[i]);
    if (!segments[i].valid || previous == previousOffset_.end()) continue;
    which.push_back(i);
    guesses.push_back(raw[i] + previous->second);
  }
  KltOptions follow = options_.klt;
  follow.levels = std::min(follow.levels, kFollowLevels);
  refine(which, guesses, follow);

  which.clear();
  guesses.clear();
  for (std::size_t i = 0; i < ids.size(); ++i) {
    cv::Point2f guess;
    if (!segments[i].valid || matched[i] || searchedInVain_.count(ids[i])) continue;
    if (!search(base, secondary, raw[i], segments[i], guess)) continue;
    which.push_back(i);
    guesses.push_back(guess);
  }
  refine(which, guesses, options_.klt);

  std::vector<StereoMatch> result;
  previousOffset_.clear();
  std::unordered_set<int> searchedInVain;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (!matched[i]) {
      if (segments[i].valid) searchedInVain.insert(ids[i]);
      continue;
    }
    result.push_back({ids[i], positions[i], pixels[i]});
    previousOffset_[ids[i]] = positions[i] - raw[i];
  }
  searchedInVain_ = std::move(searchedInVain);
  return result;
}

}  // namespace lrsvo

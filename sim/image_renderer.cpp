#include "lrsvo/sim/image_renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/graph/stopwatch.h"
#include "lrsvo/sim/gaussian_noise.h"
#include "lrsvo/sim/surface_view.h"

namespace lrsvo {
namespace {

constexpr std::uint64_t kGainStream = 0x6761696e, kNoiseStream = 0x6e6f6973;  // "gain", "nois"
constexpr int kGainSinusoids = 3;
constexpr int kRowsPerChunk = 8;  // ~100 chunks an image: both threads stay busy to the last row

}  // namespace

ImageRenderer::ImageRenderer(const Terrain& terrain, const SurfaceTexture& texture, const RenderOptions& options,
                             std::uint64_t seed)
    : terrain_(terrain), texture_(texture), options_(options), seed_(seed) {
  const RenderOptions& o = options_;
  if (!(o.noiseSigma_grey >= 0.0 && o.blurSigma_px >= 0.0 && o.exposureDrift >= 0.0 && o.vignetting >= 0.0 &&
        o.vignetting < 1.0 && std::isfinite(o.noiseSigma_grey) && std::isfinite(o.blurSigma_px) &&
        o.exposureDrift < 1.0))
    throw Error(
        "image renderer: noiseSigma_grey and blurSigma_px must be finite and >= 0, exposureDrift and "
        "vignetting in [0, 1)");
  if (!(o.exposurePeriod_s > 0.0 && std::isfinite(o.exposurePeriod_s)) || o.threads < 1)
    throw Error("image renderer: exposurePeriod_s must be finite and > 0 and threads >= 1");
}

double ImageRenderer::gain(double time_s, int cameraIndex) const {
  if (options_.exposureDrift == 0.0) return 1.0;
  SplitMix64 rng(mixSeed(seed_, kGainStream, static_cast<std::uint64_t>(cameraIndex)));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double drift = 0.0;
  for (int i = 0; i < kGainSinusoids; ++i) {
    const double period = options_.exposurePeriod_s * std::exp2(2.0 * unit(rng) - 1.0);
    const double phase = 2.0 * std::numbers::pi * unit(rng);
    drift += std::sin(2.0 * std::numbers::pi * time_s / period + phase) / kGainSinusoids;
  }
  return 1.0 + options_.exposureDrift * drift;
}

cv::Mat ImageRenderer::renderScene(const Camera& camera, const Eigen::Isometry3d& cameraFromWorld) const {
  Stopwatch phase;
  const SurfaceView view(terrain_, camera, cameraFromWorld, options_.threads);
  times_.view_s += phase.lap();
  texture_.prepare(view.regions(), options_.threads);
  times_.texture_s += phase.lap();
  cv::Mat scene(camera.height, camera.width, CV_32FC1);
  const int chunks = (camera.height + kRowsPerChunk - 1) / kRowsPerChunk;
  parallelFor(0, chunks, options_.threads, 1, [&](int chunk) {
    RowHits row;
    for (int v = chunk * kRowsPerChunk; v < std::min(camera.height, (chunk + 1) * kRowsPerChunk); ++v) {
      view.hitRow(v, 0, camera.width, row);
      texture_.greyRow(row, scene.ptr<float>(v));
    }
  });
  ++times_.images;
  times_.shade_s += phase.seconds();
  return scene;
}

cv::Mat ImageRenderer::render(const Camera& camera, const Eigen::Isometry3d& cameraFromWorld, double time_s, int frame,
                              int cameraIndex) const {
  cv::Mat image = renderScene(camera, cameraFromWorld);
  const Stopwatch start;
  image *= gain(time_s, cameraIndex);
  if (options_.vignetting > 0.0) vignette(camera, image);
  if (options_.blurSigma_px > 0.0) cv::GaussianBlur(image, image, cv::Size(0, 0), options_.blurSigma_px);
  // Noise and the conversion to 8 bits, a band of rows at a time. Each pixel
  // draws its noise by its index (sim/gaussian_noise.h): the image does not depend on the threads.
  cv::Mat out(image.size(), CV_8UC1);
  const std::uint64_t noiseKey =
      mixSeed(seed_ ^ kNoiseStream, static_cast<std::uint64_t>(frame), static_cast<std::uint64_t>(cameraIndex));
  const int chunks = (image.rows + kRowsPerChunk - 1) / kRowsPerChunk;
  parallelFor(0, chunks, options_.threads, 1, [&](int chunk) {
    const cv::Range rows(chunk * kRowsPerChunk, std::min(image.rows, (chunk + 1) * kRowsPerChunk));
    if (options_.noiseSigma_grey > 0.0)
      for (int v = rows.start; v < rows.end; ++v)
        addGaussianNoise(image.ptr<float>(v), image.cols, options_.noiseSigma_grey, noiseKey,
                         static_cast<std::uint64_t>(v) * static_cast<std::uint64_t>(image.cols));
    image.rowRange(rows).convertTo(out.rowRange(rows), CV_8UC1);  // rounds and saturates to 0..255
  });
  times_.sensor_s += start.seconds();
  return out;
}

void ImageRenderer::vignette(const Camera& camera, cv::Mat& image) const {
  // Relative illumination cos^4 of the off-axis angle, scaled to the requested corner loss.
  const PinholeIntrinsics& k = camera.intrinsics;
  const double cornerSquared = std::pow(std::max(k.cx, camera.width - k.cx) / k.fx, 2) +
                               std::pow(std::max(k.cy, camera.height - k.cy) / k.fy, 2);
  const double cornerCos4 = 1.0 / std::pow(1.0 + cornerSquared, 2);
  for (int v = 0; v < image.rows; ++v) {
    float* row = image.ptr<float>(v);
    for (int u = 0; u < image.cols; ++u) {
      const double r2 = std::pow((u - k.cx) / k.fx, 2) + std::pow((v - k.cy) / k.fy, 2);
      const double cos4 = 1.0 / std::pow(1.0 + r2, 2);
      row[u] *= static_cast<float>(1.0 - options_.vignetting * (1.0 - cos4) / (1.0 - cornerCos4));
    }
  }
}

}  // namespace lrsvo

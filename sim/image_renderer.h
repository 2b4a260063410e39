#pragma once

#include <cstdint>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/sim/surface_texture.h"
#include "lrsvo/sim/terrain.h"

namespace lrsvo {

// The sensor: what turns the scene's grey levels into an 8-bit image.
struct RenderOptions {
  double noiseSigma_grey = 2.0;    // Gaussian read noise per pixel, grey levels
  double blurSigma_px = 0.5;       // Gaussian optical blur, pixels (0: none)
  double exposureDrift = 0.08;     // relative amplitude of the slow gain drift of each camera (0: constant gain)
  double exposurePeriod_s = 20.0;  // typical period of that drift (its sinusoids span half to twice this)
  double vignetting = 0.0;         // relative darkening at the image corners (cos^4-like fall-off; 0: none)
  int threads = 2;                 // 1: on the calling thread; more: parallelFor (graph/parallel_for.h)
};

// Where the renderer's time goes: wall seconds summed over the images rendered.
struct RenderTimes {
  int images = 0;
  double view_s = 0.0;     // each view's ground grid and obstacle lists
  double texture_s = 0.0;  // the texture's caches (making the texel tiles an image needs)
  double shade_s = 0.0;    // tracing and shading every pixel
  double sensor_s = 0.0;   // gain, vignetting, blur, noise, 8-bit conversion (render() only)
  double total_s() const { return view_s + texture_s + shade_s + sensor_s; }
};

// Renders what a pinhole camera (no distortion) sees of a terrain: each
// pixel's ray meets the surface (sim/surface_view.h) and takes the texture's
// grey there, averaged over the pixel's footprint on the surface so that
// images do not shimmer as the camera moves. Then the gain of that camera at
// that time, vignetting, blur and noise (seeded by seed, frame and camera:
// the same call gives the same image). One image at a time: render() fills
// the texture's caches for the image first, then shades its rows in parallel.
class ImageRenderer {
 public:
  // Throws lrsvo::Error on negative sigmas, drift or vignetting, a
  // non-positive period or thread count.
  ImageRenderer(const Terrain& terrain, const SurfaceTexture& texture, const RenderOptions& options,
                std::uint64_t seed);

  // Camera `cameraIndex` of the rig at pose cameraFromWorld in frame `frame`
  // at time_s: a CV_8UC1 image of camera.width x camera.height.
  cv::Mat render(const Camera& camera, const Eigen::Isometry3d& cameraFromWorld, double time_s, int frame,
                 int cameraIndex) const;
  // The scene alone (before gain, vignetting, blur and noise): CV_32FC1 grey levels.
  cv::Mat renderScene(const Camera& camera, const Eigen::Isometry3d& cameraFromWorld) const;
  // The relative gain of camera `cameraIndex` at time_s, 1 +- exposureDrift.
  double gain(double time_s, int cameraIndex) const;
  // The time of every image rendered so far, by stage.
  const RenderTimes& times() const { return times_; }

 private:
  void vignette(const Camera& camera, cv::Mat& image) const;

  const Terrain& terrain_;
  const SurfaceTexture& texture_;
  RenderOptions options_;
  std::uint64_t seed_;
  mutable RenderTimes times_;
};

}  // namespace lrsvo

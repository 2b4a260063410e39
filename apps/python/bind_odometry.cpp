// lrsvo.run (a whole run, as `lrsvo run`), lrsvo.Source (frames of a source
// as numpy images), lrsvo.Rig and lrsvo.Odometry (frame by frame, from a
// caller's own loop).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>

#include "apps/run_setup.h"
#include "apps/stop_on_signal.h"
#include "bindings.h"
#include "frame_table.h"
#include "lrsvo/eval/run_report.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/graph/error.h"
#include "trajectory_arrays.h"

namespace py = pybind11;

namespace lrsvo::python {
namespace {

// The Python keyword of an option word: "--scale-drift" -> "scale_drift".
std::string keywordOf(const std::string& word) {
  std::string keyword = word.substr(2);
  std::replace(keyword.begin(), keyword.end(), '-', '_');
  return keyword;
}

// An unknown keyword is named as the caller wrote it, with the known ones.
void checkKeywords(const CLI::App& parser, const std::vector<std::string>& words) {
  for (const std::string& word : words) {
    if (word.rfind("--", 0) != 0 || parser.get_option_no_throw(word)) continue;
    std::string known;
    for (const CLI::Option* option : parser.get_options())
      if (!option->get_lnames().empty())
        known += (known.empty() ? "" : ", ") + keywordOf("--" + option->get_lnames().front());
    throw Error("unknown odometry option '" + keywordOf(word) + "' (known: " + known + ")");
  }
}

// The odometry's options from `lrsvo run`'s option words (["--window", "12", "--rigid"]):
// the CLI's own parser, so names, checks and messages are the CLI's.
RunOptions runOptionsFrom(const std::vector<std::string>& words) {
  CLI::App parser("lrsvo odometry options");
  cli::OdometrySettings settings;
  settings.addOptions(parser);
  checkKeywords(parser, words);
  std::vector<std::string> reversed(words.rbegin(), words.rend());
  try {
    parser.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw Error(std::string("odometry options: ") + e.what());
  }
  return settings.runOptions();
}

Trajectory truthTrajectory(const GroundTruth& truth, double from_s = -INFINITY, double to_s = INFINITY) {
  Trajectory trajectory;
  for (const TimedPose& pose : truth.poses)
    if (pose.time_s >= from_s && pose.time_s <= to_s) trajectory.add(pose.time_s, pose.worldFromCamera);
  return trajectory;
}

py::object parseJson(const nlohmann::json& json) { return py::module_::import("json").attr("loads")(json.dump()); }

py::dict runResult(const RunResult& run, const std::vector<FrameEstimate>& frames, int secondaryCameras,
                   const RunReport& report, const GroundTruth& truth) {
  py::dict result;
  result["trajectory"] = toArray(run.trajectory);
  result["frames"] = frameTable(frames, secondaryCameras);
  result["metrics"] = parseJson(report.metrics);
  // The truth over the frames run (a source's truth may span far more).
  result["truth"] = frames.empty() ? toArray(Trajectory{})
                                   : toArray(truthTrajectory(truth, frames.front().time_s, frames.back().time_s));
  result["stopped"] = run.stopped;
  result["warning"] = report.warning;
  return result;
}

py::dict run(const std::string& source, const std::string& out, const std::vector<std::string>& optionWords, int first,
             int frames, bool plot, bool featureLevel, bool progress) {
  RunOptions options = runOptionsFrom(optionWords);
  if (first < 0) throw Error("first must be >= 0, got " + std::to_string(first));
  options.firstFrame = first;
  options.maxFrames = frames;
  options.outDir = out;
  if (progress) options.progress = &std::cerr;
  std::vector<FrameEstimate> estimates;
  options.onFrame = [&](const FrameEstimate& estimate) { estimates.push_back(estimate); };
  int secondaryCameras = 0;
  cli::SourceRun done;
  RunReport report;
  {
    py::gil_scoped_release release;
    const cli::StopOnSignal stop;
    options.stop = &stop.requested();
    done = cli::runSource(source, options, featureLevel,
                          [&](const std::string&, int, const Rig& rig) { secondaryCameras = rig.secondaryCount(); });
    report = writeRunReport(options.outDir, done.run, done.truth, plot);
  }
  return runResult(done.run, estimates, secondaryCameras, report, done.truth);
}

py::array_t<std::uint8_t> toNumpy(const cv::Mat& image) {
  if (image.empty()) return py::array_t<std::uint8_t>(std::vector<py::ssize_t>{0, 0});
  const cv::Mat gray = image.isContinuous() ? image : image.clone();
  py::array_t<std::uint8_t> array({static_cast<py::ssize_t>(gray.rows), static_cast<py::ssize_t>(gray.cols)});
  std::memcpy(array.mutable_data(), gray.data, gray.total());
  return array;
}

// A source's frames in order; each as (time_s, [image per camera]).
class Source {
 public:
  explicit Source(const std::string& spec) : source_(cli::openSource(spec)) {}
  const FrameSource& source() const { return *source_; }
  std::optional<py::tuple> next() {
    std::optional<StereoFrame> frame;
    std::vector<cv::Mat> images;
    {
      py::gil_scoped_release release;
      frame = source_->next();
      // A source may defer a camera's image until asked: rendering it needs no GIL.
      if (frame && frame->defect.empty())
        for (int k = 0; k < frame->cameraCount(); ++k) images.push_back(frame->image(k));
    }
    if (!frame) return std::nullopt;
    if (!frame->defect.empty()) throw Error("frame " + std::to_string(frame->index) + ": " + frame->defect);
    py::list arrays;
    for (const cv::Mat& image : images) arrays.append(toNumpy(image));
    return py::make_tuple(frame->time_s, arrays);
  }

 private:
  std::unique_ptr<FrameSource> source_;
};

// The odometry fed frame by frame: process() takes a rig's images and returns
// the frames whose estimates it completed (an initialisation holds a few back).
class FrameByFrameOdometry {
 public:
  FrameByFrameOdometry(const Rig& rig, const std::vector<std::string>& optionWords, const std::string& out)
      : rig_(rig) {
    rig.validate();
    RunOptions options = runOptionsFrom(optionWords);
    options.outDir = out;
    options.onFrame = [this](const FrameEstimate& estimate) { completed_.push_back(estimate); };
    pipeline_ = std::make_unique<OdometryPipeline>(rig, std::vector<LensDistortion>(rig.cameras.size()), GroundTruth{},
                                                   options);
  }

  py::dict process(const std::vector<py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>>& images,
                   double time_s) {
    if (finished_) throw Error("Odometry.process: the run is finished");
    if (static_cast<int>(images.size()) != static_cast<int>(rig_.cameras.size()))
      throw Error("Odometry.process: the rig has " + std::to_string(rig_.cameras.size()) + " cameras, got " +
                  std::to_string(images.size()) + " images");
    StereoFrame frame;
    frame.index = frames_++;
    frame.time_s = time_s;
    for (const auto& image : images) {
      if (image.ndim() != 2) throw Error("Odometry.process: an image is a 2-D uint8 array (grey levels)");
      frame.images.push_back(cv::Mat(static_cast<int>(image.shape(0)), static_cast<int>(image.shape(1)), CV_8UC1,
                                     const_cast<std::uint8_t*>(image.data()))
                                 .clone());
    }
    const std::size_t before = completed_.size();
    {
      py::gil_scoped_release release;
      pipeline_->process(frame);
    }
    return frameTable({completed_.begin() + static_cast<std::ptrdiff_t>(before), completed_.end()},
                      rig_.secondaryCount());
  }

  py::dict finish() {
    if (finished_) throw Error("Odometry.finish: the run is finished");
    finished_ = true;
    RunResult run;
    {
      py::gil_scoped_release release;
      run = pipeline_->finish();
    }
    py::dict result;
    result["trajectory"] = toArray(run.trajectory);
    result["frames"] = frameTable(completed_, rig_.secondaryCount());
    return result;
  }

 private:
  Rig rig_;
  std::unique_ptr<OdometryPipeline> pipeline_;
  std::vector<FrameEstimate> completed_;
  int frames_ = 0;
  bool finished_ = false;
};

Rig makeRig(const std::vector<std::array<double, 6>>& cameras,
            const std::vector<Eigen::Matrix<double, 6, 1>>& extrinsics,
            const std::optional<Eigen::Matrix<double, 6, 1>>& tolerance) {
  Rig rig;
  for (const auto& [fx, fy, cx, cy, width, height] : cameras) {
    Camera camera;
    camera.intrinsics = {fx, fy, cx, cy};
    camera.width = static_cast<int>(width);
    camera.height = static_cast<int>(height);
    rig.cameras.push_back(camera);
  }
  rig.extrinsics = extrinsics;
  if (tolerance) rig.tolerance = *tolerance;
  rig.validate();
  return rig;
}

}  // namespace

void bindOdometry(py::module_& m) {
  m.def("_run", &run, py::arg("source"), py::arg("out"), py::arg("options"), py::arg("first"), py::arg("frames"),
        py::arg("plot"), py::arg("feature_level"), py::arg("progress"));

  py::class_<Rig>(m, "Rig",
                  "The cameras' pinhole intrinsics and image sizes; each secondary camera's extrinsic s = (x, y, z, "
                  "roll, pitch, yaw) relative to the base camera (docs/method.md) and the box around it.")
      .def(py::init(&makeRig), py::arg("cameras"), py::arg("extrinsics"), py::arg("tolerance") = std::nullopt,
           "cameras: (fx, fy, cx, cy, width, height) per camera, the base first; extrinsics: one 6-vector per "
           "secondary camera; tolerance: the box's half-widths (default 1 mm, 10 mrad).")
      .def_static("paper", &paperRig, py::arg("baseline_m") = 0.7, py::arg("width") = 1280, py::arg("height") = 960,
                  py::arg("horizontal_fov_rad") = 0.733, "The paper's rig: two cameras along the fuselage.")
      .def_property_readonly("cameras",
                             [](const Rig& rig) {
                               std::vector<std::array<double, 6>> cameras;
                               for (const Camera& c : rig.cameras)
                                 cameras.push_back({c.intrinsics.fx, c.intrinsics.fy, c.intrinsics.cx, c.intrinsics.cy,
                                                    static_cast<double>(c.width), static_cast<double>(c.height)});
                               return cameras;
                             })
      .def_readonly("extrinsics", &Rig::extrinsics)
      .def_readonly("tolerance", &Rig::tolerance);

  py::class_<Source>(m, "Source",
                     "A source of rig images as `lrsvo run` opens it: sim:demo, sim:paper, sim:stress, "
                     "sim:FILE.yaml (rendered on the fly), or a EuRoC or KITTI folder. Iterating gives "
                     "(time_s, [uint8 image per camera]).")
      .def(py::init<const std::string&>(), py::arg("spec"))
      .def_property_readonly("name", [](const Source& s) { return s.source().name(); })
      .def_property_readonly("rig", [](const Source& s) { return s.source().rig(); })
      .def_property_readonly("frame_count", [](const Source& s) { return s.source().frameCount(); })
      .def(
          "ground_truth", [](const Source& s) { return toArray(truthTrajectory(s.source().groundTruth())); },
          "The base camera's true poses (N x 8), empty when the source has none.")
      .def("__iter__", [](Source& s) -> Source& { return s; })
      .def("__next__", [](Source& s) {
        std::optional<py::tuple> frame = s.next();
        if (!frame) throw py::stop_iteration();
        return *frame;
      });

  py::class_<FrameByFrameOdometry>(m, "_Odometry")
      .def(py::init<const Rig&, const std::vector<std::string>&, const std::string&>(), py::arg("rig"),
           py::arg("options"), py::arg("out"))
      .def("process", &FrameByFrameOdometry::process, py::arg("images"), py::arg("time_s"))
      .def("finish", &FrameByFrameOdometry::finish);
}

}  // namespace lrsvo::python

#include "unit_tests/fuzz/parsers.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include <unistd.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "lrsvo/constraints/constraint_types.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/frontend/datasets/euroc_reader.h"
#include "lrsvo/frontend/datasets/gtsam_stereo_vo.h"
#include "lrsvo/frontend/datasets/kitti_reader.h"
#include "lrsvo/frontend/datasets/nist_problem.h"
#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/sim/scenario.h"

namespace lrsvo::fuzz {
namespace {

namespace fs = std::filesystem;

// This process's scratch folder, removed when the process ends normally.
class Scratch {
 public:
  Scratch() : root_(fs::temp_directory_path() / ("lrsvo_fuzz_" + std::to_string(::getpid()))) {
    fs::create_directories(root_);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
};

const fs::path& scratch() {
  static const Scratch folder;
  return folder.root();
}

void writeFile(const fs::path& path, std::string_view text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
}

// The input's parts between NUL bytes, at least `count` (missing ones empty).
std::vector<std::string_view> parts(const std::uint8_t* data, std::size_t size, std::size_t count) {
  std::vector<std::string_view> result;
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  while (result.size() + 1 < count) {
    const std::size_t end = rest.find('\0');
    if (end == std::string_view::npos) break;
    result.push_back(rest.substr(0, end));
    rest.remove_prefix(end + 1);
  }
  result.push_back(rest);
  result.resize(std::max(result.size(), count));
  return result;
}

std::string_view whole(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs a parser; its rejection of bad input is lrsvo::Error, anything else propagates.
template <typename Parse>
void rejectingBadInput(Parse&& parse) {
  try {
    parse();
  } catch (const Error&) {
  }
}

// A valid EuRoC cam<i>/sensor.yaml: the data.csv harness varies only the image lists.
constexpr std::string_view kSensorYaml =
    "%YAML:1.0\n"
    "sensor_type: camera\n"
    "T_BS:\n"
    "  cols: 4\n"
    "  rows: 4\n"
    "  data: [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]\n"
    "rate_hz: 20\n"
    "resolution: [16, 12]\n"
    "camera_model: pinhole\n"
    "intrinsics: [10.0, 10.0, 8.0, 6.0]\n"
    "distortion_model: radial-tangential\n"
    "distortion_coefficients: [0.0, 0.0, 0.0, 0.0]\n";
constexpr std::string_view kSensorYamlRight =
    "%YAML:1.0\n"
    "T_BS:\n"
    "  cols: 4\n"
    "  rows: 4\n"
    "  data: [1.0, 0.0, 0.0, 0.1, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]\n"
    "resolution: [16, 12]\n"
    "intrinsics: [10.0, 10.0, 8.0, 6.0]\n"
    "distortion_coefficients: [0.0, 0.0, 0.0, 0.0]\n";

void bal(const std::uint8_t* data, std::size_t size) {
  const fs::path file = scratch() / "problem.bal";
  writeFile(file, whole(data, size));
  rejectingBadInput([&] { (void)readBal(file.string()); });
}

void graphFile(const std::uint8_t* data, std::size_t size) {
  registerEdgeTypes();
  registerConstraintTypes();
  std::istringstream in{std::string(whole(data, size))};
  rejectingBadInput([&] { (void)loadGraph(in, "fuzz input"); });
}

void tumPoses(const std::uint8_t* data, std::size_t size) {
  const fs::path file = scratch() / "poses.tum";
  writeFile(file, whole(data, size));
  rejectingBadInput([&] { (void)readTumTrajectory(file); });
}

void kittiPoses(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string_view> files = parts(data, size, 2);
  const fs::path poses = scratch() / "poses.txt", times = scratch() / "times.txt";
  writeFile(poses, files[0]);
  writeFile(times, files[1]);
  rejectingBadInput([&] { (void)readKittiTrajectory(poses, files[1].empty() ? fs::path() : times); });
}

void eurocSensor(const std::uint8_t* data, std::size_t size) {
  const fs::path file = scratch() / "sensor.yaml";
  writeFile(file, whole(data, size));
  rejectingBadInput([&] { (void)readEurocSensor(file.string()); });
}

void eurocDataCsv(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string_view> files = parts(data, size, 2);
  const fs::path sequence = scratch() / "euroc";
  writeFile(sequence / "mav0" / "cam0" / "sensor.yaml", kSensorYaml);
  writeFile(sequence / "mav0" / "cam1" / "sensor.yaml", kSensorYamlRight);
  writeFile(sequence / "mav0" / "cam0" / "data.csv", files[0]);
  writeFile(sequence / "mav0" / "cam1" / "data.csv", files[1]);
  rejectingBadInput([&] { EurocSource source(sequence.string()); });
}

void eurocGroundTruth(const std::uint8_t* data, std::size_t size) {
  const fs::path sequence = scratch() / "euroc_truth";
  const fs::path mav = sequence / "mav0";
  if (!fs::exists(mav / "cam1" / "data.csv")) {
    constexpr std::string_view kOneFrame = "#timestamp [ns],filename\n1000,1000.png\n";
    writeFile(mav / "cam0" / "sensor.yaml", kSensorYaml);
    writeFile(mav / "cam1" / "sensor.yaml", kSensorYamlRight);
    writeFile(mav / "cam0" / "data.csv", kOneFrame);
    writeFile(mav / "cam1" / "data.csv", kOneFrame);
  }
  writeFile(mav / "state_groundtruth_estimate0" / "data.csv", whole(data, size));
  rejectingBadInput([&] { EurocSource source(sequence.string()); });
}

void kittiCalibTimes(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string_view> files = parts(data, size, 2);
  const fs::path sequence = scratch() / "kitti";
  const fs::path image = sequence / "image_0" / "000000.png";
  if (!fs::exists(image)) {
    fs::create_directories(image.parent_path());
    cv::imwrite(image.string(), cv::Mat(12, 16, CV_8UC1, cv::Scalar(128)));
  }
  writeFile(sequence / "calib.txt", files[0]);
  writeFile(sequence / "times.txt", files[1]);
  rejectingBadInput([&] { KittiSource source(sequence.string()); });
}

void scenarioYaml(const std::uint8_t* data, std::size_t size) {
  const fs::path file = scratch() / "scenario.yaml";
  writeFile(file, whole(data, size));
  rejectingBadInput([&] { (void)readScenarioYaml(file.string()); });
}

void gtsamVo(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string_view> files = parts(data, size, 3);
  const fs::path folder = scratch() / "gtsam";
  writeFile(folder / "VO_calibration.txt", files[0]);
  writeFile(folder / "VO_camera_poses_fuzz.txt", files[1]);
  writeFile(folder / "VO_stereo_factors_fuzz.txt", files[2]);
  rejectingBadInput([&] { (void)loadGtsamStereoVo(folder.string(), "fuzz"); });
}

void nistProblem(const std::uint8_t* data, std::size_t size) {
  rejectingBadInput([&] { (void)parseNistProblem(std::string(whole(data, size)), "fuzz input"); });
}

}  // namespace

const std::vector<Parser>& parsers() {
  static const std::vector<Parser> all = {
      {"bal", "a BAL problem (readBal)", bal},
      {"graph_file", "the graph file (loadGraph)", graphFile},
      {"tum_poses", "a TUM pose file (readTumTrajectory)", tumPoses},
      {"kitti_poses", "KITTI poses NUL their times (readKittiTrajectory)", kittiPoses},
      {"euroc_sensor", "EuRoC cam<i>/sensor.yaml (readEurocSensor)", eurocSensor},
      {"euroc_data_csv", "EuRoC cam0 NUL cam1 data.csv (EurocSource)", eurocDataCsv},
      {"euroc_ground_truth", "EuRoC state_groundtruth_estimate0/data.csv (EurocSource)", eurocGroundTruth},
      {"kitti_calib_times", "KITTI calib.txt NUL times.txt (KittiSource)", kittiCalibTimes},
      {"scenario_yaml", "a sim: scenario YAML (readScenarioYaml)", scenarioYaml},
      {"gtsam_vo", "GTSAM VO calibration NUL poses NUL factors (loadGtsamStereoVo)", gtsamVo},
      {"nist_problem", "a NIST StRD regression file (parseNistProblem)", nistProblem},
  };
  return all;
}

const Parser& parser(const std::string& name) {
  for (const Parser& p : parsers())
    if (p.name == name) return p;
  throw Error("fuzz: unknown parser '" + name + "'");
}

}  // namespace lrsvo::fuzz

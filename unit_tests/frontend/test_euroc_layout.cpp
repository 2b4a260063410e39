// The EuRoC layout as other tools write it: the lens models of sensor.yaml
// (radial-tangential, Kalibr's radtan, the equidistant fisheye model, none)
// and EuRoC's own ground truth, mav0/state_groundtruth_estimate0/data.csv.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/frontend/datasets/euroc_reader.h"
#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/frontend/features/undistortion.h"
#include "lrsvo/graph/error.h"
#include "unit_tests/shared_data.h"
#include "unit_tests/temp_folder.h"

namespace lrsvo {
namespace {

namespace fs = std::filesystem;

// A sensor.yaml with the given lens lines (and camera_model line, if any).
std::string sensorYaml(const std::string& lens, const std::string& cameraModel = "camera_model: pinhole\n") {
  return "%YAML:1.0\nsensor_type: camera\nT_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, "
         "0, 0, 0, 1]\nrate_hz: 20\nresolution: [752, 480]\n" +
         cameraModel + "intrinsics: [458.6, 457.3, 367.2, 248.4] #fu, fv, cu, cv\n" + lens;
}

EurocCameraCalibration readSensorText(const fs::path& folder, const std::string& text) {
  fs::create_directories(folder);
  const fs::path path = folder / "sensor.yaml";
  std::ofstream(path) << text;
  return readEurocSensor(path.string());
}

std::string errorOf(const fs::path& folder, const std::string& text) {
  try {
    readSensorText(folder, text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(EurocSensor, ReadsEveryLensModelItNames) {
  const fs::path folder = test::freshFolder("euroc_lens");
  using Model = LensDistortion::Model;
  const EurocCameraCalibration radtan = readSensorText(
      folder, sensorYaml("distortion_model: radial-tangential\ndistortion_coefficients: [-0.28, 0.07, 2e-4, 1e-5]\n"));
  EXPECT_EQ(radtan.distortion.model, Model::kRadialTangential);
  EXPECT_EQ(radtan.distortion.coefficients, (std::array<double, 5>{-0.28, 0.07, 2e-4, 1e-5, 0.0}));

  const EurocCameraCalibration kalibr = readSensorText(
      folder, sensorYaml("distortion_model: radtan\ndistortion_coefficients: [-0.28, 0.07, 2e-4, 1e-5, 0.01]\n"));
  EXPECT_EQ(kalibr.distortion.model, Model::kRadialTangential);
  EXPECT_EQ(kalibr.distortion.coefficients[4], 0.01);

  const EurocCameraCalibration fisheye =
      readSensorText(folder, sensorYaml("distortion_model: 'equidistant'  # Kannala-Brandt\n"
                                        "distortion_coefficients: [0.01, -0.003, 0.0005, -0.0001]\n"));
  EXPECT_EQ(fisheye.distortion.model, Model::kEquidistant);
  EXPECT_EQ(fisheye.distortion.coefficients, (std::array<double, 5>{0.01, -0.003, 0.0005, -0.0001, 0.0}));

  EXPECT_TRUE(readSensorText(folder, sensorYaml("distortion_model: none\n")).distortion.none());
  // Without distortion_model the file is EuRoC's own: radial-tangential.
  EXPECT_EQ(readSensorText(folder, sensorYaml("distortion_coefficients: [0.1, 0, 0, 0]\n")).distortion.model,
            Model::kRadialTangential);
  fs::remove_all(folder);
}

TEST(EurocSensor, RejectsWhatItCannotModelNamingIt) {
  const fs::path folder = test::freshFolder("euroc_lens_errors");
  EXPECT_NE(errorOf(folder, sensorYaml("distortion_model: fov\ndistortion_coefficients: [0.9]\n")).find("'fov'"),
            std::string::npos);
  EXPECT_NE(errorOf(folder, sensorYaml("distortion_model: equidistant\ndistortion_coefficients: [0.1, 0, 0, 0, 0]\n"))
                .find("k1 k2 k3 k4"),
            std::string::npos);
  EXPECT_NE(
      errorOf(folder, sensorYaml("distortion_model: radtan\ndistortion_coefficients: [0.1, 0]\n")).find("k1 k2 p1 p2"),
      std::string::npos);
  EXPECT_NE(errorOf(folder, sensorYaml("distortion_model: none\n", "camera_model: omni\n")).find("'omni'"),
            std::string::npos);
  fs::remove_all(folder);
}

// The equidistant model as its definition gives it: a ray at angle theta from
// the axis lands at f theta_d (x, y) / r with theta_d = theta (1 + k1 theta^2
// + k2 theta^4 + k3 theta^6 + k4 theta^8), and undistortion inverts it.
TEST(Undistorter, EquidistantModelIsKannalaBrandtAndInvertsIt) {
  const PinholeIntrinsics k{380.0, 381.0, 320.0, 240.0};
  LensDistortion lens;
  lens.model = LensDistortion::Model::kEquidistant;
  lens.coefficients = {0.02, -0.01, 0.004, -0.001, 0.0};
  const Undistorter undistorter(k, lens);
  const std::vector<Eigen::Vector2d> ideal = {{320, 240}, {100, 60}, {600, 450}, {20, 400}, {500, 30}};
  const std::vector<cv::Point2f> captured = undistorter.distort(ideal);
  for (std::size_t i = 0; i < ideal.size(); ++i) {
    const double x = (ideal[i].x() - k.cx) / k.fx, y = (ideal[i].y() - k.cy) / k.fy, r = std::hypot(x, y);
    const double theta = std::atan(r), t2 = theta * theta;
    const double thetaD = theta * (1 + t2 * (0.02 + t2 * (-0.01 + t2 * (0.004 + t2 * -0.001))));
    const double scale = r > 0 ? thetaD / r : 1.0;
    // distort() returns floats: 1e-3 px at these magnitudes.
    EXPECT_NEAR(captured[i].x, k.fx * scale * x + k.cx, 1e-3) << i;
    EXPECT_NEAR(captured[i].y, k.fy * scale * y + k.cy, 1e-3) << i;
  }
  const std::vector<Eigen::Vector2d> back = undistorter.undistort(captured);
  for (std::size_t i = 0; i < ideal.size(); ++i) EXPECT_LT((back[i] - ideal[i]).norm(), 2e-3) << i;
}

// The micro sequence with its ground truth written the way EuRoC ships it
// (state_groundtruth_estimate0/data.csv, ns and w-first quaternions) instead
// of as TUM: the same poses.
TEST(EurocSource, ReadsEurocsOwnGroundTruth) {
  if (!fs::exists(test::kEuroc)) GTEST_SKIP() << "no " << test::kEuroc;
  const fs::path folder = test::freshFolder("euroc_state_truth");
  fs::create_directories(folder / "mav0" / "state_groundtruth_estimate0");
  for (const char* camera : {"cam0", "cam1"})
    fs::create_directory_symlink(fs::absolute(fs::path(test::kEuroc) / "mav0" / camera), folder / "mav0" / camera);
  const Trajectory tum = readTumTrajectory(test::kEuroc + "/groundtruth_body_tum.txt");
  {
    std::ofstream csv(folder / "mav0" / "state_groundtruth_estimate0" / "data.csv");
    csv << "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], q_RS_z [], "
           "v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], b_w_RS_S_x [rad s^-1], b_w_RS_S_y [rad s^-1], "
           "b_w_RS_S_z [rad s^-1], b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], b_a_RS_S_z [m s^-2]\n"
        << std::setprecision(17);
    for (std::size_t i = 0; i < tum.size(); ++i) {
      const Eigen::Quaterniond q(tum.worldFromCamera[i].linear());
      const Eigen::Vector3d p = tum.worldFromCamera[i].translation();
      csv << std::llround(tum.times_s[i] * 1e9) << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << q.w() << ','
          << q.x() << ',' << q.y() << ',' << q.z() << ",0,0,0,0,0,0,0,0,0\n";
    }
  }
  const GroundTruth expected = EurocSource(test::kEuroc).groundTruth();
  const GroundTruth truth = EurocSource(folder.string()).groundTruth();
  ASSERT_EQ(truth.poses.size(), expected.poses.size());
  ASSERT_FALSE(truth.poses.empty());
  for (std::size_t i = 0; i < truth.poses.size(); ++i) {
    // The times pass through whole nanoseconds and a double of 1.4e9 s (resolution 2.4e-7 s).
    EXPECT_NEAR(truth.poses[i].time_s, expected.poses[i].time_s, 1e-6) << i;
    EXPECT_TRUE(truth.poses[i].worldFromCamera.matrix().isApprox(expected.poses[i].worldFromCamera.matrix(), 1e-12))
        << i;
  }

  std::ofstream(folder / "mav0" / "state_groundtruth_estimate0" / "data.csv")
      << "#timestamp\n1403715273262142976,1,2\n";
  try {
    EurocSource source(folder.string());
    ADD_FAILURE() << "expected an error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("data.csv"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), 2) << e.what();
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace lrsvo

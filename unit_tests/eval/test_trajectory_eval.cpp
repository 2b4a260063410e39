#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/eval/trajectory_alignment.h"
#include "lrsvo/eval/trajectory_association.h"
#include "lrsvo/eval/trajectory_metrics.h"
#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/graph/error.h"
#include "unit_tests/temp_folder.h"

namespace lrsvo {
namespace {

constexpr double kTight = 1e-9;

// An empty folder for a test's files.
std::filesystem::path emptyFolder(const std::string& name) {
  const std::filesystem::path folder = test::freshFolder(name);
  std::filesystem::create_directories(folder);
  return folder;
}

Eigen::Isometry3d pose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& position) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = rotation;
  p.translation() = position;
  return p;
}

Eigen::Matrix3d rotationZ(double angle) { return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).matrix(); }

// A climbing turn of radius 150 m, 2 m per frame, turning and rolling as it goes:
// positions spread in all three axes, orientations all different.
Trajectory climbingTurn(int frames) {
  Trajectory t;
  for (int i = 0; i < frames; ++i) {
    const double a = 2.0 * i / 150.0;
    const Eigen::Matrix3d r = rotationZ(a) * Eigen::AngleAxisd(0.1 * std::sin(0.05 * i), Eigen::Vector3d::UnitX());
    t.add(0.1 * i, pose(r, Eigen::Vector3d(150.0 * std::sin(a), 150.0 * (1.0 - std::cos(a)), 0.3 * i)));
  }
  return t;
}

// A straight line along z (KITTI's forward axis), `step` metres per frame.
Trajectory straightLine(int frames, double step) {
  Trajectory t;
  for (int i = 0; i < frames; ++i) t.add(0.1 * i, pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, step * i)));
  return t;
}

Trajectory moved(const Trajectory& t, const Eigen::Isometry3d& g) {
  Trajectory out;
  for (std::size_t i = 0; i < t.size(); ++i) out.add(t.times_s[i], g * t.worldFromCamera[i]);
  return out;
}

TEST(TrajectoryEvalMetrics, IdenticalTrajectoriesHaveNoError) {
  const Trajectory truth = climbingTurn(400);
  const TrajectoryMetrics m = computeTrajectoryMetrics({truth, truth});
  EXPECT_EQ(m.frames, 400u);
  EXPECT_NEAR(m.distance_m, 399 * std::hypot(2.0 * 150.0 * std::sin(1.0 / 150.0), 0.3), 1e-6);
  EXPECT_NEAR(m.ate_m.max, 0.0, kTight);
  EXPECT_NEAR(m.ateSim3_m.max, 0.0, kTight);
  EXPECT_NEAR(m.sim3.scale, 1.0, kTight);
  EXPECT_NEAR(m.rpeTranslation_m.max, 0.0, kTight);
  EXPECT_NEAR(m.rpeRotation_rad.max, 0.0, kTight);
  EXPECT_GT(m.drift.segments, 0u);
  EXPECT_NEAR(m.drift.translation_percent, 0.0, kTight);
  EXPECT_NEAR(m.drift.rotation_deg_per_100m, 0.0, kTight);
  EXPECT_NEAR(m.scaleErrorPercent, 0.0, kTight);
  EXPECT_NEAR(m.finalPositionError_m, 0.0, kTight);
}

TEST(TrajectoryEvalMetrics, RigidMotionOfTheEstimateIsAlignedAway) {
  const Trajectory truth = climbingTurn(300);
  const Eigen::Isometry3d g =
      pose(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).matrix(), Eigen::Vector3d(40, -25, 7));
  const TrajectoryMetrics m = computeTrajectoryMetrics({moved(truth, g), truth});
  EXPECT_TRUE(m.se3.rigid.isApprox(g.inverse(), 1e-9));
  EXPECT_NEAR(m.ate_m.rmse, 0.0, 1e-9);
  EXPECT_NEAR(m.ateRotation_rad.max, 0.0, 1e-9);
  EXPECT_NEAR(m.rpeTranslation_m.max, 0.0, 1e-9);  // relative motions do not see a rigid move
  EXPECT_NEAR(m.drift.translation_percent, 0.0, 1e-9);
  EXPECT_NEAR(m.finalPositionError_m, 0.0, 1e-9);
}

TEST(TrajectoryEvalMetrics, KnownScaleIsRecoveredBySim3Only) {
  const Trajectory truth = climbingTurn(300);
  // The estimate at half size, turned and shifted: truth = 2 R^T (estimate - t).
  const Eigen::Isometry3d g = pose(rotationZ(0.3), Eigen::Vector3d(5, 6, 7));
  Trajectory estimate;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Isometry3d& q = truth.worldFromCamera[i];
    estimate.add(truth.times_s[i], g * pose(q.linear(), 0.5 * q.translation()));
  }
  const TrajectoryMetrics m = computeTrajectoryMetrics({estimate, truth});
  EXPECT_NEAR(m.sim3.scale, 2.0, 1e-9);
  EXPECT_NEAR(m.ateSim3_m.rmse, 0.0, 1e-8);
  EXPECT_NEAR(m.scaleErrorPercent, -50.0, 1e-9);
  EXPECT_GT(m.ate_m.rmse, 10.0);  // a rigid alignment cannot undo a scale
}

TEST(TrajectoryEvalMetrics, OffsetOfHalfThePosesGivesHalfAMetreEverywhere) {
  // Every position twice; the second copy of each is 1 m off along x in the
  // estimate. The offsets do not correlate with the positions, so the best rigid
  // alignment is the mean shift, 0.5 m, and every pose is then 0.5 m off.
  const Trajectory turn = climbingTurn(200);
  Trajectory truth, estimate;
  for (std::size_t i = 0; i < turn.size(); ++i) {
    const Eigen::Isometry3d& q = turn.worldFromCamera[i];
    truth.add(2.0 * i, q);
    truth.add(2.0 * i + 1.0, q);
    estimate.add(2.0 * i, q);
    estimate.add(2.0 * i + 1.0, pose(q.linear(), q.translation() + Eigen::Vector3d::UnitX()));
  }
  const TrajectoryMetrics m = computeTrajectoryMetrics({estimate, truth});
  EXPECT_NEAR(m.ate_m.rmse, 0.5, 1e-9);
  EXPECT_NEAR(m.ate_m.mean, 0.5, 1e-9);
  EXPECT_NEAR(m.ate_m.median, 0.5, 1e-9);
  EXPECT_NEAR(m.ate_m.max, 0.5, 1e-9);
  EXPECT_TRUE(m.se3.rigid.linear().isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_TRUE(m.se3.rigid.translation().isApprox(Eigen::Vector3d(-0.5, 0, 0), 1e-9));
}

TEST(TrajectoryEvalMetrics, OneWrongStepShowsInTheRelativePoseErrors) {
  // Truth: 1 m steps along x. Estimate: the same steps, but the step into frame 5
  // carries an extra error G = [Rz(theta) | (0.1, 0, 0)].
  const double theta = 0.02;
  const Eigen::Isometry3d stepError = pose(rotationZ(theta), Eigen::Vector3d(0.1, 0, 0));
  const Eigen::Isometry3d step = pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 0));
  Trajectory truth, estimate;
  truth.add(0, Eigen::Isometry3d::Identity());
  estimate.add(0, Eigen::Isometry3d::Identity());
  for (int i = 1; i <= 9; ++i) {
    truth.add(i, truth.worldFromCamera.back() * step);
    estimate.add(i, estimate.worldFromCamera.back() * step * (i == 5 ? stepError : Eigen::Isometry3d::Identity()));
  }
  // delta 1: E(4, 5) = G; every other pair is exact.
  const RelativePoseErrors one = relativePoseErrors(estimate, truth, pairsByFrames(10, 1, false));
  ASSERT_EQ(one.translation_m.size(), 9u);
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_NEAR(one.translation_m[k], k == 4 ? 0.1 : 0.0, 1e-12) << k;
    EXPECT_NEAR(one.rotation_rad[k], k == 4 ? theta : 0.0, 1e-12) << k;
  }
  const ErrorStatistics s = errorStatistics(one.translation_m);
  EXPECT_NEAR(s.rmse, 0.1 / 3.0, 1e-12);
  EXPECT_NEAR(s.mean, 0.1 / 9.0, 1e-12);
  EXPECT_NEAR(s.median, 0.0, 1e-12);
  EXPECT_NEAR(s.max, 0.1, 1e-12);
  // delta 2, chained pairs (0,2) (2,4) (4,6) (6,8): E(4, 6) = S^-1 G S with S the 1 m step,
  // whose translation is Rz(theta) (1, 0, 0) + (0.1, 0, 0) - (1, 0, 0).
  const IndexPairs pairs = pairsByFrames(10, 2, false);
  ASSERT_EQ(pairs, (IndexPairs{{0, 2}, {2, 4}, {4, 6}, {6, 8}}));
  const RelativePoseErrors two = relativePoseErrors(estimate, truth, pairs);
  EXPECT_NEAR(two.translation_m[2], std::hypot(std::cos(theta) - 0.9, std::sin(theta)), 1e-12);
  EXPECT_NEAR(two.rotation_rad[2], theta, 1e-12);
  EXPECT_NEAR(two.translation_m[1] + two.translation_m[3], 0.0, 1e-12);
  EXPECT_EQ(pairsByFrames(10, 2, true).size(), 8u);
}

// evo's pairs by distance. Chained: marks where the path walked since the
// last mark reaches delta (3, 6, 9 for 3 m), pairs between consecutive marks.
// All pairs: the j whose path length from i is nearest delta, within 10 % of
// it (2.5 m: 2 and 3 m are as near; the first, 2 m, is off by 20 %: none;
// 2.8 m: 3 m, off by 0.2 m, within 0.28 m, for i = 0..7).
TEST(TrajectoryEvalMetrics, RelativePosePairsByDistance) {
  const Trajectory line = straightLine(11, 1.0);  // 0, 1, ..., 10 m
  EXPECT_EQ(pairsByDistance(line, 3.0, false), (IndexPairs{{3, 6}, {6, 9}}));
  EXPECT_TRUE(pairsByDistance(line, 2.5, true).empty());
  const IndexPairs all = pairsByDistance(line, 2.8, true);
  ASSERT_EQ(all.size(), 8u);
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], (std::pair<std::size_t, std::size_t>{i, i + 3}));
}

// The step is measured along the estimate's path by default (evo's rule): an
// estimate 2x too long reaches 4 m after 2 true metres.
TEST(TrajectoryEvalMetrics, RelativePoseStepFollowsTheChosenPath) {
  const Trajectory truth = straightLine(11, 1.0);
  const Trajectory estimate = straightLine(11, 2.0);
  TrajectoryMetricsOptions options;
  options.rpeDelta_m = 4.0;
  const TrajectoryMetrics alongEstimate = computeTrajectoryMetrics({estimate, truth}, options);
  options.rpePath = RpePath::kTruth;
  const TrajectoryMetrics alongTruth = computeTrajectoryMetrics({estimate, truth}, options);
  EXPECT_EQ(alongEstimate.rpeDistanceTranslation_m.count, 4u);  // marks 2, 4, 6, 8, 10
  EXPECT_EQ(alongTruth.rpeDistanceTranslation_m.count, 1u);     // marks 4, 8
  EXPECT_NEAR(alongEstimate.rpeDistanceTranslation_m.rmse, 2.0, 1e-12);
  EXPECT_NEAR(alongTruth.rpeDistanceTranslation_m.rmse, 4.0, 1e-12);
}

TEST(TrajectoryEvalMetrics, KittiDriftOfAStraightLineWithOnePercentScaleError) {
  // 1000 m in 1 m steps; the estimate 1 % too long. The devkit ends a segment of
  // length L at the first frame strictly beyond L, i.e. L + 1 m along, and divides
  // by L: each segment's error is 1 % (L + 1) / L, with no rotation error.
  const Trajectory truth = straightLine(1001, 1.0);
  const Trajectory estimate = straightLine(1001, 1.01);
  const KittiDrift drift = kittiDrift(estimate, truth, kittiSegmentLengths());
  ASSERT_EQ(drift.perLength.size(), 8u);
  double weightedSum = 0.0;
  std::size_t segments = 0;
  for (const DriftAtLength& d : drift.perLength) {
    const double length = d.length_m;
    // Starts 0, 10, 20, ... with start + L + 1 <= 1000.
    const auto expectedSegments = static_cast<std::size_t>((999.0 - length) / 10.0) + 1;
    EXPECT_EQ(d.segments, expectedSegments) << length;
    EXPECT_NEAR(d.translation_percent, (length + 1.0) / length, 1e-9) << length;
    EXPECT_NEAR(d.rotation_deg_per_100m, 0.0, 1e-12);
    weightedSum += (length + 1.0) / length * static_cast<double>(expectedSegments);
    segments += expectedSegments;
  }
  EXPECT_EQ(drift.segments, segments);
  EXPECT_NEAR(drift.translation_percent, weightedSum / static_cast<double>(segments), 1e-9);
  EXPECT_NEAR(drift.translation_percent, 1.00, 0.005);  // 1.00 % to the devkit's printed precision
}

TEST(TrajectoryEvalMetrics, ShortTruthUsesOnlyTheLengthsThatFit) {
  const Trajectory truth = straightLine(151, 1.0);  // 150 m: only 100 m segments fit
  const TrajectoryMetrics m = computeTrajectoryMetrics({straightLine(151, 1.02), truth});
  ASSERT_EQ(m.drift.perLength.size(), 1u);
  EXPECT_EQ(m.drift.perLength[0].length_m, 100.0);
  const nlohmann::json json = toJson(m);
  EXPECT_EQ(json["drift_lengths_m"], nlohmann::json::array({100.0}));
  EXPECT_NEAR(json["drift_percent"].get<double>(), 2.0 * 101.0 / 100.0, 1e-9);

  const TrajectoryMetrics tooShort = computeTrajectoryMetrics({straightLine(51, 1.02), straightLine(51, 1.0)});
  EXPECT_TRUE(std::isnan(tooShort.drift.translation_percent));
  const nlohmann::json none = toJson(tooShort);
  EXPECT_TRUE(none["drift_percent"].is_null());
  EXPECT_TRUE(none["drift_lengths_m"].is_null());
  EXPECT_NEAR(none["scale_error_percent"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(none["final_position_error_m"].get<double>(), 1.0, 1e-9);  // 51 m against 50 m
}

TEST(TrajectoryEvalMetrics, JsonHasTheReportedKeys) {
  const nlohmann::json json = toJson(computeTrajectoryMetrics({climbingTurn(100), climbingTurn(100)}));
  for (const char* key :
       {"frames", "distance_m", "ate_rmse_m", "ate_sim3_rmse_m", "rpe_trans_rmse_m", "rpe_rot_rmse_deg",
        "drift_percent", "drift_deg_per_100m", "scale_error_percent", "sim3_scale", "final_position_error_m"})
    EXPECT_TRUE(json.contains(key)) << key;
}

TEST(TrajectoryEvalFiles, TumRoundTrip) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal;
  Trajectory written;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized();
    written.add(1e9 + 0.05 * i, pose(q.matrix(), Eigen::Vector3d(normal(random), normal(random), normal(random))));
  }
  const std::filesystem::path file = emptyFolder("tum") / "poses.txt";
  writeTumTrajectory(file, written);
  EXPECT_EQ(detectPoseFileFormat(file), PoseFileFormat::kTum);
  const Trajectory read = readTumTrajectory(file);
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read.times_s[i], written.times_s[i]);
    EXPECT_TRUE(read.worldFromCamera[i].isApprox(written.worldFromCamera[i], 1e-14)) << i;
  }
}

TEST(TrajectoryEvalFiles, KittiRoundTripWithAndWithoutTimes) {
  const Trajectory written = climbingTurn(20);
  const std::filesystem::path folder = emptyFolder("kitti");
  writeKittiTrajectory(folder / "poses.txt", written);
  std::ofstream(folder / "times.txt") << "0.5\n0.6\n" << std::string(18, '\n');
  EXPECT_EQ(detectPoseFileFormat(folder / "poses.txt"), PoseFileFormat::kKitti);
  const Trajectory byIndex = readKittiTrajectory(folder / "poses.txt");
  ASSERT_EQ(byIndex.size(), 20u);
  for (std::size_t i = 0; i < byIndex.size(); ++i) {
    EXPECT_EQ(byIndex.times_s[i], static_cast<double>(i));
    EXPECT_TRUE(byIndex.worldFromCamera[i].isApprox(written.worldFromCamera[i], 1e-14)) << i;
  }
  // 2 times for 20 poses.
  EXPECT_THROW(readKittiTrajectory(folder / "poses.txt", folder / "times.txt"), Error);
  std::ofstream times(folder / "times.txt");
  for (int i = 0; i < 20; ++i) times << 0.1 * i << '\n';
  times.close();
  EXPECT_DOUBLE_EQ(readKittiTrajectory(folder / "poses.txt", folder / "times.txt").times_s[19], 1.9);
}

TEST(TrajectoryEvalFiles, TumQuaternionIsNormalisedAndCommentsSkipped) {
  const std::filesystem::path file = emptyFolder("tum_norm") / "poses.txt";
  std::ofstream(file) << "# t tx ty tz qx qy qz qw\n\n1.5 1 2 3 0 0 0 2  # scaled identity\n";
  const Trajectory t = readTumTrajectory(file);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_TRUE(t.worldFromCamera[0].linear().isApprox(Eigen::Matrix3d::Identity(), 1e-15));
  EXPECT_EQ(t.worldFromCamera[0].translation(), Eigen::Vector3d(1, 2, 3));
}

// The message of the lrsvo::Error that reading `text` as `format` throws.
std::string readError(const std::string& text, PoseFileFormat format) {
  const std::filesystem::path file = emptyFolder("bad") / "bad_poses.txt";
  std::ofstream(file) << text;
  try {
    if (format == PoseFileFormat::kTum)
      readTumTrajectory(file);
    else
      readKittiTrajectory(file);
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), file.string());
    return e.what();
  }
  return "no error";
}

TEST(TrajectoryEvalFiles, MalformedLinesNameFileAndLine) {
  const std::string good = "0 0 0 0 0 0 0 1\n";
  EXPECT_NE(readError(good + "# c\n1 2 3\n", PoseFileFormat::kTum).find("bad_poses.txt:3: 3 numbers, expected 8"),
            std::string::npos);
  EXPECT_NE(readError(good + "1 0 0 x 0 0 0 1\n", PoseFileFormat::kTum).find(":2: 'x' is not a number"),
            std::string::npos);
  EXPECT_NE(readError(good + "1 0 nan 0 0 0 0 1\n", PoseFileFormat::kTum).find(":2: 'nan': expected a finite"),
            std::string::npos);
  EXPECT_NE(readError("1 0 0 0 0 0 0 0\n", PoseFileFormat::kTum).find(":1: zero quaternion"), std::string::npos);
  EXPECT_NE(readError("2 0 0 0 0 1 0 0 0 0 1 0\n", PoseFileFormat::kKitti).find(":1: the 3x3 part is not a rotation"),
            std::string::npos);
  EXPECT_NE(readError("1 0 0 0 0 1 0 0 0 0 1\n", PoseFileFormat::kKitti).find(":1: 11 numbers, expected 12"),
            std::string::npos);
  EXPECT_THROW(poseFileFormatFromName("euroc"), Error);
}

TEST(TrajectoryEvalAssociation, JitteredTimesMatchTheirOwnPose) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> jitter(-0.009, 0.009);
  const Trajectory truth = climbingTurn(100);  // 10 Hz
  Trajectory estimate;
  for (std::size_t i = 0; i < truth.size(); ++i)
    if (i % 7 != 3) estimate.add(truth.times_s[i] + jitter(random), truth.worldFromCamera[i]);
  estimate.add(50.0, Eigen::Isometry3d::Identity());  // far from every true stamp
  const AssociatedTrajectories matched = associateByTime(estimate, truth, 0.02);
  ASSERT_EQ(matched.estimate.size(), estimate.size() - 1);
  for (std::size_t k = 0; k < matched.estimate.size(); ++k) {
    EXPECT_NEAR(matched.estimate.times_s[k], matched.truth.times_s[k], 0.009);
    EXPECT_TRUE(matched.estimate.worldFromCamera[k].isApprox(matched.truth.worldFromCamera[k], 1e-15)) << k;
  }
}

TEST(TrajectoryEvalAssociation, EachPoseMatchesOnceClosestFirst) {
  Trajectory truth, estimate;
  truth.add(1.0, Eigen::Isometry3d::Identity());
  truth.add(2.0, Eigen::Isometry3d::Identity());
  estimate.add(0.99, Eigen::Isometry3d::Identity());
  estimate.add(1.005, Eigen::Isometry3d::Identity());  // closer to 1.0: takes it from 0.99
  estimate.add(1.97, Eigen::Isometry3d::Identity());   // 0.03 s from 2.0: beyond 0.02 s
  const AssociatedTrajectories matched = associateByTime(estimate, truth, 0.02);
  ASSERT_EQ(matched.estimate.size(), 1u);
  EXPECT_EQ(matched.estimate.times_s[0], 1.005);
  EXPECT_EQ(matched.truth.times_s[0], 1.0);
  EXPECT_EQ(associateByTime(estimate, truth, 0.05).estimate.size(), 2u);
  EXPECT_THROW(associateByIndex(estimate, truth), Error);
}

// ORB-SLAM2 stereo's published trajectory of KITTI 00 against the truth. Its
// paper (Mur-Artal & Tardos 2017, Table 2) prints t_rel 0.70 %, r_rel 0.25 deg/100 m
// and ATE RMSE 1.3 m; the devkit's and evo's definitions must give those.
TEST(TrajectoryEvalKitti00, MatchesOrbSlam2PublishedNumbers) {
  const std::string folder = std::string(LRSVO_SHARED_DATA) + "/kitti00_poses/";
  if (!std::filesystem::exists(folder + "KITTI_00_gt.txt")) GTEST_SKIP() << "no " << folder;
  const Trajectory truth = readKittiTrajectory(folder + "KITTI_00_gt.txt", folder + "KITTI_00_gt_times.txt");
  const Trajectory estimate = readKittiTrajectory(folder + "KITTI_00_ORB.txt", folder + "KITTI_00_gt_times.txt");
  const TrajectoryMetrics m = computeTrajectoryMetrics(associateByIndex(estimate, truth));
  EXPECT_EQ(m.frames, 4541u);
  EXPECT_NEAR(m.distance_m, 3724.2, 0.1);  // KITTI 00 is 3.7 km
  EXPECT_NEAR(m.drift.translation_percent, 0.70, 0.05);
  EXPECT_NEAR(m.drift.rotation_deg_per_100m, 0.25, 0.05);
  EXPECT_NEAR(m.ate_m.rmse, 1.3, 0.2);
}

// evo_rpe on the same files, `--delta 10 --delta_unit m` (consecutive pairs along
// the estimate's path), prints RMSE 0.2263 m over 353 pairs; it rounds to 4
// digits, so ours is within half a unit of the last one.
TEST(TrajectoryEvalKitti00, RelativePoseErrorOverTenMetresMatchesEvo) {
  const std::string folder = std::string(LRSVO_SHARED_DATA) + "/kitti00_poses/";
  if (!std::filesystem::exists(folder + "KITTI_00_gt.txt")) GTEST_SKIP() << "no " << folder;
  const Trajectory truth = readKittiTrajectory(folder + "KITTI_00_gt.txt", folder + "KITTI_00_gt_times.txt");
  const Trajectory estimate = readKittiTrajectory(folder + "KITTI_00_ORB.txt", folder + "KITTI_00_gt_times.txt");
  TrajectoryMetricsOptions options;
  options.rpeDelta_m = 10.0;
  const TrajectoryMetrics m = computeTrajectoryMetrics(associateByIndex(estimate, truth), options);
  EXPECT_EQ(m.rpeDistanceTranslation_m.count, 353u);
  EXPECT_NEAR(m.rpeDistanceTranslation_m.rmse, 0.2263, 0.5e-4);
}

}  // namespace
}  // namespace lrsvo

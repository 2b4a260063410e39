// Frames whose images cannot be used: the frame check on its own, then whole
// runs on the real EuRoC frames with one frame broken in each way a data set
// breaks (missing, truncated, blank, wrongly sized, left out of one camera's
// list); stereo pairs matched by time.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lrsvo/frontend/datasets/euroc_reader.h"
#include "lrsvo/frontend/features/frame_check.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/graph/error.h"
#include "unit_tests/shared_data.h"
#include "unit_tests/temp_folder.h"

namespace lrsvo {
namespace {

namespace fs = std::filesystem;

Rig twoCameraRig(int width, int height) {
  Rig rig;
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.intrinsics = {400.0, 400.0, width / 2.0, height / 2.0};
  rig.cameras = {camera, camera};
  rig.extrinsics = {(VertexStereoExtrinsic::Vector6() << 0.1, 0, 0, 0, 0, 0).finished()};
  return rig;
}

cv::Mat texturedImage(int width, int height, std::uint64_t seed) {
  cv::Mat image(height, width, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

StereoFrame frameOf(cv::Mat base, cv::Mat secondary) {
  StereoFrame frame;
  frame.images = {std::move(base), std::move(secondary)};
  return frame;
}

TEST(FrameCheck, TexturedImagesOfTheCalibratedSizePass) {
  const Rig rig = twoCameraRig(64, 48);
  EXPECT_EQ(frameDefect(frameOf(texturedImage(64, 48, 1), texturedImage(64, 48, 2)), rig), "");
}

TEST(FrameCheck, SaysWhatIsWrongWithEachKindOfBadFrame) {
  const Rig rig = twoCameraRig(64, 48);
  const cv::Mat good = texturedImage(64, 48, 3);
  EXPECT_NE(frameDefect(frameOf(good, cv::Mat()), rig).find("camera 1: no image"), std::string::npos);
  EXPECT_NE(frameDefect(frameOf(texturedImage(32, 48, 4), good), rig).find("camera 0: the image is 32x48"),
            std::string::npos);
  EXPECT_NE(frameDefect(frameOf(good, cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(9))), rig).find("8-bit grey"),
            std::string::npos);
  EXPECT_NE(frameDefect(frameOf(cv::Mat(48, 64, CV_8UC1, cv::Scalar(0)), good), rig).find("camera 0: a blank image"),
            std::string::npos);
  StereoFrame one = frameOf(good, good);
  one.images.pop_back();
  EXPECT_NE(frameDefect(one, rig).find("1 images for a rig of 2 cameras"), std::string::npos);
  StereoFrame unread = frameOf(good, good);
  unread.defect = "cannot read image x.png";
  EXPECT_EQ(frameDefect(unread, rig), "cannot read image x.png");
}

// Blank means less spread than sensor noise alone gives: a uniform frame with
// noise of std 0.5 is blank, one with std 3 (a dim but live sensor) is not.
TEST(FrameCheck, BlankIsLessSpreadThanSensorNoise) {
  const Rig rig = twoCameraRig(64, 48);
  const cv::Mat good = texturedImage(64, 48, 5);
  for (const auto& [sigma, blank] : std::vector<std::pair<double, bool>>{{0.5, true}, {3.0, false}}) {
    cv::Mat noisy(48, 64, CV_8UC1);
    cv::RNG rng(6);
    rng.fill(noisy, cv::RNG::NORMAL, 40, sigma);
    const std::string defect = frameDefect(frameOf(noisy, good), rig);
    EXPECT_EQ(defect.find("blank") != std::string::npos, blank) << "sigma " << sigma << ": " << defect;
  }
}

// A copy of the EuRoC frames whose images are links to the originals, so that
// one of them can be replaced.
fs::path linkedEurocCopy(const std::string& name) {
  const fs::path copy = test::freshFolder(name);
  const fs::path source(test::kEuroc);
  for (const char* camera : {"cam0", "cam1"}) {
    const fs::path from = source / "mav0" / camera, to = copy / "mav0" / camera;
    fs::create_directories(to / "data");
    fs::copy_file(from / "sensor.yaml", to / "sensor.yaml");
    fs::copy_file(from / "data.csv", to / "data.csv");
    for (const auto& entry : fs::directory_iterator(from / "data"))
      fs::create_symlink(fs::absolute(entry.path()), to / "data" / entry.path().filename());
  }
  fs::copy_file(source / "groundtruth_body_tum.txt", copy / "groundtruth_body_tum.txt");
  return copy;
}

// The image file of a camera's n-th frame (data.csv order).
fs::path imageOf(const fs::path& sequence, const char* camera, int n) {
  std::vector<fs::path> images;
  for (const auto& entry : fs::directory_iterator(sequence / "mav0" / camera / "data")) images.push_back(entry.path());
  std::sort(images.begin(), images.end());
  return images.at(static_cast<std::size_t>(n));
}

enum class Breakage { kMissing, kTruncated, kBlank, kWrongSize, kUnlisted };

// Rewrites a camera's data.csv, each row through `edit` (a row it returns
// empty is left out).
template <typename Edit>
void editImageList(const fs::path& camera, Edit edit) {
  std::vector<std::string> rows;
  {
    std::ifstream in(camera / "data.csv");
    for (std::string row; std::getline(in, row);) rows.push_back(row[0] == '#' ? row : edit(row));
  }
  std::ofstream out(camera / "data.csv");
  for (const std::string& row : rows)
    if (!row.empty()) out << row << '\n';
}

// Replaces the image with a broken one; returns what frames.csv should say.
std::string breakImage(const fs::path& image, Breakage breakage) {
  if (breakage == Breakage::kUnlisted) {
    const std::string file = image.filename().string();
    editImageList(image.parent_path().parent_path(),
                  [&](const std::string& row) { return row.find(file) == std::string::npos ? row : std::string(); });
    return image.parent_path().parent_path().filename() == "cam0" ? "no cam0 image" : "no cam1 image";
  }
  const cv::Mat original = cv::imread(image.string(), cv::IMREAD_GRAYSCALE);
  std::ifstream in(image, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(image);
  switch (breakage) {
    case Breakage::kMissing: return "cannot read image";
    case Breakage::kTruncated:
      std::ofstream(image, std::ios::binary) << bytes.substr(0, bytes.size() / 3);
      return "cannot read image";
    case Breakage::kBlank:
      cv::imwrite(image.string(), cv::Mat(original.size(), CV_8UC1, cv::Scalar(255)));
      return "a blank image";
    case Breakage::kUnlisted: break;
    case Breakage::kWrongSize: {
      cv::Mat half;
      cv::resize(original, half, original.size() / 2);
      cv::imwrite(image.string(), half);
      return "sensor.yaml says 752x480";
    }
  }
  return "";
}

// The frames.csv row of frame n, split at commas.
std::vector<std::string> framesCsvRow(const fs::path& out, int n) {
  std::ifstream in(out / "frames.csv");
  std::string line;
  for (int i = 0; i <= n + 1 && std::getline(in, line); ++i) {
  }
  std::vector<std::string> fields;
  std::stringstream row(line);
  for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
  return fields;
}

class BadEurocFrame : public testing::TestWithParam<std::tuple<Breakage, const char*>> {};

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

// One broken image in the middle of the sequence: its frame gets no pose and
// says why, every other frame is posed as on the whole sequence, in one
// segment. The progress stream gives the segment's start and the bad frame a
// line each.
TEST_P(BadEurocFrame, IsSkippedAndTheRunGoesOn) {
  const auto [breakage, camera] = GetParam();
  const int bad = 47;
  const fs::path sequence = linkedEurocCopy("bad_frame");
  const std::string expected = breakImage(imageOf(sequence, camera, bad), breakage);
  EurocSource source(sequence.string());
  RunOptions options;
  options.outDir = sequence / "out";
  options.frontEnd.stereo.minDepth_m = 0.5;
  std::ostringstream progress;
  options.progress = &progress;
  const RunResult run = runOdometry(source, options);
  const std::string lines = progress.str();
  EXPECT_EQ(occurrences(lines, "\nframe 0: stereo start at a median depth of "), 1u) << lines;
  EXPECT_EQ(occurrences(lines, ": stereo start"), 1u) << lines;
  EXPECT_EQ(occurrences(lines, "\nframe " + std::to_string(bad) + " skipped: "), 1u) << lines;
  EXPECT_EQ(run.totals.frames, source.frameCount());
  EXPECT_EQ(run.totals.badFrames, 1);
  EXPECT_EQ(run.segments.at(bad), -1);
  EXPECT_EQ(run.totals.segments, 1);
  EXPECT_EQ(run.totals.tracked, run.totals.frames - 1);

  const std::vector<std::string> row = framesCsvRow(options.outDir, bad);
  ASSERT_EQ(row.size(), 28u);
  EXPECT_EQ(row[0], std::to_string(bad));
  EXPECT_EQ(row[26], "bad_frame");
  EXPECT_NE(row[27].find(expected), std::string::npos) << row[27];
  fs::remove_all(sequence);
}

std::string breakageName(const testing::TestParamInfo<BadEurocFrame::ParamType>& info) {
  constexpr const char* kNames[] = {"Missing", "Truncated", "Blank", "WrongSize", "Unlisted"};
  return std::string(kNames[static_cast<int>(std::get<0>(info.param))]) + "In" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(
    EachKind, BadEurocFrame,
    testing::Values(std::make_tuple(Breakage::kMissing, "cam0"), std::make_tuple(Breakage::kTruncated, "cam1"),
                    std::make_tuple(Breakage::kBlank, "cam0"), std::make_tuple(Breakage::kWrongSize, "cam1"),
                    std::make_tuple(Breakage::kUnlisted, "cam0"), std::make_tuple(Breakage::kUnlisted, "cam1")),
    breakageName);

// Every image's timestamp in one camera's data.csv moved by `shift_ns`.
void shiftTimestamps(const fs::path& camera, long long shift_ns) {
  editImageList(camera, [&](const std::string& row) {
    const std::size_t comma = row.find(',');
    return std::to_string(std::stoll(row.substr(0, comma)) + shift_ns) + row.substr(comma);
  });
}

// Stereo pairs match by time within the tolerance, whichever camera's clock
// runs ahead; past it no image pairs, and the error says so.
TEST(EurocSource, PairsStereoImagesWithinTheSyncTolerance) {
  const long long tolerance = EurocSource::kStereoSyncTolerance_ns;
  const fs::path sequence = linkedEurocCopy("stereo_sync");
  for (long long shift : {tolerance / 4, -tolerance}) {
    SCOPED_TRACE(shift);
    EurocSource reference(sequence.string());
    shiftTimestamps(sequence / "mav0" / "cam1", shift);
    EurocSource shifted(sequence.string());
    ASSERT_EQ(shifted.frameCount(), reference.frameCount());
    for (int i = 0; i < reference.frameCount(); ++i) {
      const std::optional<StereoFrame> a = reference.next(), b = shifted.next();
      ASSERT_TRUE(a && b);
      EXPECT_EQ(b->defect, "") << i;
      EXPECT_EQ(b->time_s, a->time_s) << i;  // cam0's time
    }
    shiftTimestamps(sequence / "mav0" / "cam1", -shift);
  }
  shiftTimestamps(sequence / "mav0" / "cam1", tolerance + 1);
  try {
    EurocSource source(sequence.string());
    ADD_FAILURE() << "no image pairs, but no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("no cam0 image has a cam1 image within 1000 us"), std::string::npos)
        << error.what();
  }
  fs::remove_all(sequence);
}

TEST(BadEurocFrameStop, EndsTheRunNamingTheFrame) {
  const fs::path sequence = linkedEurocCopy("bad_frame_stop");
  breakImage(imageOf(sequence, "cam0", 12), Breakage::kMissing);
  EurocSource source(sequence.string());
  RunOptions options;
  options.frontEnd.stereo.minDepth_m = 0.5;
  options.onBadFrame = BadFramePolicy::kStop;
  try {
    runOdometry(source, options);
    ADD_FAILURE() << "a missing image with --on-bad-frame stop did not end the run";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("frame 12: cannot read image"), std::string::npos) << error.what();
  }
  fs::remove_all(sequence);
}

}  // namespace
}  // namespace lrsvo

#include "lrsvo/frontend/datasets/bal_problem.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string_view>
#include <system_error>

#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

namespace {

std::string readWholeFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw Error("BAL file '" + path + "' does not exist");
  if (!std::filesystem::is_regular_file(path, error)) throw Error("BAL file '" + path + "' is not a regular file");
  std::ifstream in(path, std::ios::binary);
  const auto size = std::filesystem::file_size(path, error);
  if (!in || error) throw Error("cannot open BAL file '" + path + "'");
  std::string text(size, '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(size))) throw Error("cannot read BAL file '" + path + "'");
  return text;
}

bool isBlank(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Whitespace-separated tokens of a text, each with the 1-based line it sits
// on, parsed with std::from_chars (BAL files reach 10^7 numbers).
class TokenReader {
 public:
  TokenReader(const std::string& path, std::string_view text) : path_(path), text_(text) {}

  // Errors name the line of the last token read, so an early end of the
  // file names the last line that holds something.
  [[noreturn]] void fail(const std::string& message) const { throw ParseError(path_, tokenLine_, message); }

  [[noreturn]] void failAtNextToken(const std::string& message) {
    skipWhitespace();
    tokenLine_ = currentLine_;
    fail(message);
  }

  bool atEnd() {
    skipWhitespace();
    return position_ == text_.size();
  }

  // `what` and `index` say what the value is, for messages ("camera", 3).
  double readReal(const char* what, long long index) {
    const std::string_view token = next(what, index);
    // from_chars takes no leading '+', which some writers emit.
    const std::string_view digits = token.size() > 1 && token[0] == '+' ? token.substr(1) : token;
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range)
      fail("number '" + std::string(token) + "' out of the range of a double in " + describe(what, index));
    if (error != std::errc() || end != digits.data() + digits.size())
      fail("malformed number '" + std::string(token) + "' in " + describe(what, index));
    if (!std::isfinite(value)) fail("non-finite value '" + std::string(token) + "' in " + describe(what, index));
    return value;
  }

  long long readInteger(const char* what, long long index) {
    const std::string_view token = next(what, index);
    long long value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      fail("malformed integer '" + std::string(token) + "' in " + describe(what, index));
    return value;
  }

 private:
  static std::string describe(const char* what, long long index) {
    return index < 0 ? std::string(what) : std::string(what) + " " + std::to_string(index);
  }

  void skipWhitespace() {
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (!isBlank(c)) return;
      if (c == '\n') ++currentLine_;
      ++position_;
    }
  }

  std::string_view next(const char* what, long long index) {
    if (atEnd()) fail("the file ends early: " + describe(what, index) + " is missing");
    tokenLine_ = currentLine_;
    const std::size_t start = position_;
    while (position_ < text_.size() && !isBlank(text_[position_])) ++position_;
    return text_.substr(start, position_ - start);
  }

  const std::string& path_;
  std::string_view text_;
  std::size_t position_ = 0;
  int currentLine_ = 1;
  int tokenLine_ = 1;
};

int readCount(TokenReader& reader, const char* what) {
  const long long count = reader.readInteger(what, -1);
  if (count <= 0 || count > std::numeric_limits<int>::max())
    reader.fail(std::string(what) + " must be a positive int, got " + std::to_string(count));
  return static_cast<int>(count);
}

// `what` is "camera" or "point"; `slot` describes the value, e.g. "camera index of observation".
int readIndex(TokenReader& reader, const char* what, const char* slot, long long observation, int count) {
  const long long index = reader.readInteger(slot, observation);
  if (index < 0 || index >= count)
    reader.fail("observation " + std::to_string(observation) + " names " + what + " " + std::to_string(index) +
                ", outside 0.." + std::to_string(count - 1));
  return static_cast<int>(index);
}

void appendNumber(std::string& out, double value) {
  char buffer[32];
  // Scientific with 16 decimals: 17 significant digits, enough for an exact round trip.
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific, 16);
  out.append(buffer, result.ptr);
}

void appendInteger(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void checkProblem(const BalProblem& problem) {
  const auto cameras = static_cast<long long>(problem.cameras.size());
  const auto points = static_cast<long long>(problem.points.size());
  if (cameras + points > std::numeric_limits<int>::max()) throw Error("BAL problem: too many cameras and points");
  for (std::size_t i = 0; i < problem.observations.size(); ++i) {
    const BalObservation& o = problem.observations[i];
    if (o.camera < 0 || o.camera >= cameras || o.point < 0 || o.point >= points)
      throw Error("BAL problem: observation " + std::to_string(i) + " names camera " + std::to_string(o.camera) +
                  " and point " + std::to_string(o.point) + ", outside the problem's " + std::to_string(cameras) +
                  " cameras and " + std::to_string(points) + " points");
  }
}

}  // namespace

BalProblem readBal(const std::string& path) {
  const std::string text = readWholeFile(path);
  TokenReader reader(path, text);
  const int cameraCount = readCount(reader, "the camera count");
  const int pointCount = readCount(reader, "the point count");
  const int observationCount = readCount(reader, "the observation count");

  // Reserve no more than the text can hold, so a lying header cannot exhaust memory.
  const auto capacity = [&](int count, std::size_t minimumBytes) {
    return std::min<std::size_t>(count, text.size() / minimumBytes + 1);
  };
  BalProblem problem;
  problem.observations.reserve(capacity(observationCount, 8));
  for (int i = 0; i < observationCount; ++i) {
    BalObservation o;
    o.camera = readIndex(reader, "camera", "camera index of observation", i, cameraCount);
    o.point = readIndex(reader, "point", "point index of observation", i, pointCount);
    o.pixel.x() = reader.readReal("observation", i);
    o.pixel.y() = reader.readReal("observation", i);
    problem.observations.push_back(o);
  }
  problem.cameras.reserve(capacity(cameraCount, 18));
  for (int i = 0; i < cameraCount; ++i) {
    Eigen::Matrix<double, 9, 1> camera;
    for (int k = 0; k < 9; ++k) camera[k] = reader.readReal("camera", i);
    problem.cameras.push_back(camera);
  }
  problem.points.reserve(capacity(pointCount, 6));
  for (int i = 0; i < pointCount; ++i) {
    Eigen::Vector3d point;
    for (int k = 0; k < 3; ++k) point[k] = reader.readReal("point", i);
    problem.points.push_back(point);
  }

  if (!reader.atEnd())
    reader.failAtNextToken("trailing content after the last point (the header promises " + std::to_string(cameraCount) +
                           " cameras, " + std::to_string(pointCount) + " points, " + std::to_string(observationCount) +
                           " observations)");
  return problem;
}

void writeBal(const BalProblem& problem, const std::string& path) {
  checkProblem(problem);
  std::string out;
  out.reserve(64 * problem.observations.size() + 24 * (9 * problem.cameras.size() + 3 * problem.points.size()) + 64);
  appendInteger(out, static_cast<long long>(problem.cameras.size()));
  out += ' ';
  appendInteger(out, static_cast<long long>(problem.points.size()));
  out += ' ';
  appendInteger(out, static_cast<long long>(problem.observations.size()));
  out += '\n';
  for (const BalObservation& o : problem.observations) {
    appendInteger(out, o.camera);
    out += ' ';
    appendInteger(out, o.point);
    out += ' ';
    appendNumber(out, o.pixel.x());
    out += ' ';
    appendNumber(out, o.pixel.y());
    out += '\n';
  }
  // One number per line for cameras and points, as the published BAL files.
  for (const auto& camera : problem.cameras)
    for (int k = 0; k < 9; ++k) {
      appendNumber(out, camera[k]);
      out += '\n';
    }
  for (const auto& point : problem.points)
    for (int k = 0; k < 3; ++k) {
      appendNumber(out, point[k]);
      out += '\n';
    }

  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw Error("cannot create BAL file '" + path + "'");
  file.write(out.data(), static_cast<std::streamsize>(out.size()));
  file.close();
  if (!file) throw Error("cannot write BAL file '" + path + "'");
}

Graph makeBalGraph(const BalProblem& problem, const std::string& kernel, double kernelDelta,
                   const std::function<std::unique_ptr<EdgeBalProjection>()>& makeEdge) {
  checkProblem(problem);
  const std::shared_ptr<RobustKernel> robustKernel = kernel.empty() ? nullptr : makeRobustKernel(kernel, kernelDelta);
  const int cameraCount = static_cast<int>(problem.cameras.size());
  Graph graph;
  std::vector<VertexBalCamera*> cameras(problem.cameras.size());
  std::vector<VertexPoint3*> points(problem.points.size());
  for (int i = 0; i < cameraCount; ++i) {
    cameras[i] = graph.addVertex(std::make_unique<VertexBalCamera>(i));
    cameras[i]->setEstimateVector(problem.cameras[i]);
  }
  for (std::size_t i = 0; i < problem.points.size(); ++i)
    points[i] = graph.addVertex(std::make_unique<VertexPoint3>(cameraCount + static_cast<int>(i), problem.points[i]));
  for (const BalObservation& o : problem.observations) {
    std::unique_ptr<EdgeBalProjection> edge = makeEdge ? makeEdge() : std::make_unique<EdgeBalProjection>();
    edge->setVertex(0, cameras[o.camera]);
    edge->setVertex(1, points[o.point]);
    edge->setMeasurement(o.pixel);
    edge->setRobustKernel(robustKernel);
    graph.addEdge(std::move(edge));
  }
  return graph;
}

void updateFromGraph(BalProblem& problem, const Graph& graph) {
  const int cameraCount = static_cast<int>(problem.cameras.size());
  auto vertexOf = [&](int id, const char* type) {
    const Vertex* v = graph.vertex(id);
    if (!v) throw Error("updateFromGraph: the graph has no vertex " + std::to_string(id));
    if (std::string_view(v->typeTag()) != type)
      throw Error("updateFromGraph: vertex " + std::to_string(id) + " is a " + v->typeTag() + ", not a " + type);
    return v;
  };
  for (int i = 0; i < cameraCount; ++i)
    problem.cameras[i] = static_cast<const VertexBalCamera*>(vertexOf(i, VertexBalCamera::kTypeTag))->estimate();
  for (std::size_t i = 0; i < problem.points.size(); ++i)
    problem.points[i] =
        static_cast<const VertexPoint3*>(vertexOf(cameraCount + static_cast<int>(i), VertexPoint3::kTypeTag))
            ->estimate();
}

Eigen::Vector2d projectBal(const Eigen::Matrix<double, 9, 1>& camera, const Eigen::Vector3d& point) {
  const Eigen::Vector3d P = angleAxisRotate(camera.head<3>(), point) + camera.segment<3>(3);
  const Eigen::Vector2d p = -P.head<2>() / P.z();
  const double r2 = p.squaredNorm();
  return camera[6] * (1.0 + r2 * (camera[7] + camera[8] * r2)) * p;
}

double rmsReprojectionError(const BalProblem& problem) {
  if (problem.observations.empty()) return 0.0;
  checkProblem(problem);
  double sum = 0.0;
  for (const BalObservation& o : problem.observations)
    sum += (projectBal(problem.cameras[o.camera], problem.points[o.point]) - o.pixel).squaredNorm();
  return std::sqrt(sum / (2.0 * static_cast<double>(problem.observations.size())));
}

}  // namespace lrsvo

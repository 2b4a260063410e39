#include "lrsvo/sim/scenario.h"

#include <climits>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core/persistence.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;
using Kind = FlightLeg::Kind;

constexpr int kPaperFrames = 9600;

[[noreturn]] void fail(const std::string& where, const std::string& message) {
  throw Error("scenario " + where + ": " + message);
}

// The file's text. YAML is text: a NUL byte means a corrupt or binary file,
// on which OpenCV's YAML parser (4.6) can loop for ever, so it is rejected
// before parsing.
std::string readYamlText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("file " + path, "cannot be opened");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos)
    fail("file " + path, "is not a text file (a NUL byte at offset " + std::to_string(nul) + ")");
  return text;
}

// Reads the keys of one YAML map, each optional; finish() rejects any key
// that no accessor asked for.
class MapReader {
 public:
  MapReader(const cv::FileNode& node, std::string where) : node_(node), where_(std::move(where)) {
    if (!node_.empty() && !node_.isMap()) fail(where_, "must be a map of key: value");
  }
  cv::FileNode get(const std::string& key) {
    known_.insert(key);
    return node_.empty() ? cv::FileNode() : node_[key];
  }
  void real(const std::string& key, double& value) {
    const cv::FileNode n = get(key);
    if (n.empty()) return;
    if (!n.isReal() && !n.isInt()) fail(where_ + "." + key, "must be a number");
    value = static_cast<double>(n);
  }
  void integer(const std::string& key, int& value) {
    const cv::FileNode n = get(key);
    if (n.empty()) return;
    if (!n.isInt()) fail(where_ + "." + key, "must be an integer");
    value = static_cast<int>(n);
  }
  void seed(const std::string& key, std::uint64_t& value) {
    const cv::FileNode n = get(key);
    if (n.empty()) return;
    if (n.isInt() && static_cast<int>(n) >= 0) {
      value = static_cast<std::uint64_t>(static_cast<int>(n));
    } else if (n.isString()) {
      const std::string text = static_cast<std::string>(n);
      if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        fail(where_ + "." + key, "must be a non-negative integer, got '" + text + "'");
      value = std::stoull(text);
    } else {
      fail(where_ + "." + key, "must be a non-negative integer (as a number up to 2^31 - 1, or a string of digits)");
    }
  }
  void vector6(const std::string& key, Vector6& value) {
    const cv::FileNode n = get(key);
    if (n.empty()) return;
    if (!n.isSeq() || n.size() != 6) fail(where_ + "." + key, "must be a list of 6 numbers");
    for (int i = 0; i < 6; ++i) {
      if (!n[i].isReal() && !n[i].isInt()) fail(where_ + "." + key, "must be a list of 6 numbers");
      value[i] = static_cast<double>(n[i]);
    }
  }
  void finish() const {
    if (node_.empty()) return;
    for (const std::string& key : node_.keys())
      if (!known_.count(key)) fail(where_, "unknown key '" + key + "'");
  }

 private:
  cv::FileNode node_;
  std::string where_;
  std::set<std::string> known_;
};

// Reads `key` of a map as a list of maps, each by `read(reader, item)`,
// replacing `items` when the key is given.
template <typename Item, typename Read>
void readMapList(MapReader& parent, const std::string& key, const std::string& where, const char* what,
                 std::vector<Item>& items, Read read) {
  const cv::FileNode list = parent.get(key);
  if (list.empty()) return;
  if (!list.isSeq()) fail(where, std::string("must be a list of ") + what);
  items.clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string itemWhere = where + "[" + std::to_string(i) + "]";
    MapReader reader(list[static_cast<int>(i)], itemWhere);
    Item item;
    read(reader, item, itemWhere);
    reader.finish();
    items.push_back(item);
  }
}

const char* kindName(Kind kind) {
  switch (kind) {
    case Kind::Straight: return "straight";
    case Kind::Turn: return "turn";
    case Kind::Climb: return "climb";
  }
  return "straight";
}

Kind kindFromName(const std::string& name, const std::string& where) {
  if (name == "straight") return Kind::Straight;
  if (name == "turn") return Kind::Turn;
  if (name == "climb") return Kind::Climb;
  fail(where, "kind must be straight, turn or climb, got '" + name + "'");
}

void readFlight(const cv::FileNode& node, FlightOptions& f) {
  MapReader r(node, "flight");
  r.real("altitude_m", f.altitude_m);
  r.real("speed_m_s", f.speed_m_s);
  r.real("frameRate_hz", f.frameRate_hz);
  r.integer("frameStep", f.frameStep);
  r.real("attitudeNoise_rad", f.attitudeNoise_rad);
  r.real("transition_s", f.transition_s);
  r.seed("seed", f.seed);
  readMapList(r, "legs", "flight.legs", "legs", f.legs, [](MapReader& leg, FlightLeg& l, const std::string& where) {
    const cv::FileNode kind = leg.get("kind");
    if (kind.empty() || !kind.isString()) fail(where, "needs kind: straight, turn or climb");
    l.kind = kindFromName(static_cast<std::string>(kind), where);
    leg.real("length_m", l.length_m);
    leg.real("turnRate_rad_s", l.turnRate_rad_s);
    leg.real("climbRate_m_s", l.climbRate_m_s);
  });
  readMapList(r, "gusts", "flight.gusts", "gusts", f.gusts, [](MapReader& gust, AttitudeStep& g, const std::string&) {
    gust.real("time_s", g.time_s);
    gust.real("roll_rad", g.size_rad.x());
    gust.real("pitch_rad", g.size_rad.y());
    gust.real("yaw_rad", g.size_rad.z());
    gust.real("rise_s", g.rise_s);
    gust.real("hold_s", g.hold_s);
  });
  r.finish();
}

// Reads `key` of the faults as a list of frame indices, replacing `frames` when the key is given.
void readFrameList(MapReader& faults, const std::string& key, std::vector<int>& frames) {
  const cv::FileNode list = faults.get(key);
  if (list.empty()) return;
  const std::string where = "faults." + key;
  if (!list.isSeq()) fail(where, "must be a list of frame indices");
  frames.clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const cv::FileNode frame = list[static_cast<int>(i)];
    if (!frame.isInt()) fail(where, "must be a list of integer frame indices");
    frames.push_back(static_cast<int>(frame));
  }
}

void readFaults(const cv::FileNode& node, FrameFaults& faults) {
  MapReader r(node, "faults");
  readMapList(r, "exposureJumps", "faults.exposureJumps", "{frame, gain}", faults.exposureJumps,
              [](MapReader& jump, FrameFaults::ExposureJump& j, const std::string&) {
                jump.integer("frame", j.frame);
                jump.real("gain", j.gain);
              });
  readFrameList(r, "blankFrames", faults.blankFrames);
  readFrameList(r, "corruptFrames", faults.corruptFrames);
  readFrameList(r, "droppedFrames", faults.droppedFrames);
  r.finish();
  try {
    faults.validate();
  } catch (const Error& e) {
    fail("faults", e.what());
  }
}

void writeFrameList(cv::FileStorage& fs, const char* key, const std::vector<int>& frames) {
  fs << key << "[:";
  for (int frame : frames) fs << frame;
  fs << "]";
}

void readTerrain(const cv::FileNode& node, TerrainOptions& t) {
  MapReader r(node, "terrain");
  r.real("relief_m", t.relief_m);
  r.real("hillScale_m", t.hillScale_m);
  r.real("treeDensity_per_km2", t.treeDensity_per_km2);
  r.real("treeHeight_m", t.treeHeight_m);
  r.real("buildingDensity_per_km2", t.buildingDensity_per_km2);
  r.real("buildingHeight_m", t.buildingHeight_m);
  r.real("buildingSize_m", t.buildingSize_m);
  r.seed("seed", t.seed);
  r.finish();
}

void readRig(const cv::FileNode& node, Rig& rig) {
  MapReader r(node, "rig");
  readMapList(r, "cameras", "rig.cameras", "cameras", rig.cameras,
              [](MapReader& c, Camera& camera, const std::string&) {
                c.real("fx", camera.intrinsics.fx);
                c.real("fy", camera.intrinsics.fy);
                c.real("cx", camera.intrinsics.cx);
                c.real("cy", camera.intrinsics.cy);
                c.integer("width", camera.width);
                c.integer("height", camera.height);
              });
  const cv::FileNode extrinsics = r.get("extrinsics");
  if (!extrinsics.empty()) {
    if (!extrinsics.isSeq()) fail("rig.extrinsics", "must be a list of [x, y, z, roll, pitch, yaw]");
    rig.extrinsics.assign(extrinsics.size(), Vector6::Zero());
    for (std::size_t i = 0; i < extrinsics.size(); ++i) {
      const cv::FileNode e = extrinsics[static_cast<int>(i)];
      if (!e.isSeq() || e.size() != 6) fail("rig.extrinsics[" + std::to_string(i) + "]", "must be a list of 6 numbers");
      for (int j = 0; j < 6; ++j) {
        if (!e[j].isReal() && !e[j].isInt()) fail("rig.extrinsics[" + std::to_string(i) + "]", "must be numbers");
        rig.extrinsics[i][j] = static_cast<double>(e[j]);
      }
    }
  }
  r.vector6("tolerance", rig.tolerance);
  r.finish();
}

void readDeformation(const cv::FileNode& node, DeformationOptions& d) {
  MapReader r(node, "deformation");
  r.vector6("drift", d.drift);
  r.real("driftPeriod_s", d.driftPeriod_s);
  r.vector6("vibration", d.vibration);
  r.vector6("offset", d.offset);
  r.seed("seed", d.seed);
  r.finish();
}

void readTexture(const cv::FileNode& node, GroundTextureOptions& t) {
  MapReader r(node, "texture");
  r.real("fieldSize_m", t.fieldSize_m);
  r.real("trackProbability", t.trackProbability);
  r.real("hedgeProbability", t.hedgeProbability);
  r.real("grainContrast", t.grainContrast);
  r.seed("seed", t.seed);
  r.finish();
}

void readRender(const cv::FileNode& node, RenderOptions& o) {
  MapReader r(node, "render");
  r.real("noiseSigma_grey", o.noiseSigma_grey);
  r.real("blurSigma_px", o.blurSigma_px);
  r.real("exposureDrift", o.exposureDrift);
  r.real("exposurePeriod_s", o.exposurePeriod_s);
  r.real("vignetting", o.vignetting);
  r.integer("threads", o.threads);
  r.finish();
}

void writeSeed(cv::FileStorage& fs, const char* key, std::uint64_t seed) {
  fs << key;
  if (seed <= static_cast<std::uint64_t>(INT_MAX))
    fs << static_cast<int>(seed);
  else
    fs << std::to_string(seed);
}

void writeVector6(cv::FileStorage& fs, const char* key, const Vector6& v) {
  fs << key << "[:";
  for (int i = 0; i < 6; ++i) fs << v[i];
  fs << "]";
}

}  // namespace

FeatureSimulationOptions featureSimulationOptions(const SimScenario& scenario, int pointsPerFrame,
                                                  double pixelNoise_px) {
  FeatureSimulationOptions options;
  options.flight = scenario.flight;
  options.terrain = scenario.terrain;
  options.rig = scenario.rig;
  options.deformation = scenario.deformation;
  options.pointsPerFrame = pointsPerFrame;
  options.pixelNoise_px = pixelNoise_px;
  options.seed = scenario.seed;
  return options;
}

SimScenario demoScenario() {
  SimScenario s;
  s.name = "demo";
  s.flight.altitude_m = 100.0;
  s.flight.speed_m_s = 20.0;
  s.flight.frameRate_hz = 30.0;
  s.flight.attitudeNoise_rad = 0.005;
  s.flight.legs = {{Kind::Straight, 250.0}, {Kind::Turn, 150.0, 0.06}, {Kind::Straight, 100.0}};
  return s;
}

SimScenario paperScenario() {
  SimScenario s;
  s.name = "paper";
  s.flight.altitude_m = 60.0;
  s.flight.speed_m_s = 20.0;
  s.flight.frameRate_hz = 30.0;
  s.flight.attitudeNoise_rad = 0.01;
  s.flight.legs = {{Kind::Straight, 500.0},        {Kind::Climb, 600.0, 0.0, 2.0},   // up to ~118 m
                   {Kind::Straight, 400.0},        {Kind::Turn, 400.0, 0.1},         // ~109 deg left
                   {Kind::Straight, 500.0},        {Kind::Climb, 600.0, 0.0, -2.8},  // down to ~37 m
                   {Kind::Straight, 400.0},        {Kind::Turn, 500.0, -0.08},       // ~110 deg right
                   {Kind::Climb, 600.0, 0.0, 1.5},                                   // up to ~80 m
                   {Kind::Straight, 600.0},        {Kind::Turn, 400.0, 0.1},
                   {Kind::Climb, 400.0, 0.0, 1.2}};  // up to ~103 m
  // A last straight that ends the flight at exactly kPaperFrames frames.
  double flown = 0.0;
  for (const FlightLeg& leg : s.flight.legs) flown += leg.length_m;
  const double total = (kPaperFrames - 1) / s.flight.frameRate_hz * s.flight.speed_m_s;
  s.flight.legs.push_back({Kind::Straight, total - flown});
  s.deformation.drift = (Vector6() << 8e-4, 8e-4, 8e-4, 8e-3, 8e-3, 8e-3).finished();
  return s;
}

SimScenario stressScenario() {
  SimScenario s = demoScenario();
  s.name = "stress";
  FlightOptions& f = s.flight;
  f.altitude_m = 60.0;
  f.frameRate_hz = 15.0;
  // Leg by leg (20 m/s; rates ramp over 1 s at each end): 7.5 s straight at
  // 60 m; 22.5 s climbing to 150 m; a 10 s left turn at 150 m; 7.5 s
  // straight; 25 s descending to 30 m; a 7.5 s right turn; 7.5 s straight.
  f.legs = {{Kind::Straight, 150.0}, {Kind::Climb, 450.0, 0.0, 90.0 / 21.5}, {Kind::Turn, 200.0, 0.1},
            {Kind::Straight, 150.0}, {Kind::Climb, 500.0, 0.0, -5.0},        {Kind::Turn, 150.0, -0.1},
            {Kind::Straight, 150.0}};
  // Roll steps of 12.75 deg within one frame into each turn, and back out of it.
  const double roll = 12.75 * std::numbers::pi / 180.0, frame_s = 1.0 / f.frameRate_hz;
  // A yaw step of 30 deg within one frame on the straight at 150 m, held 2 s.
  const double yaw = 30.0 * std::numbers::pi / 180.0;
  f.gusts = {{30.0, Eigen::Vector3d(roll, 0.0, 0.0), frame_s, 10.0 - frame_s},
             {42.0, Eigen::Vector3d(0.0, 0.0, yaw), frame_s, 2.0 - frame_s},
             {72.5, Eigen::Vector3d(-roll, 0.0, 0.0), frame_s, 7.5 - frame_s}};
  // Exposure steps of +-30 %, and two frames nearly black (4 %) descending.
  s.faults.exposureJumps = {{200, 1.3}, {260, 1.0}, {700, 0.7}, {760, 1.0}, {1000, 0.04}, {1002, 1.0}};
  s.faults.blankFrames = {400};
  s.faults.corruptFrames = {900};
  s.faults.droppedFrames = {1100};
  return s;
}

SimScenario readScenarioYaml(const std::string& path) {
  const std::string text = readYamlText(path);
  cv::FileStorage fs;
  // OpenCV's YAML parser rejects some malformed files with cv::Exception and
  // others with a standard exception (std::length_error on a broken scalar).
  try {
    fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    fail("file " + path, std::string("is not valid YAML: ") + e.err);
  } catch (const std::exception& e) {
    fail("file " + path, std::string("is not valid YAML: ") + e.what());
  }
  if (!fs.isOpened()) fail("file " + path, "cannot be opened");
  MapReader root(fs.root(), path);
  SimScenario s = demoScenario();
  const cv::FileNode base = root.get("base");
  if (!base.empty()) {
    const std::string name = base.isString() ? static_cast<std::string>(base) : "";
    if (name == "paper")
      s = paperScenario();
    else if (name == "stress")
      s = stressScenario();
    else if (name != "demo")
      fail(path, "base must be demo, paper or stress, got '" + name + "'");
  }
  const cv::FileNode name = root.get("name");
  s.name = name.isString() ? static_cast<std::string>(name) : path;
  root.seed("seed", s.seed);
  readFlight(root.get("flight"), s.flight);
  readTerrain(root.get("terrain"), s.terrain);
  readRig(root.get("rig"), s.rig);
  readDeformation(root.get("deformation"), s.deformation);
  readTexture(root.get("texture"), s.texture);
  readRender(root.get("render"), s.render);
  readFaults(root.get("faults"), s.faults);
  root.finish();
  s.rig.validate();
  return s;
}

SimScenario loadScenario(const std::string& spec) {
  if (spec == "demo") return demoScenario();
  if (spec == "paper") return paperScenario();
  if (spec == "stress") return stressScenario();
  if (spec.ends_with(".yaml") || spec.ends_with(".yml")) return readScenarioYaml(spec);
  fail("'" + spec + "'", "unknown; expected demo, paper, stress or a .yaml / .yml file");
}

void writeScenarioYaml(const SimScenario& s, const std::string& path) {
  cv::FileStorage fs(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
  if (!fs.isOpened()) fail("file " + path, "cannot be written");
  fs << "name" << s.name;
  writeSeed(fs, "seed", s.seed);
  const FlightOptions& f = s.flight;
  fs << "flight"
     << "{"
     << "altitude_m" << f.altitude_m << "speed_m_s" << f.speed_m_s << "frameRate_hz" << f.frameRate_hz << "frameStep"
     << f.frameStep << "attitudeNoise_rad" << f.attitudeNoise_rad << "transition_s" << f.transition_s;
  writeSeed(fs, "seed", f.seed);
  fs << "legs"
     << "[";
  for (const FlightLeg& leg : f.legs)
    fs << "{:"
       << "kind" << kindName(leg.kind) << "length_m" << leg.length_m << "turnRate_rad_s" << leg.turnRate_rad_s
       << "climbRate_m_s" << leg.climbRate_m_s << "}";
  fs << "]"
     << "gusts"
     << "[";
  for (const AttitudeStep& g : f.gusts)
    fs << "{:"
       << "time_s" << g.time_s << "roll_rad" << g.size_rad.x() << "pitch_rad" << g.size_rad.y() << "yaw_rad"
       << g.size_rad.z() << "rise_s" << g.rise_s << "hold_s" << g.hold_s << "}";
  fs << "]"
     << "}";
  const TerrainOptions& t = s.terrain;
  fs << "terrain"
     << "{"
     << "relief_m" << t.relief_m << "hillScale_m" << t.hillScale_m << "treeDensity_per_km2" << t.treeDensity_per_km2
     << "treeHeight_m" << t.treeHeight_m << "buildingDensity_per_km2" << t.buildingDensity_per_km2 << "buildingHeight_m"
     << t.buildingHeight_m << "buildingSize_m" << t.buildingSize_m;
  writeSeed(fs, "seed", t.seed);
  fs << "}";
  fs << "rig"
     << "{"
     << "cameras"
     << "[";
  for (const Camera& c : s.rig.cameras)
    fs << "{:"
       << "fx" << c.intrinsics.fx << "fy" << c.intrinsics.fy << "cx" << c.intrinsics.cx << "cy" << c.intrinsics.cy
       << "width" << c.width << "height" << c.height << "}";
  fs << "]"
     << "extrinsics"
     << "[";
  for (const Vector6& e : s.rig.extrinsics) {
    fs << "[:";
    for (int i = 0; i < 6; ++i) fs << e[i];
    fs << "]";
  }
  fs << "]";
  writeVector6(fs, "tolerance", s.rig.tolerance);
  fs << "}";
  const DeformationOptions& d = s.deformation;
  fs << "deformation"
     << "{";
  writeVector6(fs, "drift", d.drift);
  fs << "driftPeriod_s" << d.driftPeriod_s;
  writeVector6(fs, "vibration", d.vibration);
  writeVector6(fs, "offset", d.offset);
  writeSeed(fs, "seed", d.seed);
  fs << "}";
  const GroundTextureOptions& x = s.texture;
  fs << "texture"
     << "{"
     << "fieldSize_m" << x.fieldSize_m << "trackProbability" << x.trackProbability << "hedgeProbability"
     << x.hedgeProbability << "grainContrast" << x.grainContrast;
  writeSeed(fs, "seed", x.seed);
  fs << "}";
  const RenderOptions& r = s.render;
  fs << "render"
     << "{"
     << "noiseSigma_grey" << r.noiseSigma_grey << "blurSigma_px" << r.blurSigma_px << "exposureDrift" << r.exposureDrift
     << "exposurePeriod_s" << r.exposurePeriod_s << "vignetting" << r.vignetting << "threads" << r.threads << "}";
  fs << "faults"
     << "{"
     << "exposureJumps"
     << "[";
  for (const FrameFaults::ExposureJump& jump : s.faults.exposureJumps)
    fs << "{:"
       << "frame" << jump.frame << "gain" << jump.gain << "}";
  fs << "]";
  writeFrameList(fs, "blankFrames", s.faults.blankFrames);
  writeFrameList(fs, "corruptFrames", s.faults.corruptFrames);
  writeFrameList(fs, "droppedFrames", s.faults.droppedFrames);
  fs << "}";
}

}  // namespace lrsvo

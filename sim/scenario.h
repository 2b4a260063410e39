#pragma once

#include <cstdint>
#include <string>

#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/sim/feature_simulator.h"
#include "lrsvo/sim/flight.h"
#include "lrsvo/sim/frame_faults.h"
#include "lrsvo/sim/ground_texture.h"
#include "lrsvo/sim/image_renderer.h"
#include "lrsvo/sim/rig_deformation.h"
#include "lrsvo/sim/terrain.h"

namespace lrsvo {

// Everything that defines a rendered synthetic flight. Each part keeps its
// own seed (terrain.seed: the world's shape, texture.seed: its look,
// flight.seed: the attitude wobble, deformation.seed: the rig's motion);
// `seed` drives the sensor (image noise and exposure drift), so runs over
// `seed` fly the same flight over the same world with new sensor noise.
struct SimScenario {
  std::string name = "demo";
  FlightOptions flight;
  TerrainOptions terrain;
  Rig rig = paperRig();  // the calibration, as told to the estimator
  DeformationOptions deformation;
  GroundTextureOptions texture;
  RenderOptions render;
  FrameFaults faults;  // what the camera link does to the frames (none by default)
  std::uint64_t seed = 1;
};

// "demo": 100 m above farmland at 20 m/s, 751 frames at 30 Hz (25 s, 500 m):
// a straight, a gentle left turn of about 22 deg, a straight.
SimScenario demoScenario();
// "paper": like the paper's flight: 9600 frames at 30 Hz (320 s, 6.4 km at
// 20 m/s), climbs and descents between about 37 and 118 m above the mean
// ground, three turns, a slight attitude wobble, the rig deforming within
// +-1 mm and +-0.01 rad of its calibration.
SimScenario paperScenario();
// "stress": what real flights bring, in one short flight over the demo's
// world at 15 Hz: a climb from 60 m to 150 m, a stretch at 150 m, a
// descent to 30 m and a stretch there, two turns, roll gusts of 12.75 deg
// within a frame entering and leaving each turn, a yaw step of 30 deg within
// a frame, exposure jumps of +-30 %, two frames nearly black, and a blank, a
// corrupt and a dropped frame.
SimScenario stressScenario();

// The scenario's world, flight and flexing rig as a feature-level simulation
// (sim/feature_simulator.h): no images, `pointsPerFrame` scene points in
// view, `pixelNoise_px` on every observation. Runs the odometry on a long
// flight in minutes where rendering it takes hours.
FeatureSimulationOptions featureSimulationOptions(const SimScenario& scenario, int pointsPerFrame = 300,
                                                  double pixelNoise_px = 0.5);

// A named scenario ("demo", "paper", "stress") or a YAML file (docs/simulator.md: every
// key optional; `base: demo|paper` picks the starting point, default demo).
// Throws lrsvo::Error on an unknown name, an unreadable file, an unknown key
// (the message names it) or a value of the wrong type.
SimScenario loadScenario(const std::string& spec);
SimScenario readScenarioYaml(const std::string& path);
// Writes every setting, so that readScenarioYaml gives the scenario back.
void writeScenarioYaml(const SimScenario& scenario, const std::string& path);

}  // namespace lrsvo

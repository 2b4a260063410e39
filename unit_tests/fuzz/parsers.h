#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lrsvo::fuzz {

// One harness per parser of lrsvo's inputs: it hands `size` bytes to the
// parser (through files in a scratch folder where the parser reads files) and
// returns when the parser reads them or rejects them with lrsvo::Error, the
// parsers' contract for bad input. Any other exception, a crash, a leak or
// undefined behaviour is a finding. Where a parser reads several files, the
// input holds them one after the other, separated by NUL bytes.
using Harness = void (*)(const std::uint8_t* data, std::size_t size);

struct Parser {
  std::string name;  // also the folder of its seeds: unit_tests/fuzz/corpus/<name>/
  std::string reads;
  Harness harness;
};

// Every parser's harness: bal, graph_file, tum_poses, kitti_poses,
// euroc_sensor, euroc_data_csv, euroc_ground_truth, kitti_calib_times, scenario_yaml, gtsam_vo,
// nist_problem.
const std::vector<Parser>& parsers();
// Throws lrsvo::Error on an unknown name.
const Parser& parser(const std::string& name);

}  // namespace lrsvo::fuzz

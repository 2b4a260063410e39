// Every input in the fuzz corpus (unit_tests/fuzz/corpus/<parser>/: the seeds
// and each input a fuzzer found failing, kept as a regression) goes through
// its parser's harness: read, or rejected with lrsvo::Error, never another
// exception (and, under the sanitizers, no memory error or undefined
// behaviour).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "unit_tests/fuzz/parsers.h"

namespace lrsvo::fuzz {
namespace {

namespace fs = std::filesystem;

class FuzzCorpus : public testing::TestWithParam<Parser> {};

TEST_P(FuzzCorpus, EveryInputIsReadOrRejectedWithAnError) {
  const Parser& parser = GetParam();
  const fs::path folder = fs::path(LRSVO_SOURCE_DIR) / "unit_tests" / "fuzz" / "corpus" / parser.name;
  ASSERT_TRUE(fs::is_directory(folder)) << "no seeds for " << parser.name << " in " << folder;
  int inputs = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NO_THROW(parser.harness(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size())) << entry.path();
    ++inputs;
  }
  EXPECT_GT(inputs, 0) << folder;
}

INSTANTIATE_TEST_SUITE_P(EveryParser, FuzzCorpus, testing::ValuesIn(parsers()),
                         [](const testing::TestParamInfo<Parser>& param) { return param.param.name; });

}  // namespace
}  // namespace lrsvo::fuzz

// libFuzzer's entry point for one parser's harness (parsers.h), chosen when
// the target is built (LRSVO_FUZZ_PARSER, its name).
#include <cstddef>
#include <cstdint>

#include "unit_tests/fuzz/parsers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const lrsvo::fuzz::Harness harness = lrsvo::fuzz::parser(LRSVO_FUZZ_PARSER).harness;
  harness(data, size);
  return 0;
}

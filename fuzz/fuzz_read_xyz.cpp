// libFuzzer target: the XYZ reader, without and with a required fourth column (see
// fuzz_read_common.hpp for what counts as a crash).
#include "fuzz_read_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rstruct::fuzz::fuzz_reader(data, size, rstruct::io::Format::xyz);
  rstruct::io::ReadOptions options;
  options.xyz_fourth_column = "weight";
  rstruct::fuzz::fuzz_reader(data, size, rstruct::io::Format::xyz, options);
  return 0;
}

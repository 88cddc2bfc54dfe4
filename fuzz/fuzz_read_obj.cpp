// libFuzzer target: the OBJ reader (see fuzz_read_common.hpp for what counts as a crash).
#include "fuzz_read_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rstruct::fuzz::fuzz_reader(data, size, rstruct::io::Format::obj);
  return 0;
}

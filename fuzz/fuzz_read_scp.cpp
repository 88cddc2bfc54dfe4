// Fuzz target: the OR-Library readers (row and column formats) and the verifier's own
// instance parser. Malformed input must give InvalidInput, never a crash, a hang or another
// exception; whatever parses must be a structurally valid instance.
#include <cstdint>
#include <sstream>
#include <string>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/setcover/read_instance.hpp"
#include "rstruct/setcover/verifier.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (int format = 0; format < 2; ++format) {
    std::istringstream in(text);
    try {
      const rstruct::setcover::Instance inst =
          format == 0 ? rstruct::setcover::read_scp_rows(in, "fuzz")
                      : rstruct::setcover::read_scp_columns(in, "fuzz");
      RSTRUCT_ASSERT(inst.is_valid());
    } catch (const rstruct::InvalidInput&) {
    }
  }
  // The same bytes as a certificate for a fixed instance: always a verdict, never a crash.
  std::istringstream cert(text);
  const auto v = rstruct::setcover::verify_certificate(2, {{0}, {1}, {0, 1}}, {1.0, 1.0, 3.0}, cert);
  RSTRUCT_ASSERT(v.valid == v.problems.empty());
  return 0;
}

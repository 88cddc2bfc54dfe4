#include "rstruct/core/assert.hpp"

namespace rstruct {

void assertion_failed(const char* expr, const char* file, int line, const std::string& message) {
  std::string what = std::string("internal error: assertion `") + expr + "` failed at " + file +
                     ":" + std::to_string(line);
  if (!message.empty()) what += ": " + message;
  throw InternalError(what);
}

}  // namespace rstruct

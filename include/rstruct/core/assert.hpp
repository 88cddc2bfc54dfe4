#pragma once
/// \file
/// Invariant checks. RSTRUCT_CHECK_LEVEL is set by the meson option `checks`
/// (0 none, 1 default, 2 expensive, 3 paranoid). RSTRUCT_ASSERT is always on (cheap,
/// local conditions whose failure would corrupt memory or output); RSTRUCT_DEBUG_ASSERT
/// and `rstruct::check_level() >= 2` guard the expensive global ones.

#include <string>

#include "rstruct/core/error.hpp"

#ifndef RSTRUCT_CHECK_LEVEL
#define RSTRUCT_CHECK_LEVEL 1
#endif

namespace rstruct {

/// Check level compiled into this build (see meson option `checks`).
constexpr int check_level() { return RSTRUCT_CHECK_LEVEL; }

[[noreturn]] void assertion_failed(const char* expr, const char* file, int line,
                                   const std::string& message);

}  // namespace rstruct

#define RSTRUCT_ASSERT_MSG(cond, msg)                                   \
  do {                                                                  \
    if (!(cond)) ::rstruct::assertion_failed(#cond, __FILE__, __LINE__, (msg)); \
  } while (false)

#define RSTRUCT_ASSERT(cond) RSTRUCT_ASSERT_MSG(cond, std::string())

#if RSTRUCT_CHECK_LEVEL >= 2
#define RSTRUCT_DEBUG_ASSERT(cond) RSTRUCT_ASSERT(cond)
#else
#define RSTRUCT_DEBUG_ASSERT(cond) \
  do {                             \
  } while (false)
#endif

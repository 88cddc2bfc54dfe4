#pragma once
/// \file
/// Typed exceptions of rstruct. The library never calls abort() or exit(): broken
/// preconditions and I/O problems throw, internal bugs throw InternalError from
/// RSTRUCT_ASSERT, and the command-line front end maps all of them to messages and exit
/// codes in one place (src/cli/main.cpp).

#include <stdexcept>
#include <string>

namespace rstruct {

/// Base class of every exception rstruct throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input violates a documented precondition: malformed file contents, NaN/Inf,
/// too few points, all points coplanar, absurd parameters. Exit code 2 in the CLI.
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// A file could not be opened, read or written. Exit code 2 in the CLI.
class IoError : public Error {
 public:
  using Error::Error;
};

/// The computation could not produce a result for valid input (for example unlabelled
/// poles, an uncoverable set-cover row). Exit code 1 in the CLI.
class ComputationFailed : public Error {
 public:
  using Error::Error;
};

/// An invariant of rstruct's own data structures does not hold: a bug. Thrown by
/// RSTRUCT_ASSERT so that tests and fuzzers can catch it.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace rstruct

// SPDX-License-Identifier: MIT
// The exceptions every LayerMOD function throws, public and internal alike (core/util/error.h
// includes this file), so an error raised deep in the core reaches the caller unchanged.
#pragma once

#include <stdexcept>
#include <string>

namespace layermod {

// Broken precondition or invalid argument (bad range, bad option value, an image of the wrong
// type or size, a camera the archive was not trained for).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file could not be opened, read or written. The message names the file.
class IoError : public Error {
 public:
  using Error::Error;
};

// A file was read but its content is malformed, truncated or foreign. The message names the file.
class FormatError : public Error {
 public:
  using Error::Error;
};

// A long job was cancelled through its cancel flag. Not an error: its own outcome.
class Cancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "cancelled"; }
};

}  // namespace layermod

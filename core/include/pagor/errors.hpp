#pragma once
/// \file errors.hpp
/// Exception types of the core. Bad user input (files, configs, parameters) throws one of these,
/// with a message that names what was wrong and where. Internal invariants use assert.

#include <stdexcept>
#include <string>

namespace pagor {

/// Base of every exception the core throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file or a data set that cannot be read or is malformed. The message names the file.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A configuration document or a parameter that is invalid. The message names the key path.
class ConfigError : public Error {
 public:
  using Error::Error;
};

/// Thrown out of a pipeline run when its cancellation flag was raised.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace pagor

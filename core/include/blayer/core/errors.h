// Exceptions that cross module boundaries. Library code throws these for bad input and
// I/O failures only; the CLI maps them to exit status 1 with an "error:" message.
#pragma once

#include <stdexcept>
#include <string>

namespace blayer {

// The user's input (file, surface, parameters) cannot be used. The message names the
// file, the element and the problem.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reading or writing a file failed for a reason outside the input's content.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace blayer

#include "blayer/core/assert.h"

#include <stdexcept>
#include <string>

namespace blayer {

void assertion_failed(const char* condition, const char* file, int line, const char* text) {
  std::string message = std::string(file) + ":" + std::to_string(line) + ": assertion failed: " + condition;
  if (text != nullptr) message += std::string(": ") + text;
  throw std::logic_error(message);
}

}  // namespace blayer

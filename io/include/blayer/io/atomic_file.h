// Atomic output: a file is written under a temporary name in its target directory and
// renamed into place only when complete, so a failed or interrupted run never leaves a
// half-written mesh under the requested name.
#pragma once

#include <string>

namespace blayer {

// A path "<prefix>-<pid>-<counter><suffix>" that does not exist yet.
std::string unique_temp_path(const std::string& prefix, const std::string& suffix);

class AtomicFile {
 public:
  explicit AtomicFile(std::string target);
  ~AtomicFile();  // removes the temporary file unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& temp_path() const { return temp_; }
  // Renames the temporary file onto the target; throws IoError on failure.
  void commit();

 private:
  std::string target_;
  std::string temp_;
  bool committed_ = false;
};

}  // namespace blayer

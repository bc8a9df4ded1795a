// A set of output files that appear together or not at all: each is written under a
// temporary name in its target directory, and all are renamed into place by commit().
// Files not committed (an exception on the way) are removed by the destructor.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace blayer {

class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();

  // Temporary path to write `target` to.
  std::string stage(const std::string& target);
  // Renames every staged file onto its target. Throws IoError on failure.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // target, temporary
  bool committed_ = false;
};

}  // namespace blayer

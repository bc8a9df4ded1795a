#include "blayer/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "blayer/core/errors.h"

namespace blayer {

namespace fs = std::filesystem;

std::string unique_temp_path(const std::string& prefix, const std::string& suffix) {
  static std::atomic<unsigned> counter{0};
  for (;;) {
    std::string p = prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + suffix;
    std::error_code ec;
    if (!fs::exists(p, ec)) return p;
  }
}

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  const fs::path t(target_);
  fs::path dir = t.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw IoError(target_ + ": directory " + dir.string() + " does not exist");
  // Hidden name in the same directory: rename() is atomic only within one file system.
  temp_ = unique_temp_path((dir / ("." + t.filename().string())).string(), ".tmp");
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::commit() {
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw IoError(target_ + ": cannot write (" + std::strerror(errno) + ")");
  committed_ = true;
}

}  // namespace blayer

#include "output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "blayer/core/errors.h"
#include "blayer/io/atomic_file.h"

namespace blayer {

namespace fs = std::filesystem;

OutputFiles::~OutputFiles() {
  if (committed_) return;
  for (const auto& [target, temp] : staged_) std::remove(temp.c_str());
}

std::string OutputFiles::stage(const std::string& target) {
  const fs::path t(target);
  fs::path dir = t.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw IoError(target + ": directory " + dir.string() + " does not exist");
  const std::string ext = t.extension().string();
  staged_.emplace_back(target, unique_temp_path((dir / ("." + t.stem().string())).string(), ".part" + ext));
  return staged_.back().second;
}

void OutputFiles::commit() {
  for (const auto& [target, temp] : staged_)
    if (std::rename(temp.c_str(), target.c_str()) != 0)
      throw IoError(target + ": cannot write (" + std::strerror(errno) + ")");
  committed_ = true;
}

}  // namespace blayer

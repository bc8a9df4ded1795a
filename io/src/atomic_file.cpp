#include "blayer/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

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

AtomicOutputs::~AtomicOutputs() {
  for (std::size_t i = n_committed_; i < staged_.size(); ++i) std::remove(staged_[i].second.c_str());
}

std::string AtomicOutputs::stage(const std::string& target) {
  const fs::path t(target);
  fs::path dir = t.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw IoError(target + ": directory " + dir.string() + " does not exist");
  const std::string ext = t.extension().string();
  staged_.emplace_back(target, unique_temp_path((dir / ("." + t.stem().string())).string(), ".part" + ext));
  return staged_.back().second;
}

void AtomicOutputs::commit() {
  for (; n_committed_ < staged_.size(); ++n_committed_) {
    const auto& [target, temp] = staged_[n_committed_];
    if (std::rename(temp.c_str(), target.c_str()) == 0) continue;
    std::string message = target + ": cannot write (" + std::strerror(errno) + ")";
    if (n_committed_ > 0) {
      message += "; already written:";
      for (std::size_t i = 0; i < n_committed_; ++i) message += " " + staged_[i].first;
    }
    for (std::size_t i = n_committed_; i < staged_.size(); ++i) std::remove(staged_[i].second.c_str());
    n_committed_ = staged_.size();  // nothing left for the destructor
    throw IoError(message);
  }
}

void write_text_file(const std::string& path, const std::string& text, const std::string& target) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw IoError(target + ": cannot write the file");
}

}  // namespace blayer

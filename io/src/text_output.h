// Buffered text output for the ASCII mesh writers: numbers are formatted with
// std::to_chars (shortest text that reads back to the same double, so coordinates
// survive a round trip exactly) into a buffer that is written out in large blocks.
// Every failure becomes an IoError naming the target the caller is writing.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>

#include "blayer/core/errors.h"

namespace blayer {

class TextOutput {
 public:
  // path is where the bytes go (normally a staged temporary), target the name the user asked for.
  TextOutput(const std::string& path, const std::string& target) : target_(target) {
    file_ = std::fopen(path.c_str(), "wb");
    if (!file_) throw IoError(target_ + ": cannot create the file");
    buffer_.reserve(kBlock + 256);
  }
  TextOutput(const TextOutput&) = delete;
  TextOutput& operator=(const TextOutput&) = delete;
  ~TextOutput() {
    if (file_) std::fclose(file_);
  }

  TextOutput& operator<<(const std::string& s) { return text(s.data(), s.size()); }
  TextOutput& operator<<(const char* s) { return text(s, std::char_traits<char>::length(s)); }
  TextOutput& operator<<(char c) { return text(&c, 1); }
  TextOutput& operator<<(std::int64_t v) { return number(v); }
  TextOutput& operator<<(int v) { return number(static_cast<std::int64_t>(v)); }
  TextOutput& operator<<(std::size_t v) { return number(static_cast<std::int64_t>(v)); }
  TextOutput& operator<<(double v) { return number(v); }

  // Raw bytes (binary blocks of a file that is otherwise text).
  TextOutput& bytes(const void* data, std::size_t n) { return text(static_cast<const char*>(data), n); }

  // Writes what is buffered and closes the file; throws IoError if anything failed.
  void close() {
    flush();
    const bool failed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (failed) throw IoError(target_ + ": cannot write the file");
  }

 private:
  static constexpr std::size_t kBlock = 1 << 20;

  template <class T>
  TextOutput& number(T v) {
    char digits[32];
    const auto r = std::to_chars(digits, digits + sizeof digits, v);
    return text(digits, static_cast<std::size_t>(r.ptr - digits));
  }
  TextOutput& text(const char* s, std::size_t n) {
    buffer_.append(s, n);
    if (buffer_.size() >= kBlock) flush();
    return *this;
  }
  void flush() {
    if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
      throw IoError(target_ + ": cannot write the file (disk full?)");
    buffer_.clear();
  }

  std::string target_;
  std::FILE* file_ = nullptr;
  std::string buffer_;
};

}  // namespace blayer

// Reading binary numbers of either byte order from a file's bytes, with a bounds check
// on every read (binary PLY, binary legacy VTK).
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>
#include <utility>

namespace blayer::detail {

enum class ByteOrder { kLittle, kBig };

// The scalar types binary surface formats store.
enum class Scalar { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kInt64, kUint64, kFloat32, kFloat64 };

inline int scalar_size(Scalar s) {
  switch (s) {
    case Scalar::kInt8: case Scalar::kUint8: return 1;
    case Scalar::kInt16: case Scalar::kUint16: return 2;
    case Scalar::kInt32: case Scalar::kUint32: case Scalar::kFloat32: return 4;
    case Scalar::kInt64: case Scalar::kUint64: case Scalar::kFloat64: return 8;
  }
  return 0;
}

inline bool scalar_is_integer(Scalar s) { return s != Scalar::kFloat32 && s != Scalar::kFloat64; }

class ByteCursor {
 public:
  ByteCursor(std::string_view bytes, ByteOrder order) : bytes_(bytes), order_(order) {}

  std::size_t remaining() const { return bytes_.size() - pos_; }
  std::size_t position() const { return pos_; }

  // Reads one value as double (every integer of up to 53 bits is exact, and the
  // formats' indices are far below that); false when fewer bytes remain.
  bool read(Scalar s, double* out) {
    const int n = scalar_size(s);
    if (remaining() < static_cast<std::size_t>(n)) return false;
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, n);
    pos_ += n;
    if ((order_ == ByteOrder::kBig) == host_is_little())
      for (int i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    *out = decode(s, b);
    return true;
  }

  bool skip(std::size_t n) {
    if (remaining() < n) return false;
    pos_ += n;
    return true;
  }

 private:
  static bool host_is_little() {
    const std::uint16_t one = 1;
    unsigned char c;
    std::memcpy(&c, &one, 1);
    return c == 1;
  }

  template <class T>
  static double as(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
  }

  static double decode(Scalar s, const unsigned char* b) {
    switch (s) {
      case Scalar::kInt8: return as<std::int8_t>(b);
      case Scalar::kUint8: return as<std::uint8_t>(b);
      case Scalar::kInt16: return as<std::int16_t>(b);
      case Scalar::kUint16: return as<std::uint16_t>(b);
      case Scalar::kInt32: return as<std::int32_t>(b);
      case Scalar::kUint32: return as<std::uint32_t>(b);
      case Scalar::kInt64: return as<std::int64_t>(b);
      case Scalar::kUint64: return as<std::uint64_t>(b);
      case Scalar::kFloat32: return as<float>(b);
      case Scalar::kFloat64: return as<double>(b);
    }
    return 0.0;
  }

  std::string_view bytes_;
  ByteOrder order_;
  std::size_t pos_ = 0;
};

}  // namespace blayer::detail

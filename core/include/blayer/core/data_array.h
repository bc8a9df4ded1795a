// A mesh's named point or cell array: n_tuples x n_components values, stored in the
// type they are written as. Integer-valued arrays are Int32, so ParaView shows them as
// categories; single-precision ones (quality metrics and the layer mesh's point
// directions, meant for viewing and thresholding) are Float32, which halves their size
// on disk; all others are Float64.
//
// Why not doubles throughout: the arrays of a layer mesh outweigh the mesh. On a
// 400k-cell mesh its seven metrics, its validity and flags and its layer numbers took
// 32 MB as doubles, a quarter of the run's peak memory, for values written at 4 bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace blayer {

enum class ValueType : std::uint8_t { kFloat64, kFloat32, kInt32 };

// The values of one array. Reads and writes go through doubles; an Int32 array keeps
// the value truncated towards zero (what writing it as Int32 always did), so it should
// only be given integers.
class ArrayValues {
 public:
  ArrayValues() = default;  // Float64, empty
  // Float64, taking the vector over.
  ArrayValues(std::vector<double> values) : v_(std::move(values)) {}  // NOLINT: implicit on purpose
  // Float32 or Int32, taking the vector over.
  explicit ArrayValues(std::vector<float> values) : v_(std::move(values)) {}
  explicit ArrayValues(std::vector<std::int32_t> values) : v_(std::move(values)) {}
  explicit ArrayValues(ValueType type, std::size_t n = 0) {
    switch (type) {
      case ValueType::kFloat64: v_ = std::vector<double>(n); break;
      case ValueType::kFloat32: v_ = std::vector<float>(n); break;
      case ValueType::kInt32: v_ = std::vector<std::int32_t>(n); break;
    }
  }
  ArrayValues(ValueType type, const std::vector<double>& values) : ArrayValues(type) {
    visit([&](auto& v) {
      v.reserve(values.size());
      for (double x : values) v.push_back(as_stored<std::decay_t<decltype(v[0])>>(x));
    });
  }

  ValueType type() const { return static_cast<ValueType>(v_.index()); }
  std::size_t size() const {
    return std::visit([](const auto& v) { return v.size(); }, v_);
  }
  bool empty() const { return size() == 0; }

  double operator[](std::size_t i) const {
    return std::visit([i](const auto& v) { return static_cast<double>(v[i]); }, v_);
  }
  void set(std::size_t i, double x) {
    visit([&](auto& v) { v[i] = as_stored<std::decay_t<decltype(v[0])>>(x); });
  }
  void push_back(double x) {
    visit([&](auto& v) { v.push_back(as_stored<std::decay_t<decltype(v[0])>>(x)); });
  }
  void reserve(std::size_t n) {
    visit([n](auto& v) { v.reserve(n); });
  }
  void resize(std::size_t n, double fill = 0.0) {
    visit([&](auto& v) { v.resize(n, as_stored<std::decay_t<decltype(v[0])>>(fill)); });
  }

  // The stored values; T must be the stored type (double, float or std::int32_t).
  template <class T>
  const std::vector<T>& as() const {
    return std::get<std::vector<T>>(v_);
  }
  template <class T>
  std::vector<T>& as() {
    return std::get<std::vector<T>>(v_);
  }

  // Equal when of the same type with the same values. Not comparable with a vector of
  // doubles, which would convert to a Float64 array and differ from any other type.
  friend bool operator==(const ArrayValues& a, const ArrayValues& b) { return a.v_ == b.v_; }
  friend bool operator==(const ArrayValues&, const std::vector<double>&) = delete;
  friend bool operator==(const std::vector<double>&, const ArrayValues&) = delete;

 private:
  template <class T>
  static T as_stored(double x) {
    return static_cast<T>(x);
  }
  template <class F>
  void visit(F&& f) {
    std::visit(std::forward<F>(f), v_);
  }

  // In the order of ValueType.
  std::variant<std::vector<double>, std::vector<float>, std::vector<std::int32_t>> v_;
};

struct DataArray {
  std::string name;
  int n_components = 1;
  ArrayValues values;

  ValueType type() const { return values.type(); }
  bool integer() const { return type() == ValueType::kInt32; }
  bool single_precision() const { return type() == ValueType::kFloat32; }
};

}  // namespace blayer

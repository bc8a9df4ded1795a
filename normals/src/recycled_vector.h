// A std::vector whose storage is recycled between the objects of one thread: it takes a
// released buffer on construction and gives its own back on destruction. The solvers
// build their scratch tables once per vertex solve, tens of thousands of times per
// front; with plain vectors their allocations took about a tenth of a wing-skin solve.
// The contents start empty as with std::vector; only the capacity is carried over, so
// results cannot depend on it. Not copyable (a copy would have to come from the pool as
// well, which no caller needs). Internal to blayer_normals.
#pragma once

#include <utility>
#include <vector>

namespace blayer {
namespace detail {

template <class T>
class RecycledVector : public std::vector<T> {
 public:
  RecycledVector() {
    std::vector<std::vector<T>>& pool = released();
    if (!pool.empty()) {
      std::vector<T>::swap(pool.back());
      pool.pop_back();
      std::vector<T>::clear();
    }
  }
  RecycledVector(const RecycledVector&) = delete;
  RecycledVector& operator=(const RecycledVector&) = delete;
  ~RecycledVector() {
    // Buffers beyond a handful would only pile up after an unusual nesting.
    std::vector<std::vector<T>>& pool = released();
    if (pool.size() < kMaxReleased && std::vector<T>::capacity() > 0) {
      pool.emplace_back();
      pool.back().swap(*this);
    }
  }

 private:
  static constexpr std::size_t kMaxReleased = 16;
  static std::vector<std::vector<T>>& released() {
    thread_local std::vector<std::vector<T>> pool;
    return pool;
  }
};

}  // namespace detail
}  // namespace blayer

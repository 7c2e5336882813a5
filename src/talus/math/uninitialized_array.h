#pragma once
// A fixed array whose elements are not constructed. Vec3 and every struct holding one start at
// zero, so a scratch array of them costs a memset on each call; the narrow phase and the
// manifold builders run once per touching part pair and step, and those memsets were 2 % of a
// flowing pile's step. An element must be assigned before it is read.
#include <cstddef>
#include <new>
#include <type_traits>

namespace talus {

template <class T, std::size_t N>
class UninitializedArray {
  // Bytes become objects of an implicit-lifetime type when assigned (C++20, P0593).
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  T* data() { return std::launder(reinterpret_cast<T*>(bytes_)); }
  const T* data() const { return std::launder(reinterpret_cast<const T*>(bytes_)); }
  T& operator[](std::size_t k) { return data()[k]; }
  const T& operator[](std::size_t k) const { return data()[k]; }
  static constexpr std::size_t size() { return N; }

 private:
  alignas(T) unsigned char bytes_[N * sizeof(T)];
};

}  // namespace talus

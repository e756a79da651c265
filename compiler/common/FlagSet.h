#pragma once
/// \file
/// A set of the values of a small enum, as bits (as naga's `Features` bitflags): the features a
/// material uses, combined from its parts and read by every consumer.

#include <cstdint>

namespace mxc {

/// The values of enum `E` (whose last enumerator is `Count`, at most 64) as a bit set.
template <typename E>
class FlagSet {
  static_assert(static_cast<unsigned>(E::Count) <= 64, "a FlagSet holds at most 64 values");

 public:
  constexpr FlagSet() = default;
  constexpr FlagSet& insert(E e) {
    bits_ |= bit(e);
    return *this;
  }
  constexpr void erase(E e) { bits_ &= ~bit(e); }
  constexpr bool has(E e) const { return (bits_ & bit(e)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr FlagSet& operator|=(FlagSet other) {
    bits_ |= other.bits_;
    return *this;
  }
  constexpr bool operator==(const FlagSet&) const = default;
  /// How many values are in the set.
  constexpr int size() const { return __builtin_popcountll(bits_); }
  /// Calls f(E) for each value in the set, in enum order.
  template <typename F>
  void forEach(F f) const {
    for (unsigned i = 0; i < static_cast<unsigned>(E::Count); ++i) {
      if (bits_ & (uint64_t{1} << i)) f(static_cast<E>(i));
    }
  }

 private:
  static constexpr uint64_t bit(E e) { return uint64_t{1} << static_cast<unsigned>(e); }
  uint64_t bits_ = 0;
};

}  // namespace mxc

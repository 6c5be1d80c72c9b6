// SPDX-License-Identifier: MIT
#pragma once

// Explicit little-endian encoding of integers and floats, one byte at a time, so the archive's
// binary tables do not depend on the host's byte order, struct padding or compiler.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "util/error.h"

namespace layermod {

// Appends little-endian values to a byte string.
class ByteWriter {
 public:
  explicit ByteWriter(std::string& out) : out_(out) {}

  template <typename T>
  void Put(T value) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>);
    if constexpr (std::is_enum_v<T>) {
      Put(static_cast<std::underlying_type_t<T>>(value));
    } else if constexpr (std::is_same_v<T, float>) {
      PutUnsigned(std::bit_cast<std::uint32_t>(value));
    } else if constexpr (std::is_same_v<T, double>) {
      PutUnsigned(std::bit_cast<std::uint64_t>(value));
    } else {
      PutUnsigned(static_cast<std::make_unsigned_t<T>>(value));
    }
  }

  void PutZeros(std::size_t count) { out_.append(count, '\0'); }

 private:
  template <typename U>
  void PutUnsigned(U value) {
    char bytes[sizeof(U)];
    for (std::size_t i = 0; i < sizeof(U); ++i) {
      bytes[i] = static_cast<char>(static_cast<std::uint8_t>(value >> (8 * i)));
    }
    out_.append(bytes, sizeof(U));
  }

  std::string& out_;
};

// Reads little-endian values from a byte range; every read is bounds-checked and throws
// FormatError (without a file name: the caller adds it) when the data ends early.
class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes, std::size_t position = 0)
      : bytes_(bytes), position_(position) {}

  template <typename T>
  T Get() {
    static_assert(std::is_arithmetic_v<T>);
    if constexpr (std::is_same_v<T, float>) {
      return std::bit_cast<float>(GetUnsigned<std::uint32_t>());
    } else if constexpr (std::is_same_v<T, double>) {
      return std::bit_cast<double>(GetUnsigned<std::uint64_t>());
    } else {
      return static_cast<T>(GetUnsigned<std::make_unsigned_t<T>>());
    }
  }

  // True when the next `count` bytes are all zero (consumes them).
  bool SkipZeros(std::size_t count) {
    Require(count);
    bool zero = true;
    for (std::size_t i = 0; i < count; ++i) zero = zero && bytes_[position_ + i] == '\0';
    position_ += count;
    return zero;
  }

  std::size_t position() const { return position_; }
  std::size_t remaining() const { return bytes_.size() - position_; }

 private:
  void Require(std::size_t count) const {
    if (count > bytes_.size() - position_) [[unlikely]] {
      ThrowPastEnd(count);
    }
  }

  // Kept out of line so that the checks above stay cheap enough to inline in hot loops.
  [[noreturn]] __attribute__((noinline)) void ThrowPastEnd(std::size_t count) const {
    throw FormatError("data ends at byte " + std::to_string(bytes_.size()) + ", needed " +
                      std::to_string(count) + " more from byte " + std::to_string(position_));
  }

  template <typename U>
  U GetUnsigned() {
    Require(sizeof(U));
    U value = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) {
      value |= static_cast<U>(static_cast<U>(static_cast<std::uint8_t>(bytes_[position_ + i]))
                              << (8 * i));
    }
    position_ += sizeof(U);
    return value;
  }

  std::string_view bytes_;
  std::size_t position_ = 0;
};

}  // namespace layermod

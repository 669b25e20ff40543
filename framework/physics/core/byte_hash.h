#pragma once
// The project's one hash for "are these two states the same to the bit?": FNV-1a over 64 bits (Fowler,
// Noll and Vo), fed byte by byte. The rewind check's fingerprint (app/checks/state_fingerprint.h), the golden
// files' draw hashes and the determinism tests all use it. It is neither a hash-table hash for untrusted
// keys nor cryptographic.
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "physics/core/types.h"

namespace pba {

class ByteHash {
 public:
  /// Mixes n bytes at `data`, in order.
  void bytes(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) hash_ = (hash_ ^ b[i]) * kPrime;
  }
  /// Mixes the object representation of a value (its bits, so −0.0 and 0.0 differ, as do two NaNs).
  template <typename T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "ByteHash::add hashes the bytes of plain values");
    bytes(&value, sizeof value);
  }
  void add(const Vec3& v) {
    add(v.x);
    add(v.y);
    add(v.z);
  }
  void add(const Quat& q) {
    add(q.w);
    add(q.x);
    add(q.y);
    add(q.z);
  }
  template <typename T>
  void addAll(std::span<const T> values) {
    for (const T& v : values) add(v);
  }
  std::uint64_t value() const { return hash_; }

 private:
  // The offset basis is the one the goldens were recorded with (tests/golden/*.json store draw hashes):
  // the published basis 14695981039346656037 without its last digit. Any odd start serves equally well.
  static constexpr std::uint64_t kOffsetBasis = 1469598103934665603ull;
  static constexpr std::uint64_t kPrime = 1099511628211ull;
  std::uint64_t hash_ = kOffsetBasis;
};

}  // namespace pba

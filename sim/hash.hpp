// SPDX-License-Identifier: MIT
// FNV-1a 64-bit hashing of plain values, for golden determinism hashes.
#pragma once

#include <bit>
#include <cstdint>
#include <string>

namespace swarmpath::sim {

class Fnv1a {
 public:
  void add_bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      h_ ^= p[i];
      h_ *= 0x100000001b3ULL;
    }
  }

  void add(std::uint64_t v) { add_bytes(&v, sizeof v); }

  void add(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }

  void add(int v) { add(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))); }

  /// Hash a double by its exact bit pattern (+0 and -0 differ, as they should for golden tests).
  void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }

  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ULL;
};

/// 16-digit lower-case hexadecimal, as printed in JSON and golden tests.
std::string to_hex(std::uint64_t v);

}  // namespace swarmpath::sim

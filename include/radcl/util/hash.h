// Content hashing for cache keys (program binaries, later ambient files). Not cryptographic:
// a 128-bit digest from two independent 64-bit FNV-1a lanes with a final avalanche mix.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace radcl {

class Hasher {
public:
  Hasher& add(std::string_view bytes);
  Hasher& add(std::uint64_t value);
  // 32 lowercase hex digits.
  std::string hex() const;

private:
  std::uint64_t a_ = 0xcbf29ce484222325ull;
  std::uint64_t b_ = 0x84222325cbf29ce4ull;
};

} // namespace radcl

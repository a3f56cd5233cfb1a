#include "radcl/util/hash.h"

#include <cstdio>

namespace radcl {
namespace {
constexpr std::uint64_t kPrimeA = 0x100000001b3ull;
constexpr std::uint64_t kPrimeB = 0x100000001b3ull * 31ull + 2ull; // odd, distinct lane
std::uint64_t mix(std::uint64_t x) {                               // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
} // namespace

Hasher& Hasher::add(std::string_view bytes) {
  for (unsigned char c : bytes) {
    a_ = (a_ ^ c) * kPrimeA;
    b_ = (b_ ^ (c + 0x5bu)) * kPrimeB;
  }
  // Length-delimit so ("ab","c") and ("a","bc") differ.
  return add(static_cast<std::uint64_t>(bytes.size()) ^ 0x9e3779b97f4a7c15ull);
}

Hasher& Hasher::add(std::uint64_t value) {
  for (int i = 0; i < 8; ++i) {
    unsigned char c = static_cast<unsigned char>(value >> (8 * i));
    a_ = (a_ ^ c) * kPrimeA;
    b_ = (b_ ^ (c + 0x5bu)) * kPrimeB;
  }
  return *this;
}

std::string Hasher::hex() const {
  char buf[33];
  std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(mix(a_)),
                static_cast<unsigned long long>(mix(b_ ^ a_)));
  return buf;
}

} // namespace radcl

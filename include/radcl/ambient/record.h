// One irradiance-cache record exactly as Radiance 5 keeps it (ambient.h's AMBVAL minus the
// list links) and its 67-byte portable form (../shared/docs/radiance/ambient-file.md §1.2). Fields
// are float, as in Radiance, so that decoding and re-encoding a file reproduces its bytes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace radcl::ambient {

constexpr std::size_t kRecordSize = 67; // AMBVALSIZ
constexpr int kMagic = 559;             // AMBMAGIC, written as 2 big-endian bytes
constexpr const char* kFormat = "Radiance_ambval";

struct AmbientRecord {
  std::array<float, 3> pos{};  // world position
  std::int32_t ndir = 0;       // encode_dir() of the unperturbed normal
  std::int32_t udir = 0;       // encode_dir() of the u axis (first principal axis)
  std::int16_t lvl = 0;        // ambient level; one unsigned byte in the file
  float weight = 0.0f;         // 0 < weight <= 1
  std::array<float, 2> rad{};  // radii along u and v, rad[0] <= rad[1], not yet times -aa
  std::array<float, 3> val{};  // ambient radiance (RGB), stored as RGBE
  std::array<float, 2> gpos{}; // relative translational gradient along u, v
  std::array<float, 2> gdir{}; // relative rotational gradient, u and v components
  std::uint32_t corral = 0;    // 32 sector bits of possible light leaks

  bool operator==(const AmbientRecord&) const = default;
};

using RecordBytes = std::array<unsigned char, kRecordSize>;

// writambval(): the level is written modulo 256, the value through setcolr().
RecordBytes encode_record(const AmbientRecord& r);
// readambval() on 67 available bytes, without the validity check.
AmbientRecord decode_record(const unsigned char* bytes);

// ambvalOK(): the checks Radiance applies to every record it reads
// (../shared/docs/radiance/ambient-file.md §1.3).
bool record_ok(const AmbientRecord& r);
// What a reader will accept: finite fields and record_ok() of the record as decoded from its
// bytes. Nothing else is ever appended to a shared file.
bool record_writable(const AmbientRecord& r);

// readambval(): the record at `bytes` if `n` (bytes left in the file) holds a whole one that
// passes record_ok(), else nullopt; Radiance stops reading at the first such failure.
std::optional<AmbientRecord> read_record(const unsigned char* bytes, std::size_t n);

} // namespace radcl::ambient

#include "radcl/image/scanline.h"

#include <cstdio>

namespace radcl::image {
namespace {

constexpr int kMinRun = 4;   // shorter repeats are not worth a run packet
constexpr int kMaxRun = 127; // a run code is 128 + count in one byte
constexpr int kMaxLiteral = 128;

// One component plane, packets as fwritecolrs() chooses them: find the next run of at least
// kMinRun equal bytes; what precedes it goes out as literals, unless it is 2 or 3 equal bytes,
// which become a short run; then the run itself.
void encode_plane(std::span<const Rgbe> px, int c, std::vector<unsigned char>& out) {
  const int len = static_cast<int>(px.size());
  int j = 0;
  while (j < len) {
    int beg = j;
    int cnt = 0;
    for (; beg < len; beg += cnt) {
      cnt = 1;
      while (cnt < kMaxRun && beg + cnt < len && px[beg + cnt][c] == px[beg][c])
        ++cnt;
      if (cnt >= kMinRun) break;
    }
    const int before = beg - j;
    if (before > 1 && before < kMinRun) {
      bool same = true;
      for (int k = j + 1; k < beg; ++k)
        same = same && px[k][c] == px[j][c];
      if (same) {
        out.push_back(static_cast<unsigned char>(128 + before));
        out.push_back(px[j][c]);
        j = beg;
      }
    }
    while (j < beg) {
      const int n = beg - j > kMaxLiteral ? kMaxLiteral : beg - j;
      out.push_back(static_cast<unsigned char>(n));
      for (int k = 0; k < n; ++k)
        out.push_back(px[j++][c]);
    }
    if (cnt >= kMinRun) {
      out.push_back(static_cast<unsigned char>(128 + cnt));
      out.push_back(px[beg][c]);
      j = beg + cnt;
    }
  }
}

// Flat pixels with old-style repeat markers (R = G = B = 1, count in E, shifted left by 8 for
// each consecutive marker). `done` pixels of the scanline are already filled.
ScanStatus decode_old(std::streambuf& in, std::span<Rgbe> px, std::size_t done) {
  int shift = 0;
  while (done < px.size()) {
    Rgbe p;
    for (auto& b : p) {
      const int v = in.sbumpc();
      if (v == EOF) return ScanStatus::truncated;
      b = static_cast<unsigned char>(v);
    }
    if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
      if (done == 0) return ScanStatus::corrupt; // nothing to repeat
      // Radiance stops quietly at the scanline's end when a count runs past it, so a count
      // shifted beyond any scanline's length just fills the rest.
      const std::size_t left = px.size() - done;
      const std::size_t n =
          shift >= 32 ? (p[3] ? left : 0) : static_cast<std::size_t>(p[3]) << shift;
      for (std::size_t k = 0; k < n && done < px.size(); ++k, ++done)
        px[done] = px[done - 1];
      if (shift < 32) shift += 8;
    } else {
      px[done++] = p;
      shift = 0;
    }
  }
  return ScanStatus::ok;
}

} // namespace

void encode_scanline(std::span<const Rgbe> pixels, std::vector<unsigned char>& out) {
  const int len = static_cast<int>(pixels.size());
  if (len < kMinRleLength || len > kMaxRleLength) {
    for (const auto& p : pixels)
      out.insert(out.end(), p.begin(), p.end());
    return;
  }
  out.push_back(2);
  out.push_back(2);
  out.push_back(static_cast<unsigned char>(len >> 8));
  out.push_back(static_cast<unsigned char>(len & 0xff));
  for (int c = 0; c < 4; ++c)
    encode_plane(pixels, c, out);
}

ScanStatus decode_scanline(std::streambuf& in, std::span<Rgbe> px) {
  const std::size_t len = px.size();
  if (len < kMinRleLength || len > kMaxRleLength) return decode_old(in, px, 0);
  const int b0 = in.sgetc();
  if (b0 == EOF) return ScanStatus::truncated;
  if (b0 != 2) return decode_old(in, px, 0);
  int b[4];
  for (int& v : b)
    if ((v = in.sbumpc()) == EOF) return ScanStatus::truncated;
  if (b[1] != 2 || (b[2] & 0x80)) { // an ordinary first pixel that happens to start with 2
    px[0] = {2, static_cast<unsigned char>(b[1]), static_cast<unsigned char>(b[2]),
             static_cast<unsigned char>(b[3])};
    return decode_old(in, px, 1);
  }
  if (static_cast<std::size_t>(b[2] << 8 | b[3]) != len) return ScanStatus::corrupt;
  for (int c = 0; c < 4; ++c) {
    for (std::size_t j = 0; j < len;) {
      int code = in.sbumpc();
      if (code == EOF) return ScanStatus::truncated;
      if (code > 128) {
        code &= 127;
        const int v = in.sbumpc();
        if (v == EOF) return ScanStatus::truncated;
        if (j + code > len) return ScanStatus::corrupt;
        while (code--)
          px[j++][c] = static_cast<unsigned char>(v);
      } else {
        if (j + code > len) return ScanStatus::corrupt;
        while (code--) {
          const int v = in.sbumpc();
          if (v == EOF) return ScanStatus::truncated;
          px[j++][c] = static_cast<unsigned char>(v);
        }
      }
    }
  }
  return ScanStatus::ok;
}

} // namespace radcl::image

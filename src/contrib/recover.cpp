// -r: picking up the files of an interrupted rcontrib run (Radiance's recover_output() and
// reload_output()).
#include "radcl/contrib/output.h"

#include "radcl/image/resolution.h"
#include "radcl/image/rgbe.h"
#include "radcl/options/ray_io.h"
#include "radcl/util/error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <sys/stat.h>

namespace radcl::contrib {
namespace {

// One line as fgets() with a `size`-byte buffer reads it, newline kept; false at end of file
// with nothing read.
bool read_line(std::FILE* fp, std::string& line, std::size_t size) {
  line.clear();
  int c;
  while (line.size() + 1 < size && (c = std::getc(fp)) != EOF) {
    line.push_back(static_cast<char>(c));
    if (c == '\n') break;
  }
  return !line.empty();
}

// checkheader(fp, format, NULL) == 1: a header (printable first byte, ended by an empty line)
// whose last FORMAT= value is `format`. Leaves fp after the header.
bool header_has_format(std::FILE* fp, const std::string& format) {
  const int first = std::getc(fp);
  if (first == EOF || !std::isprint(first)) return false;
  std::ungetc(first, fp);
  std::string line, found;
  for (;;) {
    if (!read_line(fp, line, 2048)) return false; // the file ends inside the header
    if (line[line[0] == '\r'] == '\n') break;
    if (line.compare(0, 7, "FORMAT=") != 0) continue;
    std::size_t p = 7;
    while (p < line.size() && std::isspace(static_cast<unsigned char>(line[p])))
      ++p;
    if (p == line.size()) continue; // no value: not a format line
    std::size_t e = p;
    while (e < line.size() && !std::isspace(static_cast<unsigned char>(line[e])) && e - p < 63)
      ++e;
    found = line.substr(p, e - p);
  }
  return found == format;
}

// fscnresolu() and the comparison: the standard "-Y <yr> +X <xr>" line.
bool resolution_is(std::FILE* fp, int xr, int yr) {
  std::string line;
  if (!read_line(fp, line, 32)) return false;
  const auto r = image::Resolution::parse(line);
  return r && r->is_standard() && r->xres == xr && r->yres == yr;
}

// get_contrib(): one rgb value in the output format.
bool read_value(std::FILE* fp, char format, double* rgb) {
  switch (format) {
  case 'a':
    return std::fscanf(fp, "%lf %lf %lf", &rgb[0], &rgb[1], &rgb[2]) == 3;
  case 'f': {
    float v[3];
    if (std::fread(v, sizeof v[0], 3, fp) != 3) return false;
    std::copy(v, v + 3, rgb);
    return true;
  }
  case 'd':
    return std::fread(rgb, sizeof rgb[0], 3, fp) == 3;
  case 'c': {
    image::Rgbe p;
    if (std::fread(p.data(), 1, p.size(), fp) != p.size()) return false;
    const image::Color c = image::to_color(p);
    std::copy(c.begin(), c.end(), rgb);
    return true;
  }
  }
  return false;
}

} // namespace

long Outputs::recover(std::vector<double>& reloaded) {
  reloaded.clear();
  complete_ = false;
  if (!s_.recover) return 0;
  if (s_.accumulate > 0) return recover_records();
  reload(reloaded);
  return 0;
}

// myclose(): the files opened to read them are closed again (they are opened anew, truncated,
// for the first record).
void Outputs::close_inputs() {
  for (Stream& st : streams_)
    if (st.fp) {
      std::fclose(st.fp);
      st.fp = nullptr;
    }
}

// reload_output(): -c 0's totals so far, read back from the files to add to.
void Outputs::reload(std::vector<double>& reloaded) {
  reloaded.assign(nvalues_, 0.0);
  const std::string format = options::format_name(s_.format);
  double* out = reloaded.data();
  for (const Modifier& m : mods_) {
    if (!m.spec) throw FatalError("cannot reload from stdout");
    if ((*m.spec)[0] == '!') throw FatalError("cannot reload from command");
    for (int j = 0; j < m.nbins; ++j) {
      Stream& st = streams_[m.streams[static_cast<std::size_t>(j)]];
      if (!st.fp) {
        st.fp = std::fopen(st.name.c_str(), s_.format == 'a' ? "r" : "rb");
        if (!st.fp) {
          warning("missing reload file '" + st.name + "'");
          break;
        }
        if (s_.header && !header_has_format(st.fp, format))
          throw FatalError("format mismatch for '" + st.name + "'");
        if (st.reclen == 1 && st.xr > 0 && st.yr > 0 && !resolution_is(st.fp, st.xr, st.yr))
          throw FatalError("resolution mismatch for '" + st.name + "'");
      }
      if (!read_value(st.fp, s_.format, out + 3 * j)) {
        if (j > 0) throw FatalError("missing data in '" + st.name + "'");
        // An empty file is ignored. (Radiance closes it here without forgetting the FILE, and
        // closes it again with the others.)
        std::fclose(st.fp);
        st.fp = nullptr;
        break;
      }
    }
    out += 3 * static_cast<std::size_t>(m.nbins);
  }
  close_inputs();
}

// recover_output(): the complete records in every file; the files are left open, positioned
// after them, for the run to go on.
long Outputs::recover_records() {
  if (s_.format == 'a') throw FatalError("cannot recover ASCII output");
  const long value_size = s_.format == 'f'   ? 3 * sizeof(float)
                          : s_.format == 'd' ? 3 * sizeof(double)
                                             : sizeof(image::Rgbe);
  const std::string format = options::format_name(s_.format);
  long lastout = -1;
  for (const Modifier& m : mods_) {
    if (!m.spec) throw FatalError("cannot recover from stdout");
    if ((*m.spec)[0] == '!') throw FatalError("cannot recover from command");
    for (int j = 0; j < m.nbins; ++j) {
      Stream& st = streams_[m.streams[static_cast<std::size_t>(j)]];
      if (st.fp) { // opened for an earlier modifier or bin
        if (m.flags & kNamesBin) continue;
        break;
      }
      st.fp = std::fopen(st.name.c_str(), "rb+");
      if (!st.fp) {
        warning("missing recover file '" + st.name + "'");
        lastout = 0;
        break;
      }
      struct stat info;
      if (fstat(fileno(st.fp), &info) != 0 || info.st_size <= 0) {
        lastout = 0; // an empty file: nothing to recover
        std::fclose(st.fp);
        st.fp = nullptr;
        break;
      }
      if (s_.header && !header_has_format(st.fp, format))
        throw FatalError("format mismatch for '" + st.name + "'");
      if (st.reclen == 1 && st.xr > 0 && st.yr > 0 && !resolution_is(st.fp, st.xr, st.yr))
        throw FatalError("resolution mismatch for '" + st.name + "'");
      const long records =
          static_cast<long>((info.st_size - ftello(st.fp)) / (value_size * std::max(st.reclen, 1)));
      if (lastout < 0 || records < lastout) lastout = records;
      if (!(m.flags & kNamesBin)) break; // every bin in this one file
    }
    if (lastout == 0) {
      warning("no previous data to recover");
      close_inputs();
      return 0;
    }
  }
  if (lastout < 0) {
    warning("no output files to recover");
    return 0;
  }
  // rcinit()'s ray count for -x/-y, in records.
  const long long wanted = s_.yres > 0 ? static_cast<long long>(s_.yres) * std::max(s_.xres, 1) : 0;
  if (wanted && lastout >= wanted) {
    warning("output appears to be complete");
    complete_ = true;
    return lastout;
  }
  for (Stream& st : streams_) { // myseeko(): on from the end of each file's header
    if (!st.fp) continue;
    const off_t bytes = static_cast<off_t>(lastout) * value_size * std::max(st.reclen, 1);
    if (fseeko(st.fp, bytes, SEEK_CUR) < 0)
      throw SystemError(std::string("seek error on file '") + st.name +
                        "': " + std::strerror(errno));
  }
  return lastout;
}

} // namespace radcl::contrib

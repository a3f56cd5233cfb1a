// rcontrib's output streams: registration (addmodifier()'s getostream() calls), opening with
// header and resolution string, records (mod_output(), put_contrib()), end of record and
// flushing (end_record()), closing. Recovery is in recover.cpp.
#include "radcl/contrib/output.h"

#include "radcl/image/rgbe.h"
#include "radcl/options/ray_io.h"
#include "radcl/util/error.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <unistd.h>

namespace radcl::contrib {
namespace {

std::string with_reason(std::string msg, int err) {
  if (err > 0) msg += std::string(": ") + std::strerror(err);
  return msg;
}

void put_text(std::FILE* fp, const std::string& s) {
  std::fwrite(s.data(), 1, s.size(), fp);
}

} // namespace

Outputs::Outputs(OutputSettings s) : s_(std::move(s)) {
  if (s_.format != 'a' && s_.format != 'f' && s_.format != 'd' && s_.format != 'c')
    throw std::invalid_argument("rcontrib output format must be one of a f d c");
  // Radiance's override_options(): a single record is never flushed early. (Radiance zeroes
  // them after the options, so streams registered by an earlier -m kept -x/-y given before it;
  // here the whole command line is known, so all streams see the final values.)
  if (s_.accumulate <= 0) s_.xres = s_.yres = 0;
  // rcinit(): a picture is flushed only at the end; otherwise every -x records (never for 0).
  waitflush_ = s_.yres > 0 && s_.xres > 1 ? 0 : s_.xres;
}

Outputs::~Outputs() {
  int err;
  if (!close_all(err)) warning("error closing output stream");
}

// getostream(noopen=1) for bin `bn`: finds or creates the bin's stream (its index goes to
// `index`) and counts the bin in the stream's record. False, without counting, when the
// stream exists already as a picture named by bin: addmodifier() then moves its bin0 on.
bool Outputs::register_bin(const Modifier& m, int bn, int& index) {
  if (!m.spec) {
    index = kStdout;
    ++stdout_.reclen;
    return true;
  }
  std::string name;
  const int flags = output_name(*m.spec, m.name, bn, name);
  if (flags < 0) throw FatalError("bad output format '" + *m.spec + "'");
  const auto [it, created] = by_name_.try_emplace(name, static_cast<int>(streams_.size()));
  index = it->second;
  if (created) {
    Stream st;
    st.name = name;
    st.pipe = name[0] == '!';
    st.xr = s_.xres;
    st.yr = s_.yres;
    streams_.push_back(std::move(st));
    if (!streams_.back().pipe && !s_.force_open && !s_.recover && access(name.c_str(), F_OK) == 0)
      throw SystemError(with_reason("cannot open '" + name + "' for writing", EEXIST));
  } else if (s_.format == 'c' && streams_[index].xr > 0 && streams_[index].yr > 0) {
    if (flags & kNamesBin) return false;
    warning("output '" + name + "' not a valid picture");
  }
  ++streams_[index].reclen;
  return true;
}

int Outputs::add_modifier(const std::optional<std::string>& outspec, const std::string& name,
                          int nbins) {
  if (nbins <= 0) throw std::invalid_argument("a modifier needs at least one bin");
  Modifier m;
  m.spec = outspec;
  m.name = name;
  m.nbins = nbins;
  if (outspec) {
    std::string unused;
    m.flags = output_name(*outspec, name, 0, unused);
  }
  m.streams.resize(static_cast<std::size_t>(nbins));
  while (!register_bin(m, m.bin0, m.streams[0]))
    ++m.bin0;
  // A later bin may land on an existing stream without being counted in it, as in Radiance.
  for (int j = 1; j < nbins; ++j)
    register_bin(m, m.bin0 + j, m.streams[static_cast<std::size_t>(j)]);
  nvalues_ += 3 * static_cast<std::size_t>(nbins);
  mods_.push_back(std::move(m));
  return static_cast<int>(mods_.size()) - 1;
}

void Outputs::open_stdout() {
  if (s_.header) {
    std::string info;
    if (s_.yres > 0) info += "NROWS=" + std::to_string(s_.yres * (s_.xres + !s_.xres)) + '\n';
    if (s_.xres <= 0 || stdout_.reclen > 1)
      info += "NCOLS=" + std::to_string(stdout_.reclen) + '\n';
    put_text(stdout, format_header(s_, info));
  }
  if (stdout_.reclen == 1 && s_.xres > 0 && s_.yres > 0)
    put_text(stdout, options::format_resolution(s_.xres, s_.yres));
  if (waitflush_ > 0) std::fflush(stdout);
  stdout_.fp = stdout;
  stdout_.xr = s_.xres;
  stdout_.yr = s_.yres;
  using_stdout_ = true;
}

// getostream(noopen=0) for a stream not yet open; `m` and `bin` are the first value's, whose
// modifier and bin the header names.
void Outputs::open_stream(Stream& st, const Modifier& m, int bin) {
  errno = 0;
  st.fp = st.pipe ? popen(st.name.c_str() + 1, "w") : std::fopen(st.name.c_str(), "w");
  if (!st.fp) throw SystemError(with_reason("cannot open '" + st.name + "' for writing", errno));
  if (s_.accumulate > 0) {
    st.xr = s_.xres;
    st.yr = s_.yres;
  }
  if (s_.header) {
    std::string info;
    if ((m.flags & kNamesModifier) || st.reclen == 1) info += "MODIFIER=" + m.name + '\n';
    if (m.flags & kNamesBin) info += "BIN=" + std::to_string(m.bin0 + bin) + '\n';
    if (st.yr > 0) info += "NROWS=" + std::to_string(st.yr * (st.xr + !st.xr)) + '\n';
    if (st.xr <= 0 || st.reclen > 1) info += "NCOLS=" + std::to_string(st.reclen) + '\n';
    put_text(st.fp, format_header(s_, info));
  }
  if (st.reclen == 1 && st.xr > 0 && st.yr > 0)
    put_text(st.fp, options::format_resolution(st.xr, st.yr));
  if (waitflush_ > 0) std::fflush(st.fp);
}

// put_contrib(): the value divided by `divisor` (when over 1) in the output format. In -ff it
// is rounded to float before it is scaled, in float, as Radiance's COLOR arithmetic does.
void Outputs::put(std::FILE* fp, const double* c, int divisor) {
  const double sf = divisor > 1 ? 1.0 / divisor : 1.0; // a product with 1 is exact
  switch (s_.format) {
  case 'a':
    std::fprintf(fp, "%.6e\t%.6e\t%.6e\t", sf * c[0], sf * c[1], sf * c[2]);
    break;
  case 'f': {
    float v[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = static_cast<float>(c[i]);
      v[i] = static_cast<float>(v[i] * sf);
    }
    std::fwrite(v, sizeof v[0], 3, fp);
    break;
  }
  case 'd': {
    const double v[3] = {sf * c[0], sf * c[1], sf * c[2]};
    std::fwrite(v, sizeof v[0], 3, fp);
    break;
  }
  case 'c': {
    const image::Rgbe p = image::to_rgbe(sf * c[0], sf * c[1], sf * c[2]);
    std::fwrite(p.data(), 1, p.size(), fp);
    break;
  }
  }
}

void Outputs::write_record(std::span<const double> values, int rays) {
  if (values.size() != nvalues_)
    throw std::invalid_argument("rcontrib record of " + std::to_string(values.size()) +
                                " values for " + std::to_string(nvalues_));
  const int divisor = rays > 0 ? rays : s_.accumulate;
  const double* v = values.data();
  for (const Modifier& m : mods_)
    for (int j = 0; j < m.nbins; ++j, v += 3) {
      const int index = m.streams[static_cast<std::size_t>(j)];
      if (index == kStdout) {
        if (!using_stdout_) open_stdout();
      } else if (!streams_[index].fp) {
        open_stream(streams_[index], m, j);
      }
      put(stream(index).fp, v, divisor);
    }
}

void Outputs::end_record() {
  --waitflush_;
  for (Stream& st : streams_) {
    if (!st.fp) continue;
    if (s_.format == 'a') std::putc('\n', st.fp);
    if (!waitflush_) std::fflush(st.fp);
    if (std::ferror(st.fp))
      throw SystemError(with_reason("write error on file '" + st.name + "'", errno));
  }
  if (using_stdout_ && s_.format == 'a') std::putc('\n', stdout);
  if (!waitflush_) {
    waitflush_ = s_.yres > 0 && s_.xres > 1 ? 0 : s_.xres;
    if (using_stdout_) std::fflush(stdout);
  }
}

void Outputs::request_flush() {
  if (s_.yres <= 0 || s_.xres <= 1) waitflush_ = 1;
}

bool Outputs::close_all(int& err) {
  bool ok = true;
  err = 0;
  for (Stream& st : streams_) {
    if (!st.fp) continue;
    errno = 0;
    const int status = st.pipe ? pclose(st.fp) : std::fclose(st.fp);
    st.fp = nullptr;
    if (status != 0 && ok) {
      ok = false;
      err = status == -1 || !st.pipe ? errno : 0; // a command's exit status has no reason
    }
  }
  if (using_stdout_) std::fflush(stdout);
  return ok;
}

void Outputs::finish() {
  int err;
  if (!close_all(err)) throw SystemError(with_reason("error closing output stream", err));
}

} // namespace radcl::contrib

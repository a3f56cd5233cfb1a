// radcl ambient: Radiance's lookamb. Prints the records of a .amb file (labelled, or -d one
// line of 21 columns each), with the file's header unless -h; -r turns that text back into a
// binary file on stdout (-h: the text has no header, a fresh one is written).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "radcl/ambient/format.h"
#include "radcl/ambient/text.h"
#include "radcl/util/error.h"
#include "radcl_commands.h"

namespace radcl::cli {
namespace {

std::string read_all(const std::string& file) {
  std::ostringstream ss;
  if (file.empty()) {
    ss << std::cin.rdbuf();
  } else {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw FatalError(file + ": file not found");
    ss << in.rdbuf();
  }
  return std::move(ss).str();
}

void put(const std::string& s) {
  if (std::fwrite(s.data(), 1, s.size(), stdout) != s.size())
    throw FatalError("write error on standard output");
}

// Header lines other than FORMAT ones, as checkheader() copies them.
std::string header_text(const image::PictureHeader& h) {
  std::string out;
  for (const auto& l : h.lines)
    if (!ambient::format_value(l)) out += l + '\n';
  return out;
}

void to_text(const std::string& bytes, bool data_only, bool header) {
  const ambient::AmbientContents c = ambient::parse_ambient(bytes, "format error on input");
  if (header) put(header_text(c.header) + "FORMAT=ascii\n\n");
  std::string out;
  for (const auto& r : c.records) {
    out += ambient::format_record(r, data_only);
    if (out.size() > (1u << 16)) {
      put(out);
      out.clear();
    }
  }
  put(out);
}

void to_binary(const std::string& text, bool data_only, bool header,
               const std::vector<std::string>& argv) {
  std::string out;
  std::size_t body = 0;
  if (header) {
    auto hs = ambient::read_header(text);
    if (!hs) throw FatalError("format error on input");
    const std::string fmt = ambient::header_format(hs->header);
    if (!fmt.empty() && fmt != "ascii") throw FatalError("format error on input");
    out = header_text(hs->header);
    body = hs->end;
  } else {
    image::PictureHeader h;
    h.add_id("RADIANCE").add_command(argv);
    out = header_text(h);
  }
  out += std::string("FORMAT=") + ambient::kFormat + "\n\n";
  out += static_cast<char>(ambient::kMagic >> 8);
  out += static_cast<char>(ambient::kMagic & 0xff);
  for (const auto& r : ambient::parse_records(std::string_view(text).substr(body), data_only)) {
    const ambient::RecordBytes b = ambient::encode_record(r);
    out.append(reinterpret_cast<const char*>(b.data()), b.size());
  }
  put(out);
}

} // namespace

int cmd_ambient(int argc, char** argv) {
  bool data_only = false, header = true, reverse = false;
  int i = 1;
  // lookamb's parsing: options up to the first word not starting with '-', one letter each.
  for (; i < argc && argv[i][0] == '-'; ++i) {
    switch (argv[i][1]) {
    case 'd':
      data_only = true;
      break;
    case 'r':
      reverse = true;
      break;
    case 'h':
      header = false;
      break;
    default:
      throw FatalError(std::string("ambient: unknown option '") + argv[i] + "'");
    }
  }
  const std::string file = i < argc ? argv[i] : "";
  const std::string in = read_all(file);
  if (reverse) {
    std::vector<std::string> words{"radcl"};
    words.insert(words.end(), argv, argv + argc);
    to_binary(in, data_only, header, words);
  } else {
    to_text(in, data_only, header);
  }
  if (std::fflush(stdout) != 0) throw FatalError("write error on standard output");
  return 0;
}

} // namespace radcl::cli

// A cache Radiance 5.4a wrote (office_clear_default.amb, 2253 records) against lookamb's
// decoding of it (office_clear_default.amb.txt, `lookamb -h -d`): reading, rewriting, the text
// forms and `radcl ambient`.
#include <algorithm>
#include <gtest/gtest.h>
#include <string>

#include "amb_test_util.h"
#include "radcl/ambient/format.h"
#include "radcl/ambient/text.h"

using namespace radcl::ambient;
namespace rt = radcl::test;

namespace {

std::string reference_text() {
  return rt::read_file(rt::data("results/office_clear_default.amb.txt"));
}

std::string data_lines(const std::vector<AmbientRecord>& records) {
  std::string s;
  for (const auto& r : records)
    s += format_record(r, true);
  return s;
}

// Every tab-separated field "-0.000000" written as "0.000000".
std::string without_negative_zeros(std::string s) {
  const std::string neg = "-0.000000";
  for (std::size_t i = s.find(neg); i != std::string::npos; i = s.find(neg, i)) {
    const bool starts = i == 0 || s[i - 1] == '\t' || s[i - 1] == '\n';
    const bool ends =
        i + neg.size() == s.size() || s[i + neg.size()] == '\t' || s[i + neg.size()] == '\n';
    if (starts && ends)
      s.erase(i, 1);
    else
      ++i;
  }
  return s;
}

std::string radcl_bin() {
  return rt::bin_dir() + "/radcl";
}

} // namespace

TEST(OfficeAmb, HeaderAndRecordCount) {
  const std::string bytes = rt::read_file(rt::office_amb());
  const AmbientContents c = parse_ambient(bytes, "bad ambient file");
  ASSERT_EQ(c.header.lines.size(), 6u);
  EXPECT_EQ(c.header.lines[0], "#?RADIANCE");
  EXPECT_EQ(header_format(c.header), "Radiance_ambval");
  EXPECT_EQ(c.records.size(), 2253u);
  EXPECT_EQ(c.valid_end, bytes.size());
  EXPECT_EQ(c.data_start + 2253 * kRecordSize, bytes.size());
  // The command line initambfile() writes, rebuilt from the settings of that run.
  AmbientSettings s;
  s.progname = "rtrace";
  s.ab = 5;
  s.aa = 0.15;
  s.ad = 1024;
  s.as = 256;
  s.ar = 256;
  s.octree = "office_clear.oct";
  s.software = "RADIANCE 5.4a 2026-11-22 LBNL (5.2.Unknown)";
  const radcl::image::PictureHeader h = new_file_header(s);
  ASSERT_EQ(h.lines.size(), 5u);
  EXPECT_EQ(h.lines[1], c.header.lines[1]);
  EXPECT_EQ(h.lines[2], c.header.lines[2]);
  EXPECT_EQ(h.lines[3].substr(0, 9), "CAPDATE= ");
  EXPECT_EQ(h.lines[4].substr(0, 5), "GMT= ");
  s.octree.reset(); // rpict reading its octree from stdin: the line ends in a space
  EXPECT_EQ(new_file_header(s).lines[1],
            "rtrace -av 0 0 0 -aw 0 -ab 5 -aa 0.15 -ad 1024 -as 256 -ar 256 ");
}

TEST(OfficeAmb, DecodesExactlyAsLookamb) {
  const AmbientContents c = parse_ambient(rt::read_file(rt::office_amb()), "bad ambient file");
  const std::string ours = data_lines(c.records);
  const std::string ref = reference_text();
  ASSERT_EQ(ours.size(), ref.size());
  // Line by line first, so a difference is reported where it is.
  std::size_t line = 1, a = 0;
  while (a < ref.size()) {
    const std::size_t e = ref.find('\n', a);
    ASSERT_EQ(ours.substr(a, e - a), ref.substr(a, e - a)) << "line " << line;
    a = e + 1;
    ++line;
  }
  EXPECT_EQ(ours, ref);
}

TEST(OfficeAmb, RewritingReproducesTheBytes) {
  const std::string bytes = rt::read_file(rt::office_amb());
  const AmbientContents c = parse_ambient(bytes, "bad ambient file");
  std::string out;
  for (const auto& r : c.records) {
    const RecordBytes b = encode_record(r);
    out.append(reinterpret_cast<const char*>(b.data()), b.size());
  }
  EXPECT_TRUE(out == bytes.substr(c.data_start)) << "records differ after the header";
  // Header lines + FORMAT + magic, as file_prologue writes them, are the file's prologue too.
  radcl::image::PictureHeader h = c.header;
  EXPECT_EQ(file_prologue(h), bytes.substr(0, c.data_start));
}

TEST(OfficeAmb, TextRoundTrips) {
  // Reference text -> records -> text is the identity, in both layouts.
  const std::string ref = reference_text();
  const std::vector<AmbientRecord> parsed = parse_records(ref, true);
  ASSERT_EQ(parsed.size(), 2253u);
  EXPECT_TRUE(data_lines(parsed) == ref);
  std::string verbose;
  for (const auto& r : parsed)
    verbose += format_record(r, false);
  const std::vector<AmbientRecord> again = parse_records(verbose, false);
  ASSERT_EQ(again.size(), parsed.size());
  for (std::size_t i = 0; i < again.size(); ++i)
    ASSERT_EQ(encode_record(again[i]), encode_record(parsed[i])) << "record " << i;
  // Each parsed record passes Radiance's reader checks.
  for (const auto& r : parsed)
    ASSERT_TRUE(record_writable(r));
}

TEST(OfficeAmb, VerboseLayout) {
  const AmbientContents c = parse_ambient(rt::read_file(rt::office_amb()), "bad ambient file");
  // First record of the reference text, in lookamb's labelled layout.
  EXPECT_EQ(format_record(c.records[0], false),
            "Position:\t6.000000\t2.530310\t1.835439\n"
            "Normal:\t\t-1.000000\t0.000000\t0.000000\n"
            "Uvector:\t0.000000\t-0.867973\t0.496612\n"
            "Lvl,Wt,UVrad:\t4\t\t0.062500\t8.091707\t8.950824\n"
            "Value:\t\t1.746094e+00\t1.574219e+00\t1.496094e+00\n"
            "Pos.Grad:\t0.078807\t-0.086059\n"
            "Dir.Grad:\t0.949738\t0.919303\n"
            "Corral:\t\t      F8\n\n");
}

TEST(RadclAmbient, DataOnlyWithoutHeaderMatchesLookamb) {
  rt::TempFolder dir("cli-d");
  ASSERT_EQ(rt::run_command(radcl_bin() + " ambient -d -h " + rt::office_amb() + " > " +
                            (dir / "out.txt").string()),
            0);
  EXPECT_TRUE(rt::read_file(dir / "out.txt") == reference_text());
}

TEST(RadclAmbient, HeaderIsCopiedWithAsciiFormat) {
  rt::TempFolder dir("cli-h");
  ASSERT_EQ(rt::run_command(radcl_bin() + " ambient " + rt::office_amb() + " > " +
                            (dir / "out.txt").string()),
            0);
  const std::string out = rt::read_file(dir / "out.txt");
  const std::string head = "#?RADIANCE\n"
                           "rtrace -av 0 0 0 -aw 0 -ab 5 -aa 0.15 -ad 1024 -as 256 -ar 256 "
                           "office_clear.oct\n"
                           "SOFTWARE= RADIANCE 5.4a 2026-11-22 LBNL (5.2.Unknown)\n"
                           "CAPDATE= 2026:11:22 02:03:28\n"
                           "GMT= 2026:11:22 02:03:28\n"
                           "FORMAT=ascii\n\n"
                           "Position:\t6.000000\t2.530310\t1.835439\n";
  EXPECT_EQ(out.substr(0, head.size()), head);
  // Eight lines and a blank one per record.
  EXPECT_EQ(static_cast<std::size_t>(std::count(out.begin(), out.end(), '\n')), 7 + 2253 * 9u);
}

TEST(RadclAmbient, ReverseConversionRoundTrips) {
  rt::TempFolder dir("cli-r");
  const std::string amb = rt::office_amb();
  // Binary -> text with header -> binary: the header comes back with its FORMAT restored, and
  // the records print as before, except that a printed "-0.000000" (a tiny negative) comes
  // back as "0.000000": a 5-byte real's zero has no sign, in Radiance's lookamb -r too.
  ASSERT_EQ(rt::run_command(radcl_bin() + " ambient -d " + amb + " | " + radcl_bin() +
                            " ambient -d -r > " + (dir / "a.amb").string()),
            0);
  const std::string a = rt::read_file(dir / "a.amb");
  const std::string orig = rt::read_file(amb);
  const AmbientContents ca = parse_ambient(a, "bad ambient file");
  const AmbientContents co = parse_ambient(orig, "bad ambient file");
  EXPECT_EQ(a.substr(0, ca.data_start), orig.substr(0, co.data_start));
  ASSERT_EQ(ca.records.size(), co.records.size());
  EXPECT_EQ(ca.valid_end, a.size());
  EXPECT_TRUE(data_lines(ca.records) == without_negative_zeros(reference_text()));
  // The converted file is a fixed point: text and back gives the same bytes, in both
  // layouts; labelled text without header gets a fresh header naming the command.
  ASSERT_EQ(rt::run_command(radcl_bin() + " ambient -d " + (dir / "a.amb").string() + " | " +
                            radcl_bin() + " ambient -d -r > " + (dir / "b.amb").string()),
            0);
  EXPECT_TRUE(rt::read_file(dir / "b.amb") == a);
  ASSERT_EQ(rt::run_command(radcl_bin() + " ambient -h " + (dir / "a.amb").string() + " | " +
                            radcl_bin() + " ambient -h -r > " + (dir / "c.amb").string()),
            0);
  const std::string c = rt::read_file(dir / "c.amb");
  const std::string prologue =
      "#?RADIANCE\nradcl ambient -h -r\nFORMAT=Radiance_ambval\n\n\x02\x2f";
  EXPECT_EQ(c.substr(0, prologue.size()), prologue);
  EXPECT_TRUE(c.substr(prologue.size()) == a.substr(ca.data_start));
}

TEST(RadclAmbient, FormatErrorsAreFatal) {
  rt::TempFolder dir("cli-bad");
  std::string bytes = rt::read_file(rt::office_amb());
  const AmbientContents c = parse_ambient(bytes, "bad ambient file");
  bytes[c.data_start - 1] = 0x2d; // magic 557: a Radiance 4 file
  rt::write_file(dir / "old.amb", bytes);
  std::string out;
  EXPECT_EQ(rt::run_command(radcl_bin() + " ambient -d -h " + (dir / "old.amb").string(), &out), 1);
  EXPECT_EQ(out, "radcl: fatal - format error on input\n");
  // -r on text whose header says it is not ascii.
  rt::write_file(dir / "t.txt", "#?RADIANCE\nFORMAT=Radiance_ambval\n\n");
  out.clear();
  EXPECT_EQ(rt::run_command(radcl_bin() + " ambient -r " + (dir / "t.txt").string(), &out), 1);
  EXPECT_EQ(out, "radcl: fatal - format error on input\n");
  out.clear();
  EXPECT_EQ(rt::run_command(radcl_bin() + " ambient -x", &out), 1);
  EXPECT_EQ(out, "radcl: fatal - ambient: unknown option '-x'\n");
  out.clear();
  EXPECT_EQ(rt::run_command(radcl_bin() + " ambient " + (dir / "missing.amb").string(), &out), 1);
  EXPECT_EQ(out, "radcl: fatal - " + (dir / "missing.amb").string() + ": file not found\n");
}

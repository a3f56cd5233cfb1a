// rcontrib's output streams (Radiance 5.4's rc2.c): where each modifier's bins go (-o specs
// naming the modifier with %s and the bin with %d, standard output, "!command" pipes), the
// header and resolution string each stream starts with, a record's bytes in -fa/-ff/-fd/-fc,
// flushing by -x/-y, and -r's recovery of an interrupted run's files.
#pragma once

#include <cstddef>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace radcl::contrib {

struct OutputSettings {
  char format = 'a';       // -f?x output format: a f d c
  bool header = true;      // -h
  bool force_open = false; // -fo
  bool recover = false;    // -r
  int xres = 0, yres = 0;  // -x -y as given (Outputs zeroes both when accumulate <= 0)
  int accumulate = 1;      // -c (<= 0: one record of everything)
  std::vector<std::string> octree_header; // the octree's header lines, without newlines
  std::vector<std::string> command;       // the words of the command line before the octree
  std::string software;                   // "SOFTWARE= <software>"
  std::time_t time = 0;                   // for CAPDATE= and GMT=
};

// What an output spec names besides fixed text (ofname()'s flags).
inline constexpr int kNamesModifier = 1; // %s
inline constexpr int kNamesBin = 2;      // one of %d %i %o %x %X

// ofname(): the output name of bin `bin` of modifier `modifier`, and the kNames* flags of the
// spec; -1 (and `name` untouched) for a spec with a second %s or bin field, or a '%' that is not
// followed by width digits and one of s d i o x X %.
int output_name(const std::string& spec, const std::string& modifier, int bin, std::string& name);

// printheader(): the octree's header lines (its FORMAT= line dropped), the command, SOFTWARE=,
// CAPDATE=/GMT=, NCOMP=3, `info` (the stream's own lines), BigEndian= for f and d, FORMAT=, and
// the empty line.
std::string format_header(const OutputSettings& s, const std::string& info);

class Outputs {
public:
  // Throws std::invalid_argument for a format other than a f d c.
  explicit Outputs(OutputSettings s);
  ~Outputs(); // closes everything; a failure there is a warning ("error closing output stream")
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;

  // addmodifier()'s stream registration (getostream() without opening): returns the
  // modifier's index. Its first bin number is 0 unless, with -fc and -x/-y, a bin-named picture
  // of an earlier modifier already has that name: it is then the first bin whose name is new.
  // Throws FatalError "bad output format '<spec>'", SystemError "cannot open '<name>' for
  // writing: File exists" for an existing file (not with -fo or -r, nor for "!command"); warns
  // "output '<name>' not a valid picture" when a -fc -x -y picture gets a second value per
  // pixel. After a throw the Outputs is fit only to be destroyed.
  int add_modifier(const std::optional<std::string>& outspec, const std::string& name, int nbins);
  int bin0(int modifier) const { return mods_.at(modifier).bin0; }

  // -r (a no-op unless settings.recover): recover_output() for accumulate > 0, returning the
  // number of complete records in the files, which are then positioned after them (the caller
  // skips that many times accumulate input rays); reload_output() for accumulate <= 0, which
  // returns 0 and fills `reloaded` with the files' totals (modifier-major, bin, rgb; 0 where a
  // file was missing or empty) to add to. `reloaded` is empty otherwise.
  long recover(std::vector<double>& reloaded);
  // After recover(): the files already hold every record that -x/-y ask for (Radiance warned
  // "output appears to be complete" and exits with status 0).
  bool output_complete() const { return complete_; }

  // One record: every modifier's bins in add_modifier order, 3 doubles (rgb) per bin, summed
  // over the record's rays; they are divided by `rays` (0: by accumulate) when that is over 1,
  // as put_contrib() does (rcontrib's final partial record passes the rays it holds). Streams
  // open on first use with their header and resolution string. Throws SystemError "cannot open
  // '<name>' for writing: <reason>".
  void write_record(std::span<const double> values, int rays = 0);
  // end_record(): a newline per stream in -fa, and the flush that -x and request_flush() call
  // for. Throws SystemError "write error on file '<name>'".
  void end_record();
  // A zero-direction input ray: flush after the next end_record() (unless -x -y make a
  // picture, whose rows are not flushed).
  void request_flush();
  // Closes every stream (pclose() for "!command"; standard output is flushed). Throws
  // SystemError "error closing output stream" when one fails (a command's non-zero exit too).
  void finish();

private:
  struct Stream {
    std::string name; // the file name or "!command"
    std::FILE* fp = nullptr;
    bool pipe = false;
    int reclen = 0; // rgb values per record
    int xr = 0, yr = 0;
  };
  struct Modifier {
    std::optional<std::string> spec;
    std::string name;
    int nbins = 0;
    int bin0 = 0;
    int flags = 0;            // output_name()'s, 0 for standard output
    std::vector<int> streams; // per bin: index in streams_, kStdout for standard output
  };
  static constexpr int kStdout = -1;

  bool register_bin(const Modifier& m, int bn, int& index);
  Stream& stream(int index) { return index == kStdout ? stdout_ : streams_[index]; }
  void open_stdout();
  void open_stream(Stream& st, const Modifier& m, int bin);
  void put(std::FILE* fp, const double* rgb, int divisor);
  bool close_all(int& err); // false (and the first failure's errno) when a close failed
  void close_inputs();
  void reload(std::vector<double>& reloaded);
  long recover_records();

  OutputSettings s_;
  long waitflush_ = 0; // records until the next flush; it never reaches 0 again when negative
  std::vector<Stream> streams_;
  std::map<std::string, int> by_name_;
  Stream stdout_;
  bool using_stdout_ = false;
  std::vector<Modifier> mods_;
  std::size_t nvalues_ = 0; // doubles per record
  bool complete_ = false;
};

} // namespace radcl::contrib

// Errors in Radiance's form. Library code throws; only the front ends print and exit, as
// "<program>: fatal - <message>" (or "<program>: warning - <message>").
#pragma once

#include <stdexcept>
#include <string>

namespace radcl {

// A condition Radiance reports as fatal (bad input, missing file, system failure).
class FatalError : public std::runtime_error {
public:
  explicit FatalError(const std::string& msg) : std::runtime_error(msg) {}
};

// Where warnings go. Front ends install their program name; tests may capture them.
using WarningSink = void (*)(const std::string& msg);
void set_warning_sink(WarningSink sink);
void warning(const std::string& msg);

// The program name used in messages ("rtrace", "rpict", "radcl").
void set_program_name(const std::string& name);
const std::string& program_name();

// Runs `body`, printing a FatalError in Radiance's form and returning exit status 1; any
// other exception is an internal error (status 2). Front ends wrap main() in it.
int run_main(const char* progname, int (*body)(int, char**), int argc, char** argv);

} // namespace radcl

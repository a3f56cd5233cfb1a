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

// A failure Radiance reports as a system error ("<program>: system - <message>", exit 2):
// the operating system refused something (a file that cannot be read, memory).
class SystemError : public FatalError {
public:
  explicit SystemError(const std::string& msg) : FatalError(msg) {}
};

// Where warnings go. Front ends install their program name; tests may capture them.
using WarningSink = void (*)(const std::string& msg);
void set_warning_sink(WarningSink sink);
void warning(const std::string& msg);

// The program name used in messages ("rtrace", "rpict", "radcl").
void set_program_name(const std::string& name);
const std::string& program_name();

// The command name as Radiance's fixargv0() makes it from argv[0]: the last path component,
// without an extension, in lower case ("/opt/radcl/bin/rtrace" -> "rtrace").
std::string command_name(const std::string& argv0);

// Runs `body` under the command name of argv[0] (`progname` without one), printing a
// FatalError in Radiance's form with exit status 1 (a SystemError: "system -", status 2); any
// other exception is an internal error (status 2). Front ends wrap main() in it.
int run_main(const char* progname, int (*body)(int, char**), int argc, char** argv);

} // namespace radcl

// Persistent rtrace/rpict (-P file, -PP file; ../shared/docs/radiance/cli-rtrace-rpict.md §3.9,
// protocol in docs/internals.md, docs/drop-in.md). The first invocation serves its own input and
// then starts a server: the same binary re-executed in a hidden mode, which loads the scene itself
// (OpenCL state does not survive fork(), so a process that has initialised it is never forked) and
// waits for later invocations to attach through named pipes listed in the control file.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace radcl::cli {

enum class PersistMode { Single, Parallel }; // -P: one job at a time; -PP: one process per job

// The -P/-PP file named on a raw command line (before any parsing), or "".
std::string find_persist_file(const std::vector<std::string>& args, PersistMode* mode);

// True in the process started by start_persist_server().
bool is_persist_server();

// Creates the control file exclusively (empty: "a server is coming"). False when it exists.
// Until release_persist_file(), a fatal exit of this process removes it again.
bool create_persist_file(const std::string& path);
void release_persist_file();

// Attaches to the server named in the control file: feeds it our standard input, copies its
// output and errors to ours. Returns the exit status to use (1 after a fatal error there).
int attach_persist(const std::string& path, const std::string& progname);

// Starts the detached server process: this binary again, with the same arguments.
void start_persist_server(const std::vector<std::string>& argv);

struct PersistJobs {
  // Makes the process ready to serve (device program, renderer). In -PP mode it runs in each
  // job's process, so the server process itself never initialises OpenCL.
  std::function<void()> prepare;
  // One job on standard input/output/error (already redirected). Throws FatalError.
  std::function<void()> serve;
  bool keep_stderr = false; // -e names an error file: messages go there, not to the client
};

// The server's loop; returns when the control file is removed, replaced or left unattended
// for 8 hours (Radiance's limit), after removing its pipes.
int run_persist_server(const std::string& path, const std::string& progname, PersistMode mode,
                       const PersistJobs& jobs);

} // namespace radcl::cli

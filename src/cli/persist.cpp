#include "persist.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fcntl.h>
#include <poll.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "radcl/util/error.h"

extern char** environ;

namespace radcl::cli {
namespace {

constexpr const char* kServerEnv = "RADCL_PERSIST_SERVER";
constexpr const char* kParentEnv = "RADCL_PERSIST_PARENT";
constexpr const char* kMagic = "radcl-persist";
constexpr int kIdleLimit = 8 * 3600; // Radiance's TIMELIM for an idle server
constexpr int kAttachWait = 600;     // seconds a client waits for a server to get ready

std::string g_owned; // control file this process created and must remove on a fatal exit

void remove_owned() {
  if (!g_owned.empty()) ::unlink(g_owned.c_str());
}

std::string temp_dir(const char* stem) {
  const char* t = std::getenv("TMPDIR");
  std::string tmpl = std::string(t && *t ? t : "/tmp") + "/" + stem + "XXXXXX";
  if (!::mkdtemp(tmpl.data())) throw FatalError("cannot create directory for named pipes");
  return tmpl;
}

void make_fifo(const std::string& path) {
  if (::mkfifo(path.c_str(), 0600) < 0) throw FatalError("cannot create named pipe " + path);
}

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

std::string read_file(const std::string& path, bool& exists) {
  int fd = ::open(path.c_str(), O_RDONLY);
  exists = fd >= 0;
  std::string s;
  if (fd < 0) return s;
  char buf[4096];
  ssize_t n;
  while ((n = ::read(fd, buf, sizeof buf)) > 0)
    s.append(buf, static_cast<std::size_t>(n));
  ::close(fd);
  return s;
}

std::string base_name(const std::string& p) {
  std::size_t k = p.find_last_of('/');
  return k == std::string::npos ? p : p.substr(k + 1);
}

struct ServerInfo {
  std::string program;
  long pid = 0;
  std::string dir;
};

// "radcl-persist <program> <pid>\n<dir>\n"; false while it is still empty (server starting).
bool parse_control(const std::string& text, ServerInfo& info) {
  if (text.empty()) return false;
  std::istringstream in(text);
  std::string magic;
  in >> magic >> info.program >> info.pid;
  in.ignore(1);
  std::getline(in, info.dir);
  if (magic != kMagic || info.pid <= 0 || info.dir.empty() || text.back() != '\n')
    throw FatalError("format error in persist file");
  return true;
}

// The job's pipes become standard input, output and (unless -e names a file) error.
class Redirect {
public:
  Redirect(const std::string& dir, bool errors) {
    fflush(stdout);
    fflush(stderr);
    int in = ::open((dir + "/in").c_str(), O_RDONLY);
    int out = in < 0 ? -1 : ::open((dir + "/out").c_str(), O_WRONLY);
    int err = out < 0 ? -1 : ::open((dir + "/err").c_str(), O_WRONLY);
    ok_ = err >= 0;
    for (int fd : {0, 1, 2})
      saved_[fd] = ::dup(fd);
    if (ok_) {
      ::dup2(in, 0);
      ::dup2(out, 1);
      if (errors) ::dup2(err, 2);
    }
    for (int fd : {in, out, err})
      if (fd >= 0) ::close(fd);
    clearerr(stdin);
  }
  ~Redirect() {
    fflush(stdout);
    fflush(stderr);
    for (int fd : {0, 1, 2}) {
      ::dup2(saved_[fd], fd);
      ::close(saved_[fd]);
    }
    clearerr(stdout);
    clearerr(stderr);
  }
  bool ok() const { return ok_; }

private:
  bool ok_ = false;
  int saved_[3] = {-1, -1, -1};
};

// Runs one attached job; false after a fatal error (reported to the client).
bool serve_client(const std::string& dir, const std::string& progname, const PersistJobs& jobs) {
  Redirect r(dir, !jobs.keep_stderr);
  if (!r.ok()) return true; // the client went away before connecting
  try {
    jobs.serve();
    return true;
  } catch (const FatalError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: fatal - %s\n", program_name().c_str(), e.what());
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: internal error - %s\n", program_name().c_str(), e.what());
  }
  return false;
}

} // namespace

std::string find_persist_file(const std::vector<std::string>& args, PersistMode* mode) {
  for (std::size_t i = 1; i + 1 < args.size(); ++i)
    if (args[i] == "-P" || args[i] == "-PP") {
      if (mode) *mode = args[i] == "-P" ? PersistMode::Single : PersistMode::Parallel;
      return args[i + 1];
    }
  return "";
}

// The environment as the program started: libraries change it in-process (an OpenCL driver
// removing itself from OCL_ICD_FILENAMES, PoCL setting HWLOC_PLUGINS_PATH), and the server
// must start as the first run did.
std::vector<std::string>& initial_environment() {
  static std::vector<std::string> env = [] {
    std::vector<std::string> v;
    for (char** e = environ; *e; ++e)
      v.emplace_back(*e);
    return v;
  }();
  return env;
}

bool is_persist_server() {
  initial_environment();
  static const bool server = [] {
    const char* v = std::getenv(kServerEnv);
    bool s = v && std::string(v) == "1";
    ::unsetenv(kServerEnv); // commands the scene runs are ordinary processes
    // The first run is still exiting: on a GPU in exclusive-process compute mode its device
    // context must be gone before ours can exist, so wait for it (a few seconds at most).
    if (const char* p = std::getenv(kParentEnv)) {
      pid_t parent = static_cast<pid_t>(std::atol(p));
      for (int i = 0; s && parent > 0 && i < 300 && ::kill(parent, 0) == 0; ++i)
        ::usleep(20000);
      ::unsetenv(kParentEnv);
    }
    return s;
  }();
  return server;
}

bool create_persist_file(const std::string& path) {
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    if (errno == EEXIST) return false;
    throw FatalError("cannot open persist file \"" + path + "\"");
  }
  ::close(fd);
  static bool registered = false;
  if (!registered) std::atexit(remove_owned);
  registered = true;
  g_owned = path;
  return true;
}

void release_persist_file() {
  g_owned.clear();
}

int attach_persist(const std::string& path, const std::string& progname) {
  std::signal(SIGPIPE, SIG_IGN);
  ServerInfo info;
  for (int waited = 0;; ++waited) {
    bool exists = false;
    std::string text = read_file(path, exists);
    if (!exists) throw FatalError("cannot open persist file \"" + path + "\"");
    if (parse_control(text, info)) break;
    if (waited >= kAttachWait * 10) throw FatalError("unattended persist file?");
    ::usleep(100000);
  }
  const std::string me = base_name(progname);
  if (info.program != me) throw FatalError("persist file for " + info.program + ", not " + me);
  const pid_t server = static_cast<pid_t>(info.pid);
  auto alive = [&] { return ::kill(server, 0) == 0 || errno == EPERM; };
  if (!alive())
    throw FatalError("cannot signal rendering process (PID " + std::to_string(server) + ")");

  const std::string dir = temp_dir("radclc");
  const std::string in = dir + "/in", out = dir + "/out", err = dir + "/err";
  auto cleanup = [&] {
    for (const std::string& f : {in, out, err})
      ::unlink(f.c_str());
    ::rmdir(dir.c_str());
  };
  int fin = -1, fout = -1, ferr = -1;
  try {
    make_fifo(in);
    make_fifo(out);
    make_fifo(err);
    int req = ::open((info.dir + "/request").c_str(), O_WRONLY | O_NONBLOCK);
    if (req < 0)
      throw FatalError("cannot attach to persist server (PID " + std::to_string(server) + ")");
    std::string line = dir + "\n"; // shorter than PIPE_BUF: written at once among other clients
    bool sent = write_all(req, line.data(), line.size());
    ::close(req);
    if (!sent) throw FatalError("cannot attach to persist server");
    // The server opens our pipes in the order in, out, err when it takes the job (after the
    // jobs before ours with -P); we wait for it as long as it lives.
    while ((fin = ::open(in.c_str(), O_WRONLY | O_NONBLOCK)) < 0) {
      if (errno != ENXIO || !alive()) throw FatalError("persist server went away");
      ::usleep(10000);
    }
    ::fcntl(fin, F_SETFL, ::fcntl(fin, F_GETFL) & ~O_NONBLOCK);
    fout = ::open(out.c_str(), O_RDONLY);
    ferr = ::open(err.c_str(), O_RDONLY);
    if (fout < 0 || ferr < 0) throw FatalError("cannot open output pipe of persist server");
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup(); // both ends are open: the names are no longer needed

  // Feeder: our input to the job until either ends.
  std::thread([fin] {
    char buf[65536];
    ssize_t n;
    while ((n = ::read(0, buf, sizeof buf)) > 0)
      if (!write_all(fin, buf, static_cast<std::size_t>(n))) break;
    ::close(fin);
  }).detach();

  int status = 0;
  std::string errors;
  pollfd p[2] = {{fout, POLLIN, 0}, {ferr, POLLIN, 0}};
  int open_fds = 2;
  while (open_fds > 0) {
    if (::poll(p, 2, -1) < 0) {
      if (errno == EINTR) continue;
      throw FatalError("poll error while attached to persist server");
    }
    for (int k = 0; k < 2; ++k) {
      if (p[k].fd < 0 || !(p[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buf[65536];
      ssize_t n = ::read(p[k].fd, buf, sizeof buf);
      if (n <= 0) {
        ::close(p[k].fd);
        p[k].fd = -1;
        --open_fds;
        continue;
      }
      if (k == 0) {
        if (!write_all(1, buf, static_cast<std::size_t>(n))) throw FatalError("write error");
      } else {
        errors.append(buf, static_cast<std::size_t>(n));
        write_all(2, buf, static_cast<std::size_t>(n));
      }
    }
  }
  // The job's exit status, deduced from its messages as Radiance's go-between does.
  if (errors.find(": fatal - ") != std::string::npos) status = 1;
  if (errors.find(": internal error - ") != std::string::npos) status = 2;
  return status;
}

void start_persist_server(const std::vector<std::string>& argv) {
  std::vector<char*> a;
  for (const std::string& s : argv)
    a.push_back(const_cast<char*>(s.c_str()));
  a.push_back(nullptr);
  std::vector<std::string> env_store;
  for (const std::string& e : initial_environment())
    if (e.compare(0, std::strlen(kServerEnv), kServerEnv) != 0 &&
        e.compare(0, std::strlen(kParentEnv), kParentEnv) != 0)
      env_store.push_back(e);
  env_store.push_back(std::string(kServerEnv) + "=1");
  env_store.push_back(std::string(kParentEnv) + "=" + std::to_string(::getpid()));
  std::vector<char*> env;
  for (std::string& s : env_store)
    env.push_back(s.data());
  env.push_back(nullptr);

  // fork + exec rather than posix_spawn: the child must close every descriptor it inherits
  // before exec, or a GPU driver's open device files (NVIDIA's are not close-on-exec) leave the
  // server without a usable device.
  const char* log = std::getenv("RADCL_PERSIST_LOG");
  std::string logfile = log ? log : "";
  std::fflush(nullptr);
  pid_t pid = ::fork();
  if (pid < 0) throw FatalError("cannot start persist server");
  if (pid == 0) {
    ::setsid();
    int null = ::open("/dev/null", O_RDWR);
    // RADCL_PERSIST_LOG names a file for the server's own messages (they are lost otherwise).
    int err = logfile.empty() ? null : ::open(logfile.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    ::dup2(null, 0);
    ::dup2(null, 1); // detached from our pipes: whoever reads our output sees its end
    ::dup2(err >= 0 ? err : null, 2);
    // Nothing of our signal state either (exec keeps ignored signals and the mask).
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    for (int sig = 1; sig < NSIG; ++sig)
      if (sig != SIGKILL && sig != SIGSTOP) std::signal(sig, SIG_DFL);
    long maxfd = ::sysconf(_SC_OPEN_MAX);
    for (long fd = 3; fd < (maxfd > 0 ? maxfd : 1024); ++fd)
      ::close(static_cast<int>(fd));
    ::execve("/proc/self/exe", a.data(), env.data());
    ::_exit(127);
  }
  // The server owns the control file from now on.
  release_persist_file();
}

int run_persist_server(const std::string& path, const std::string& progname, PersistMode mode,
                       const PersistJobs& jobs) {
  std::signal(SIGPIPE, SIG_IGN); // a client that goes away must not end the server
  struct stat st0;
  if (::stat(path.c_str(), &st0) < 0) return 0; // removed before we started
  g_owned = path;                               // a fatal error here removes it
  std::atexit(remove_owned);
  const std::string dir = temp_dir("radclp");
  const std::string request = dir + "/request";
  int req = -1, warm_fd = -1;
  pid_t warm = -1;
  int rc = 0;
  try {
    make_fifo(request);
    // Read-write: the pipe never reports end-of-file between clients.
    req = ::open(request.c_str(), O_RDWR | O_NONBLOCK);
    if (req < 0) throw FatalError("cannot open named pipe " + request);
    if (mode == PersistMode::Single) jobs.prepare();
    {
      std::string text = std::string(kMagic) + " " + base_name(progname) + " " +
                         std::to_string(::getpid()) + "\n" + dir + "\n";
      int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC);
      if (fd < 0 || !write_all(fd, text.data(), text.size()))
        throw FatalError("error writing persist file");
      ::close(fd);
    }
    auto last = std::chrono::steady_clock::now();
    std::string pending;
    bool running = true;
    while (running) {
      if (mode == PersistMode::Parallel && warm < 0) {
        // A process ready for the next job, forked before any OpenCL exists in this one.
        int p[2];
        if (::pipe(p) < 0) throw FatalError("cannot create pipe for persist job");
        std::fflush(nullptr);
        warm = ::fork();
        if (warm < 0) throw FatalError("cannot fork process for persist function");
        if (warm == 0) {
          ::close(p[1]);
          ::close(req);
          g_owned.clear();
          int status = 0;
          try {
            jobs.prepare();
            std::string job;
            char c;
            while (::read(p[0], &c, 1) == 1 && c != '\n')
              job += c;
            if (!job.empty()) status = serve_client(job, progname, jobs) ? 0 : 1;
          } catch (const FatalError& e) {
            std::fprintf(stderr, "%s: fatal - %s\n", program_name().c_str(), e.what());
            status = 1;
          }
          std::fflush(nullptr);
          ::_exit(status);
        }
        ::close(p[0]);
        warm_fd = p[1];
      }
      pollfd pf{req, POLLIN, 0};
      int n = ::poll(&pf, 1, pending.find('\n') != std::string::npos ? 0 : 500);
      // Removing (or replacing) the control file ends the server.
      struct stat st;
      if (::stat(path.c_str(), &st) < 0 || st.st_ino != st0.st_ino || st.st_dev != st0.st_dev) {
        g_owned.clear();
        break;
      }
      for (pid_t done; (done = ::waitpid(-1, nullptr, WNOHANG)) > 0;)
        if (done == warm) { // died before it got a job: nothing more will work
          warm = -1;
          ::close(warm_fd);
          warm_fd = -1;
          throw FatalError("persist job process failed");
        }
      if (n <= 0 && pending.find('\n') == std::string::npos) {
        if (std::chrono::steady_clock::now() - last > std::chrono::seconds(kIdleLimit)) break;
        continue;
      }
      char buf[4096];
      ssize_t got;
      while (n > 0 && (got = ::read(req, buf, sizeof buf)) > 0)
        pending.append(buf, static_cast<std::size_t>(got));
      for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos;) {
        std::string job = pending.substr(0, nl);
        pending.erase(0, nl + 1);
        last = std::chrono::steady_clock::now();
        if (mode == PersistMode::Single) {
          if (!serve_client(job, progname, jobs)) { // Radiance's server quits on an error
            running = false;
            rc = 1;
            break;
          }
        } else {
          job += '\n';
          write_all(warm_fd, job.data(), job.size());
          ::close(warm_fd);
          warm_fd = -1;
          warm = -1;
          break; // the next job needs the next process
        }
      }
    }
  } catch (const FatalError& e) {
    std::fprintf(stderr, "%s: fatal - %s\n", program_name().c_str(), e.what());
    rc = 1;
  }
  if (warm_fd >= 0) ::close(warm_fd); // the idle job process sees the end and exits
  if (req >= 0) ::close(req);
  ::unlink(request.c_str());
  ::rmdir(dir.c_str());
  remove_owned();
  g_owned.clear();
  return rc;
}

} // namespace radcl::cli

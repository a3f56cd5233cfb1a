#include "radcl/cost/timed_run.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <map>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "radcl/util/error.h"

extern char** environ;

namespace radcl::cost {

RunTime run_timed(const TimedRun& r) {
  // The errors go to a file beside the output (a pipe would need reading while it runs).
  const std::string err = r.out + ".err";
  std::map<std::string, std::string> env;
  for (char** e = environ; *e; ++e) {
    const char* eq = std::strchr(*e, '=');
    if (eq) env[std::string(*e, static_cast<std::size_t>(eq - *e))] = eq + 1;
  }
  for (const auto& [k, v] : r.env)
    env[k] = v;
  std::vector<std::string> env_words;
  for (const auto& [k, v] : env)
    env_words.push_back(k + "=" + v);
  std::vector<char*> envp, argv;
  for (std::string& w : env_words)
    envp.push_back(w.data());
  envp.push_back(nullptr);
  std::vector<std::string> args = r.argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, r.in.empty() ? "/dev/null" : r.in.c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, r.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const auto start = std::chrono::steady_clock::now();
  const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw FatalError("cannot run " + r.argv[0] + ": " + std::strerror(rc));
  int st = 0;
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) throw FatalError("lost " + r.argv[0] + ": " + std::strerror(errno));
  RunTime t;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
  std::ifstream e(err, std::ios::binary);
  t.errors.assign(std::istreambuf_iterator<char>(e), {});
  if (t.errors.size() > 2000) t.errors.erase(0, t.errors.size() - 2000);
  std::remove(err.c_str());
  return t;
}

double run_or_fail(const TimedRun& r) {
  RunTime t = run_timed(r);
  if (t.status != 0) {
    std::string cmd;
    for (const std::string& a : r.argv)
      cmd += (cmd.empty() ? "" : " ") + a;
    while (!t.errors.empty() && t.errors.back() == '\n')
      t.errors.pop_back();
    throw FatalError("\"" + cmd + "\" failed (exit status " + std::to_string(t.status) + ")" +
                     (t.errors.empty() ? "" : ":\n" + t.errors));
  }
  return t.seconds;
}

} // namespace radcl::cost

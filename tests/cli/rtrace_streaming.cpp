// rtrace as a co-process: each answer arrives before the next ray is sent. While it builds an
// irradiance cache it answers at Radiance's flush points only (a zero-direction ray, -x 1), so
// that its output does not depend on input timing (tests/cli/stability_determinism.cpp).
#include <csignal>
#include <cstdio>
#include <cstring>
#include <gtest/gtest.h>
#include <poll.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "temp_dir.h"
#include "test_env.h"

namespace {

struct CoProcess {
  pid_t pid = -1;
  int to = -1, from = -1;
  CoProcess(const std::string& dir, const std::vector<std::string>& argv) {
    int in[2], out[2];
    EXPECT_EQ(pipe(in), 0);
    EXPECT_EQ(pipe(out), 0);
    pid = fork();
    if (pid == 0) {
      dup2(in[0], 0);
      dup2(out[1], 1);
      close(in[1]);
      close(out[0]);
      if (chdir(dir.c_str()) != 0) _exit(127);
      std::vector<char*> a;
      for (const std::string& s : argv)
        a.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      execv(a[0], a.data());
      _exit(127);
    }
    close(in[0]);
    close(out[1]);
    to = in[1];
    from = out[0];
  }
  // One line of output, waiting at most `ms`; "" on timeout.
  std::string read_line(int ms) {
    std::string line;
    char c;
    while (true) {
      pollfd p{from, POLLIN, 0};
      if (poll(&p, 1, ms) <= 0) return "";
      if (read(from, &c, 1) != 1) return line;
      if (c == '\n') return line;
      line += c;
    }
  }
  int finish() {
    close(to);
    close(from);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

} // namespace

TEST(RtraceStreaming, AnswersEachRayBeforeTheNext) {
  CoProcess p(radcl::test::data("scenes"), {radcl::test::bin_dir() + "/rtrace", "-h", "-I", "-ab",
                                            "0", "-u-", "-ds", "0", "luminaires.oct"});
  const char* rays[] = {"1.5 1.5 0.75 0 0 1\n", "4 3 0.75 0 0 1\n", "6.5 4.5 0.75 0 0 1\n"};
  for (const char* r : rays) {
    ASSERT_EQ(write(p.to, r, std::strlen(r)), static_cast<ssize_t>(std::strlen(r)));
    // Generous limit: the first answer includes building the device program.
    std::string line = p.read_line(60000);
    ASSERT_FALSE(line.empty()) << "no answer to " << r;
    double v[3];
    ASSERT_EQ(std::sscanf(line.c_str(), "%le %le %le", &v[0], &v[1], &v[2]), 3) << line;
    EXPECT_GT(v[1], 0.0) << line;
  }
  EXPECT_EQ(p.finish(), 0);
}

// Building a cache: a ray followed by a flush request (a zero direction) is answered before
// the next one is sent, and so is each ray with -x 1; both as Radiance's rtrace answers.
TEST(RtraceStreaming, BuildingACacheAnswersAtFlushPoints) {
  const std::string rtrace = radcl::test::bin_dir() + "/rtrace";
  const char* rays[] = {"1.5 1.5 0.75 0 0 1\n", "4 3 0.75 0 0 1\n"};
  {
    CoProcess p(radcl::test::data("scenes"), {rtrace, "-h", "-I", "-ab", "1", "-aa", "0.2", "-ad",
                                              "64", "-as", "0", "-u-", "luminaires.oct"});
    for (const char* r : rays) {
      std::string in = std::string(r) + "0 0 0 0 0 0\n";
      ASSERT_EQ(write(p.to, in.data(), in.size()), static_cast<ssize_t>(in.size()));
      std::string line = p.read_line(60000);
      ASSERT_FALSE(line.empty()) << "no answer to " << r;
      const std::string empty = p.read_line(60000);
      double v[3] = {1, 1, 1};
      ASSERT_EQ(std::sscanf(empty.c_str(), "%le %le %le", &v[0], &v[1], &v[2]), 3) << empty;
      EXPECT_EQ(v[0] + v[1] + v[2], 0.0) << "the flush request's empty record: " << empty;
    }
    EXPECT_EQ(p.finish(), 0);
  }
  CoProcess p(radcl::test::data("scenes"), {rtrace, "-h", "-I", "-ab", "1", "-aa", "0.2", "-ad",
                                            "64", "-as", "0", "-u-", "-x", "1", "luminaires.oct"});
  for (const char* r : rays) {
    ASSERT_EQ(write(p.to, r, std::strlen(r)), static_cast<ssize_t>(std::strlen(r)));
    ASSERT_FALSE(p.read_line(60000).empty()) << "no answer to " << r << " with -x 1";
  }
  EXPECT_EQ(p.finish(), 0);
}

// A tool driving rtrace with its options in a file and -x N (no -y): every N rays are answered
// before it sends more.
TEST(RtraceStreaming, FlushesEveryXRays) {
  const radcl::test::TempFolder dir("stream");
  const std::string opt = (dir / "x.opt").string();
  {
    std::FILE* f = std::fopen(opt.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("-h\n-I\n-ab 0\n-u-\n", f);
    std::fclose(f);
  }
  const std::string rtrace = radcl::test::bin_dir() + "/rtrace";
  const std::string two = "1.5 1.5 0.75 0 0 1\n4 3 0.75 0 0 1\n";
  CoProcess p(radcl::test::data("scenes"), {rtrace, "@" + opt, "-x", "2", "luminaires.oct"});
  for (int round = 0; round < 2; ++round) {
    ASSERT_EQ(write(p.to, two.data(), two.size()), static_cast<ssize_t>(two.size()));
    for (int k = 0; k < 2; ++k)
      ASSERT_FALSE(p.read_line(60000).empty()) << "round " << round << ", answer " << k;
  }
  EXPECT_EQ(p.finish(), 0);
}

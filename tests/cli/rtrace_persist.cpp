// Persistent rtrace (-P, -PP): the first run answers its own input and leaves a server behind;
// later `rtrace -P file` runs attach and get what the full command would give.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <future>
#include <gtest/gtest.h>
#include <string>
#include <thread>
#include <unistd.h>

#include "temp_dir.h"
#include "test_env.h"

using radcl::test::run_command;
namespace fs = std::filesystem;

namespace {

const std::string kOpts = "-h -ab 0 -u- ";
const std::string kRays1 = "0.5 0.1 0.5 0 1 0\n";
const std::string kRays2 = "0.5 0.1 0.5 0 1 0.2\n0.3 0.1 0.5 0 1 0\n0.7 0.2 0.4 0.1 1 -0.3\n";

class RtracePersist : public radcl::test::TempDir {
protected:
  std::string pfile;
  void SetUp() override {
    TempDir::SetUp();
    pfile = (dir / "pfile").string();
    std::ofstream(dir / "rays1") << kRays1;
    std::ofstream(dir / "rays2") << kRays2;
  }
  void TearDown() override {
    fs::remove(pfile); // ends any server left behind
    TempDir::TearDown();
  }
  int rtrace(const std::string& args, std::string* out) {
    out->clear();
    return run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                           "/rtrace " + args,
                       out);
  }
  // The server's pid from the control file, once it is ready.
  long server_pid() {
    for (int i = 0; i < 600; ++i) {
      std::ifstream f(pfile);
      std::string magic, prog;
      long pid = 0;
      if (f >> magic >> prog >> pid) return pid;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return 0;
  }
};

bool alive(long pid) {
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) == 0;
}

TEST_F(RtracePersist, LaterRunsAttachAndGetPlainAnswers) {
  std::string first, plain1, attached, plain2;
  ASSERT_EQ(rtrace(kOpts + "-P " + pfile + " cornell.oct < " + (dir / "rays1").string(), &first), 0)
      << first;
  ASSERT_EQ(rtrace(kOpts + "cornell.oct < " + (dir / "rays1").string(), &plain1), 0);
  EXPECT_EQ(first, plain1);
  ASSERT_TRUE(fs::exists(pfile));
  long pid = server_pid();
  ASSERT_TRUE(alive(pid));
  // No other arguments needed.
  ASSERT_EQ(rtrace("-P " + pfile + " < " + (dir / "rays2").string(), &attached), 0) << attached;
  ASSERT_EQ(rtrace(kOpts + "cornell.oct < " + (dir / "rays2").string(), &plain2), 0);
  EXPECT_EQ(std::count(plain2.begin(), plain2.end(), '\n'), 3);
  EXPECT_EQ(attached, plain2);
  // Again: the server stays for more.
  ASSERT_EQ(rtrace("-P " + pfile + " < " + (dir / "rays2").string(), &attached), 0);
  EXPECT_EQ(attached, plain2);
  // Removing the control file ends the server, which cleans up after itself.
  fs::remove(pfile);
  for (int i = 0; i < 100 && alive(pid); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(alive(pid));
}

TEST_F(RtracePersist, ParallelServesConcurrentClients) {
  std::string first, plain2;
  ASSERT_EQ(rtrace(kOpts + "-PP " + pfile + " cornell.oct < " + (dir / "rays1").string(), &first),
            0)
      << first;
  ASSERT_EQ(rtrace(kOpts + "cornell.oct < " + (dir / "rays2").string(), &plain2), 0);
  long pid = server_pid();
  ASSERT_TRUE(alive(pid));
  auto client = [&] {
    std::string out;
    int rc = run_command(
        radcl::test::bin_dir() + "/rtrace -PP " + pfile + " < " + (dir / "rays2").string(), &out);
    return std::make_pair(rc, out);
  };
  auto a = std::async(std::launch::async, client);
  auto b = std::async(std::launch::async, client);
  auto ra = a.get(), rb = b.get();
  EXPECT_EQ(ra.first, 0) << ra.second;
  EXPECT_EQ(rb.first, 0) << rb.second;
  EXPECT_EQ(ra.second, plain2);
  EXPECT_EQ(rb.second, plain2);
  fs::remove(pfile);
  for (int i = 0; i < 100 && alive(pid); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(alive(pid));
}

TEST_F(RtracePersist, Errors) {
  std::string out;
  EXPECT_NE(rtrace(kOpts + "-n 2 -P " + pfile + " cornell.oct < /dev/null", &out), 0);
  EXPECT_NE(out.find("multiprocessing incompatible with persist file"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(pfile));
  // A control file that no server fills: the client reports it after waiting (here: a file of
  // another format is refused at once).
  std::ofstream(pfile) << "garbage\n";
  EXPECT_NE(rtrace("-P " + pfile + " < /dev/null", &out), 0);
  EXPECT_NE(out.find("format error in persist file"), std::string::npos) << out;
}

} // namespace

// Program binaries are cached on disk by a key over source, options and device; a second build
// of the same program loads the binary, a changed option or source does not.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "device_fixture.h"
#include "radcl/device/buffer.h"
#include "radcl/device/program.h"
#include "radcl/util/error.h"

using namespace radcl::device;
namespace fs = std::filesystem;

namespace {
// Each test gets an empty cache folder of its own.
struct CacheDir {
  fs::path dir;
  explicit CacheDir(const char* name) {
    const char* base = std::getenv("RADCL_CACHE_DIR");
    dir = fs::path(base ? base : "/tmp") / "cache-tests" / name;
    fs::remove_all(dir);
    setenv("RADCL_CACHE_DIR", dir.c_str(), 1);
  }
  std::size_t binaries() const {
    std::size_t n = 0;
    if (fs::exists(dir / "programs"))
      for (auto& e : fs::directory_iterator(dir / "programs"))
        n += e.path().extension() == ".bin";
    return n;
  }
};
} // namespace

TEST(ProgramCache, SecondBuildLoadsBinaryAndStillRuns) {
  CacheDir cache("reuse");
  Context& ctx = test_context();
  ProgramSource src{{"probe/rng.cl"}, "", "-cl-std=CL1.2"};
  Program first(ctx, src);
  EXPECT_FALSE(first.loaded_from_cache());
  EXPECT_EQ(cache.binaries(), 1u);
  Program second(ctx, src);
  EXPECT_TRUE(second.loaded_from_cache());
  EXPECT_EQ(first.cache_key(), second.cache_key());

  // The cached program computes the same as the one built from source.
  Buffer b1(ctx, 64 * 4), b2(ctx, 64 * 4), u(ctx, 64 * 4);
  Kernel k1 = first.kernel("rc_rng_fill"), k2 = second.kernel("rc_rng_fill");
  std::uint32_t n = 64, dims = 1, seed = 5;
  k1.arg(0, b1).arg(1, u).arg(2, n).arg(3, dims).arg(4, seed);
  k2.arg(0, b2).arg(1, u).arg(2, n).arg(3, dims).arg(4, seed);
  ctx.run(k1, n);
  ctx.run(k2, n);
  EXPECT_EQ(b1.to_vector<std::uint32_t>(n), b2.to_vector<std::uint32_t>(n));
}

TEST(ProgramCache, KeyDependsOnOptionsAndSource) {
  CacheDir cache("keys");
  Context& ctx = test_context();
  Program a(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2"});
  Program b(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2 -DRADCL_X=1"});
  Program c(ctx, ProgramSource{{"probe/rng.cl"}, "/* other generated code */", "-cl-std=CL1.2"});
  EXPECT_NE(a.cache_key(), b.cache_key());
  EXPECT_EQ(a.source(), c.source()); // rng.cl does not include generated.cl
  EXPECT_FALSE(b.loaded_from_cache());
  EXPECT_EQ(cache.binaries(), 2u);
}

TEST(ProgramCache, CorruptBinaryIsRebuilt) {
  CacheDir cache("corrupt");
  Context& ctx = test_context();
  ProgramSource src{{"probe/layout.cl"}, "", "-cl-std=CL1.2"};
  std::string key = Program(ctx, src).cache_key();
  std::ofstream(cache.dir / "programs" / (key + ".bin"), std::ios::binary) << "garbage";
  Program again(ctx, src);
  EXPECT_FALSE(again.loaded_from_cache());
  Program third(ctx, src);
  EXPECT_TRUE(third.loaded_from_cache());
}

TEST(ProgramCache, DisabledByEnvironment) {
  CacheDir cache("off");
  setenv("RADCL_PROGRAM_CACHE", "0", 1);
  Context& ctx = test_context();
  Program p(ctx, ProgramSource{{"probe/layout.cl"}, "", "-cl-std=CL1.2"});
  unsetenv("RADCL_PROGRAM_CACHE");
  EXPECT_EQ(cache.binaries(), 0u);
}

// RADCL_CL_OPTIONS reaches the compiler (a define it names is seen) and the cache key.
TEST(ProgramCache, UserOptionsAreBuiltAndKeyed) {
  CacheDir cache("user-options");
  Context& ctx = test_context();
  ProgramSource src{{"probe/features.cl"},
                    "#ifndef RADCL_USER_X\n#error RADCL_CL_OPTIONS was not applied\n#endif\n",
                    "-cl-std=CL1.2"};
  EXPECT_THROW(Program(ctx, src), radcl::FatalError);
  setenv("RADCL_CL_OPTIONS", "-DRADCL_USER_X=1", 1);
  std::string key, options;
  try {
    Program p(ctx, src);
    key = p.cache_key();
    options = p.options();
  } catch (const radcl::FatalError& e) {
    ADD_FAILURE() << e.what();
  }
  unsetenv("RADCL_CL_OPTIONS");
  EXPECT_EQ(options, "-cl-std=CL1.2 -DRADCL_USER_X=1");
  EXPECT_EQ(cache.binaries(), 1u);
  setenv("RADCL_CL_OPTIONS", "-DRADCL_USER_X=2", 1);
  Program other(ctx, src);
  unsetenv("RADCL_CL_OPTIONS");
  EXPECT_NE(other.cache_key(), key);
}

// RADCL_DUMP_PROGRAMS writes what is built: the options line, then the assembled source.
TEST(ProgramCache, DumpWritesSourceWithItsOptions) {
  CacheDir cache("dump");
  const fs::path dump = cache.dir / "dumped";
  setenv("RADCL_DUMP_PROGRAMS", dump.c_str(), 1);
  Program p(test_context(), ProgramSource{{"probe/features.cl"}, "", "-cl-std=CL1.2 -DX=1"});
  unsetenv("RADCL_DUMP_PROGRAMS");
  std::ifstream in(dump / (p.cache_key() + ".cl"));
  ASSERT_TRUE(in) << "no " << p.cache_key() << ".cl in " << dump;
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "// options: -cl-std=CL1.2 -DX=1");
  std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(rest, p.source());
}

TEST(ProgramBuild, FailureIsFatalWithTheCompilerLog) {
  Context& ctx = test_context();
  try {
    Program p(ctx, ProgramSource{{"probe/features.cl"}, "this is not OpenCL;\n", "-cl-std=CL1.2"});
    FAIL() << "build should fail";
  } catch (const radcl::FatalError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("OpenCL program build failed"), std::string::npos) << msg;
    EXPECT_NE(msg.find("generated.cl:1"), std::string::npos) << "log names file and line: " << msg;
  }
}

TEST(ProgramSource, LogPositionsMapToEmbeddedFiles) {
  std::string src = ProgramSource{{"probe/features.cl"}, "int a;\nint b;\n", ""}.assemble();
  // Find the assembled line number of "int b;" and phrase it as NVIDIA's compiler does.
  std::size_t n = 1;
  for (std::size_t i = 0; i < src.find("int b;"); ++i)
    n += src[i] == '\n';
  std::string log = "<kernel>:" + std::to_string(n) + ":1: error: x\n<kernel>:2:2: note\n";
  std::string out = locate_log_lines(log, src);
  EXPECT_NE(out.find("generated.cl:2:1: error: x"), std::string::npos) << out;
  EXPECT_NE(out.find("probe/features.cl:1:2: note"), std::string::npos) << out;
}

TEST(ProgramSource, IncludesExpandOnceWithLineMarkers) {
  std::string s = ProgramSource{{"probe/features.cl"}, "int generated_marker;", ""}.assemble();
  EXPECT_NE(s.find("#line 1 \"radcl/device_types.h\""), std::string::npos);
  EXPECT_NE(s.find("int generated_marker;"), std::string::npos);
  EXPECT_EQ(s.find("#include \""), std::string::npos);
  EXPECT_THROW(ProgramSource({{"no/such.cl"}, "", ""}).assemble(), radcl::FatalError);
}

// The generated OpenCL code computes what the host evaluator computes: a seeded corpus of random
// expressions (tests/calc/corpus.h) evaluated on the host in double and on the device with
// RC_CALC_FP64, compared to 1e-5 relative (absolute 1e-9 near zero). Expressions whose host
// value is not finite (overflow in plain arithmetic, which Radiance does not catch) are skipped
// and counted.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

#include "../device/device_fixture.h"
#include "corpus.h"
#include "radcl/calc/codegen.h"
#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "radcl/device/buffer.h"
#include "radcl/device/program.h"
#include "radcl/util/error.h"

using namespace radcl::calc;
namespace dev = radcl::device;

namespace {

constexpr int kArgs = 6;

struct DeviceRun {
  std::vector<double> values;
  std::vector<int> errors;
};

// Builds a program from generated functions plus a dispatcher over `names` and runs it.
DeviceRun run_device(CodeGenerator& gen, const std::vector<std::string>& names,
                     const std::vector<rc_calc_ray>& rays, const std::vector<float>& args) {
  std::string src = gen.source();
  src += "rc_calc_real rc_calc_probe_eval(rc_calc_env* e, uint i) {\n  switch (i) {\n";
  for (std::size_t i = 0; i < names.size(); ++i)
    src += "  case " + std::to_string(i) + ": return " + names[i] + "(e);\n";
  src += "  }\n  return 0;\n}\n";
  dev::Context& ctx = test_context();
  dev::Program prog(ctx, dev::ProgramSource{{"calc/probe.cl"}, src, "-DRC_CALC_FP64"});
  auto count = static_cast<std::uint32_t>(names.size());
  dev::Buffer ray_buf = dev::Buffer::from(ctx, rays), arg_buf = dev::Buffer::from(ctx, args);
  dev::Buffer out(ctx, count * sizeof(double)), err(ctx, count * sizeof(int));
  dev::Kernel k = prog.kernel("rc_calc_probe");
  k.arg(0, ray_buf).arg(1, arg_buf).arg(2, out).arg(3, err).arg(4, count);
  ctx.run(k, count);
  ctx.finish();
  return {out.to_vector<double>(count), err.to_vector<int>(count)};
}

rc_calc_ray random_ray(std::mt19937& rng, int index) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  rc_calc_ray r{};
  for (int s = 0; s < RC_CALC_NSLOTS; ++s)
    r.v[s] = u(rng);
  r.v[RC_CALC_T] = 1.0f + 4.0f * std::abs(r.v[RC_CALC_T]);
  r.v[RC_CALC_S] = 1.0f;
  r.nargs = kArgs;
  r.arg_base = index * kArgs;
  return r;
}

} // namespace

TEST(CalcDevice, RandomCorpusAgreesWithHost) {
  radcl::set_warning_sink([](const std::string&) {});
  Program prog;
  prog.load_rayinit();
  prog.load_string(corpus::kCorpusDefinitions, "corpus.cal");
  CodeGenerator gen(prog);
  Evaluator ev(prog);
  ev.set_warnings(false);

  // 800 expressions by default (8 programs: PoCL compiles each in about 50 s on the 2-core CI
  // machine; 1,600 made this the suite's longest test, 790 s, a fifth of its time);
  // RADCL_CALC_CORPUS=2400 or more for a wider sweep.
  const int kCount =
      std::getenv("RADCL_CALC_CORPUS") ? std::atoi(std::getenv("RADCL_CALC_CORPUS")) : 800;
  corpus::Generator g(20240611u);
  std::mt19937 rng(7u);
  std::uniform_real_distribution<float> ua(-3.0f, 3.0f);
  std::vector<std::string> texts, names;
  std::vector<rc_calc_ray> rays;
  std::vector<float> args;
  std::vector<double> host;
  int rejected = 0;
  for (int i = 0; i < kCount; ++i) {
    // Constant parts that fold to an error ("bad constant expression", as Radiance) are
    // rejected at parse time: draw another.
    Expression e;
    for (;;) {
      std::string text = g.expression();
      try {
        e = prog.parse_expression(text, "", "corpus");
      } catch (const radcl::FatalError&) {
        ++rejected;
        continue;
      }
      texts.push_back(text);
      break;
    }
    names.push_back(gen.request_expression(e));
    rays.push_back(random_ray(rng, i));
    std::vector<double> a;
    for (int j = 0; j < kArgs; ++j) {
      args.push_back(ua(rng));
      a.push_back(args.back());
    }
    ev.set_ray(rays.back());
    ev.set_args(a);
    host.push_back(ev.eval(e));
  }
  // Dead definitions are not emitted.
  std::string src = gen.source();
  EXPECT_EQ(src.find("dead"), std::string::npos);

  // One program per batch: PoCL's compile time grows faster than linearly with program size.
  DeviceRun dev;
  constexpr int kBatch = 100;
  for (int b = 0; b < kCount; b += kBatch) {
    int n = std::min(kBatch, kCount - b);
    CodeGenerator bgen(prog);
    std::vector<std::string> bnames;
    for (int i = b; i < b + n; ++i)
      bnames.push_back(bgen.request_expression(prog.parse_expression(texts[i], "", "corpus")));
    std::vector<rc_calc_ray> brays(rays.begin() + b, rays.begin() + b + n);
    for (auto& r : brays)
      r.arg_base -= b * kArgs;
    std::vector<float> bargs(args.begin() + b * kArgs, args.begin() + (b + n) * kArgs);
    DeviceRun r = run_device(bgen, bnames, brays, bargs);
    dev.values.insert(dev.values.end(), r.values.begin(), r.values.end());
    dev.errors.insert(dev.errors.end(), r.errors.begin(), r.errors.end());
  }
  int skipped = 0, compared = 0, bad = 0, constant = 0;
  for (int i = 0; i < kCount; ++i) {
    double h = host[i], d = dev.values[i];
    if (!std::isfinite(h)) {
      ++skipped;
      continue;
    }
    ++compared;
    if (prog.parse_expression(texts[i]).root.is_num()) ++constant;
    double tol = std::max(1e-5 * std::abs(h), 1e-9);
    if (!(std::abs(d - h) <= tol)) {
      if (++bad <= 10)
        ADD_FAILURE() << "expression " << i << ": " << texts[i] << "\n host " << h << " device "
                      << d << " (errors " << dev.errors[i] << ")";
    }
  }
  std::printf("calc corpus: %d expressions (%d more rejected at parse), %d compared (%d folded "
              "to constants), %d skipped (non-finite on the host), %d disagree\n",
              kCount, rejected, compared, constant, skipped, bad);
  EXPECT_EQ(bad, 0);
  // Most expressions are finite on the host (2,000 of the first 2,400 were).
  if (kCount >= 800) {
    EXPECT_GE(compared, kCount * 5 / 6);
  }
  radcl::set_warning_sink(nullptr);
}

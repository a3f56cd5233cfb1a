// rcontrib: traces rays read from standard input and writes, per record of -c rays, what each
// tracked modifier's bins received (Radiance's rcontrib, ../shared/docs/radiance/): the
// coefficients (-V-) or contributions (-V+) of every ray path that ends on a surface or light
// source of a listed modifier, the bin chosen by the modifier's .cal expression on the device.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <memory>
#include <string>
#include <tbb/global_control.h>
#include <vector>

#include "fd_input.h"
#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "radcl/contrib/output.h"
#include "radcl/device/context.h"
#include "radcl/options/ray_io.h"
#include "radcl/options/rcontrib_options.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/raypath.h"
#include "radcl/util/error.h"
#include "render_settings.h"

namespace {

using namespace radcl;

void quiet_warning(const std::string&) {}

// The .cal state while the command line is read: Radiance evaluates -bn there.
struct HostCal {
  calc::Program prog;
  HostCal() { prog.load_rayinit(); }
  options::CalHooks hooks() {
    options::CalHooks h;
    h.load_file = [this](const std::string& f) {
      std::string path = scene::find_on_raypath(f);
      if (path.empty()) throw FatalError("cannot find function file \"" + f + "\"");
      prog.load_file(path);
    };
    h.load_expr = [this](const std::string& e) { prog.load_string(e, "-e"); };
    h.set_params = [this](const std::string& p) { set_params(p); };
    h.eval = [this](const std::string& e) {
      calc::Evaluator ev(prog);
      return ev.eval(prog.parse_expression(e));
    };
    return h;
  }
  // The same pairs the device's contexts get (contrib_tables.cpp).
  void set_params(const std::string& text) {
    for (const auto& [name, v] : render::parse_contrib_params(text))
      prog.set_parameter(name, "", v);
  }
};

std::shared_ptr<render::ContribSpec> contrib_spec(const options::RcontribOptions& o) {
  auto spec = std::make_shared<render::ContribSpec>();
  for (const options::CalSource& c : o.cal)
    spec->cal.push_back({c.is_file, c.text});
  for (const options::RcontribModifier& m : o.modifiers)
    spec->modifiers.push_back({m.name, m.params, m.bin_expr, m.nbins});
  spec->contributions = o.contributions;
  return spec;
}

// The ray loop: records of -c rays (all of them with -c 0), -x/-y counts, flush requests.
class Contributor {
public:
  Contributor(const options::RcontribCommand& cmd, const scene::LoadedScene& ls,
              contrib::Outputs& out)
      : opt_(cmd.opt), out_(out) {
    render::RenderSettings st = cli::render_settings(opt_.render);
    st.irradiance_I = opt_.immediate_irradiance;
    spec_ = contrib_spec(opt_);
    st.contrib = spec_;
    renderer_ = std::make_unique<render::Renderer>(ls, st, device::default_context());
    width_ = 3 * spec_->total_bins();
    acc_.assign(width_, 0.0);
    // A batch's results hold every bin of every ray: 256 MB at most.
    chunk_ = std::max<std::size_t>(1, std::min<std::size_t>(1 << 16, (1u << 25) / (width_ + 1)));
    if (opt_.yres > 0) {
      raysleft_ = static_cast<long long>(opt_.yres) * (opt_.xres > 0 ? opt_.xres : 1);
      if (opt_.accumulate > 1) raysleft_ *= opt_.accumulate;
    }
  }

  // Reads, traces and writes until the input ends or -x/-y are done (or -r finds nothing to
  // do).
  void run(std::istream& in, cli::FdInputBuf& buf) {
    if (opt_.recover) {
      std::vector<double> reloaded;
      long done = out_.recover(reloaded);
      if (out_.output_complete()) return; // Radiance: "output appears to be complete"
      if (!reloaded.empty()) acc_ = reloaded;
      long long skip = static_cast<long long>(done) * std::max(1, opt_.accumulate);
      options::RayReader skipper(in, opt_.in_format);
      options::Vec3 o, d;
      for (long long k = 0; k < skip; ++k)
        if (!skipper.read(o, d)) throw FatalError("unexpected EOF on input");
      next_id_ = static_cast<std::uint32_t>(skip);
      if (raysleft_ > 0) raysleft_ -= skip;
    }
    options::RayReader reader(in, opt_.in_format);
    std::size_t record = opt_.in_format == 'f' ? 24 : opt_.in_format == 'd' ? 48 : 0;
    bool more = true;
    while (more) {
      options::Vec3 o, d;
      more =
          (raysleft_ < 0 || static_cast<long long>(batch_.size()) < raysleft_) && reader.read(o, d);
      if (more) batch_.push_back({o, d});
      if (!more || batch_.size() >= chunk_ || !buf.ready(record)) {
        process();
        if (raysleft_ == 0) break;
      }
    }
    process();
    finish();
  }

private:
  struct Input {
    options::Vec3 org, dir;
  };
  const options::RcontribOptions& opt_;
  contrib::Outputs& out_;
  std::shared_ptr<render::ContribSpec> spec_;
  std::unique_ptr<render::Renderer> renderer_;
  std::size_t width_ = 0, chunk_ = 1;
  std::vector<double> acc_; // the record being accumulated
  int account_ = 0;         // rays in it so far
  long long raysleft_ = -1; // -y: rays still expected (-1: until the input ends)
  long long total_ = 0;     // -t: the rays expected in all, once the first report is due
  std::time_t start_ = 0, last_report_ = 0;
  std::uint32_t next_id_ = 0;
  std::vector<Input> batch_;
  bool warned_dummy_ = false;

  void process() {
    if (batch_.empty()) return;
    std::vector<render::PrimaryRay> rays;
    std::vector<double> len(batch_.size());
    std::vector<std::uint32_t> id(batch_.size());
    for (std::size_t i = 0; i < batch_.size(); ++i) {
      Input& b = batch_[i];
      id[i] = next_id_++;
      bool finite = true;
      for (int c = 0; c < 3; ++c)
        finite = finite && std::isfinite(b.org[c]) && std::isfinite(b.dir[c]);
      len[i] = finite ? options::normalize_direction(b.dir) : 0.0;
      if (!std::isfinite(len[i])) len[i] = 0;
      if (len[i] > 0) rays.push_back({b.org, b.dir, opt_.limit_distance ? len[i] : 0.0, id[i]});
    }
    std::vector<render::PrimaryResult> res(rays.size());
    if (!rays.empty()) renderer_->render(rays, res);
    std::size_t k = 0;
    for (std::size_t i = 0; i < batch_.size(); ++i) {
      if (len[i] == 0) { // a flush request (or, while accumulating everything, ignored)
        if (opt_.accumulate <= 0) {
          if (!warned_dummy_) warning("dummy ray(s) ignored during accumulation");
          warned_dummy_ = true;
          continue;
        }
        out_.request_flush();
      } else {
        const std::vector<double>& c = res[k++].contrib;
        for (std::size_t j = 0; j < width_; ++j)
          acc_[j] += c[j];
      }
      if (raysleft_ > 0) {
        --raysleft_;
        report();
      }
      if (opt_.accumulate > 0 && ++account_ >= opt_.accumulate) emit();
    }
    batch_.clear();
  }

  // -t: progress every so many seconds where -y tells how many rays are coming (Radiance's
  // morays()).
  void report() {
    if (opt_.report_interval <= 0) return;
    const std::time_t now = std::time(nullptr);
    if (now < last_report_ + opt_.report_interval) return;
    if (total_ == 0) {
      total_ = raysleft_ + 1;
      start_ = now;
    } else {
      std::fprintf(stderr, "%s: %.2f%% done after %.3f hours\n", program_name().c_str(),
                   100.0 - 100.0 * static_cast<double>(raysleft_) / static_cast<double>(total_),
                   static_cast<double>(now - start_) / 3600.0);
    }
    last_report_ = now;
  }

  // rays > 0: a partial last record, which Radiance divides by its own ray count.
  void emit(int rays = 0) {
    out_.write_record(acc_, rays);
    out_.end_record();
    std::fill(acc_.begin(), acc_.end(), 0.0);
    account_ = 0;
  }

  void finish() {
    if (opt_.accumulate <= 0) {
      emit();
    } else if (account_ > 0) {
      warning("partial accumulation in final record");
      emit(account_);
    }
    out_.finish();
    if (raysleft_ > 0) throw FatalError("unexpected EOF on input");
    const std::uint64_t bad = renderer_->stats().bad_bins;
    if (bad > 0)
      warning("bad bin number: " + std::to_string(bad) +
              " contributions to bins beyond their modifier's count ignored");
  }
};

int rcontrib_main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  HostCal cal;
  options::RcontribCommand cmd;
  try {
    cmd = options::parse_rcontrib_command_line(args, cal.hooks(), scene::find_on_raypath);
  } catch (const options::RcontribUsageError&) {
    std::fputs(options::rcontrib_usage(program_name()).c_str(), stderr);
    throw;
  }
  if (!cmd.args.empty()) cmd.args[0] = program_name();
  if (cmd.action == options::RcontribCommand::Action::PrintDefaults) {
    std::fputs(options::format_rcontrib_defaults(cmd.opt).c_str(), stdout);
    return 0;
  }
  if (cmd.action == options::RcontribCommand::Action::PrintVersion) {
    std::printf("RADIANCE 5.4a radcl %s (rcontrib)\n", RADCL_VERSION);
    return 0;
  }
  if (!cmd.opt.warnings) set_warning_sink(quiet_warning);
  if (cmd.operand >= cmd.args.size()) throw FatalError("missing octree argument");
  if (!cmd.opt.render.photon_maps.empty()) throw FatalError("photon maps (-ap) are not supported");
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(std::max(1, cmd.opt.nproc)));
  auto device_start = device::start_default_context();
  std::vector<std::string> inputs(cmd.args.begin() + static_cast<long>(cmd.operand),
                                  cmd.args.end());
  scene::LoadedScene ls = scene::load_scene(inputs);

  contrib::OutputSettings os;
  os.format = cmd.opt.out_format;
  os.header = cmd.opt.header;
  os.force_open = cmd.opt.force_open;
  os.recover = cmd.opt.recover;
  os.xres = cmd.opt.xres;
  os.yres = cmd.opt.yres;
  os.accumulate = cmd.opt.accumulate;
  os.octree_header = ls.main.header;
  os.command.assign(cmd.args.begin(), cmd.args.begin() + static_cast<long>(cmd.operand));
  os.software = std::string("radcl ") + RADCL_VERSION;
  os.time = std::time(nullptr);
  contrib::Outputs out(os);
  for (const options::RcontribModifier& m : cmd.opt.modifiers)
    out.add_modifier(m.outspec, m.name, m.nbins);

  Contributor c(cmd, ls, out);
  cli::FdInputBuf buf(0);
  std::istream in(&buf);
  c.run(in, buf);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  return radcl::run_main("rcontrib", rcontrib_main, argc, argv);
}

// rtrace: traces rays read from standard input through a scene and writes what -o asks for,
// with Radiance's options, formats, header and flushing rules
// (../shared/docs/radiance/cli-rtrace-rpict.md §3).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <future>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <sys/stat.h>
#include <tbb/global_control.h>
#include <unistd.h>
#include <vector>

#include "fd_input.h"
#include "persist.h"
#include "radcl/device/context.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/luminance.h"
#include "radcl/options/ray_io.h"
#include "radcl/options/rtrace_options.h"
#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/compile/material_traits.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/raypath.h"
#include "radcl/util/allocator.h"
#include "radcl/util/error.h"
#include "render_settings.h"

namespace {

using namespace radcl;

bool g_warnings = true;
void quiet_warning(const std::string&) {}

render::RenderSettings settings_from(const options::RtraceOptions& o) {
  render::RenderSettings s = cli::render_settings(o.render);
  s.irradiance_I = o.immediate_irradiance;
  options::OutputSpec spec = options::parse_output_spec(o.output_spec);
  if (spec.trace_mode())
    s.trace = spec.trace_sources ? render::RenderSettings::Trace::RaysAndShadows
                                 : render::RenderSettings::Trace::Rays;
  s.std_error = spec.per_ray.find('e') != std::string::npos;
  return s;
}

// First intersections only, for output that needs no shading.
struct Caster {
  geometry::SceneGeometry geom;
  render::CompiledScene cs;
  explicit Caster(const scene::LoadedScene& ls)
      : geom(ls), cs(render::compile_scene(ls, geom, false)) {}

  void cast(std::span<const render::PrimaryRay> rays, std::span<render::PrimaryResult> res) {
    std::vector<geometry::Ray> gr(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i)
      gr[i] = {rays[i].org, rays[i].dir, 0, rays[i].tmax > 0 ? rays[i].tmax : 1e300};
    std::vector<std::optional<geometry::Hit>> hits(rays.size());
    geom.intersect(gr, hits);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      render::PrimaryResult& r = res[i];
      r = render::PrimaryResult{};
      r.point = rays[i].org;
      if (hits[i]) {
        r.hit = true;
        r.t = hits[i]->t;
        r.point = hits[i]->point;
        r.normal = hits[i]->normal;
        r.surface = cs.surface_of(*hits[i]);
      } else {
        r.surface = render::distant_surface(cs, geom, rays[i].dir);
      }
    }
  }
};

// Radiance's raynormal() for -on: `n` (the normal facing the ray, `sign` times the hit's)
// tilted by the hit's perturbation `pert` (in the hit's frame, so turned with it), made unit,
// and turned back to the ray's side (direction `d`) if the tilt would change it. Untouched
// without a perturbation, or where the tilt cancels the normal.
void perturb(options::Vec3& n, double sign, const options::Vec3& pert, const options::Vec3& d) {
  if (pert[0] == 0 && pert[1] == 0 && pert[2] == 0) return;
  double t[3], len2 = 0;
  for (int i = 0; i < 3; ++i) {
    t[i] = n[i] + sign * pert[i];
    len2 += t[i] * t[i];
  }
  if (!(len2 > 0)) return;
  const double len = std::sqrt(len2);
  double rod = 0, nd = 0;
  for (int i = 0; i < 3; ++i) {
    t[i] /= len;
    rod -= n[i] * d[i];
    nd -= t[i] * d[i];
  }
  if ((nd > 0) != (rod > 0))
    for (int i = 0; i < 3; ++i)
      t[i] += 2 * nd * d[i];
  for (int i = 0; i < 3; ++i)
    n[i] = t[i];
}

struct PendingRay {
  options::Vec3 org, dir; // dir normalised; zero for a flush request
  double length = 0;      // input direction length (-ld)
  bool bad = false;       // a NaN or Inf in the ray (or a direction too long to normalise)
};

bool finite(const options::Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

class Tracer {
public:
  Tracer(const options::RtraceCommand& cmd, const scene::LoadedScene& ls, device::Context* ctx)
      : opt_(cmd.opt), spec_(options::parse_output_spec(opt_.output_spec)),
        flow_(opt_.xres, opt_.yres) {
    // Geometric output only: no shading, no device program (Radiance's "ray cast only").
    if (spec_.cast_only)
      caster_ = std::make_unique<Caster>(ls);
    else {
      render::RenderSettings st = settings_from(opt_);
      amb_ = cli::setup_ambient(st, opt_.render, ls, cmd.args.empty() ? "rtrace" : cmd.args[0],
                                cmd.operand < cmd.args.size() ? cmd.args[cmd.operand] : "");
      renderer_ = std::make_unique<render::Renderer>(ls, st, *ctx);
    }
  }

  // Reads, traces and writes until the input ends or the -x/-y count is reached.
  void run(std::istream& in, cli::FdInputBuf& buf) {
    flow_ = options::RayFlow(opt_.xres, opt_.yres); // each persistent job starts afresh
    options::RayReader reader(in, opt_.in_format);
    std::vector<PendingRay> batch;
    building_ = renderer_ && renderer_->builds_cache();
    since_flush_ = 0;
    bool done = false;
    while (!done) {
      PendingRay p;
      bool got = reader.read(p.org, p.dir);
      if (got) {
        // Radiance traces such rays to undefined results (a NaN direction ends its input):
        // they get an all-zero record instead, so nothing non-finite reaches the output.
        p.bad = !finite(p.org) || !finite(p.dir);
        if (!p.bad) {
          p.length = options::normalize_direction(p.dir);
          p.bad = !std::isfinite(p.length);
        }
        batch.push_back(p);
      }
      // Answer what we have when input pauses, a wave is full, or input ends: results reach a
      // co-process before it sends more. While the cache is being built, a batch's records come
      // from its own misses, so batches end only where the input itself says: at Radiance's
      // flush points (a zero-direction ray, every -x rays when -y is 0 or -x is 1), a full wave
      // or the end. The output then does not depend on input timing; a co-process flushes as
      // it must with Radiance's rtrace, which answers at those points alone.
      std::size_t record = opt_.in_format == 'f' ? 24 : opt_.in_format == 'd' ? 48 : 0;
      if (got) ++since_flush_;
      bool answer = !got || batch.size() >= kWave;
      if (!answer && building_) {
        const long every = flow_.flush_interval();
        answer = (!batch.back().bad && batch.back().length == 0) ||
                 (every > 0 && since_flush_ % static_cast<unsigned long>(every) == 0);
      } else if (!answer) {
        answer = !buf.ready(record);
      }
      if (answer) done = process(batch) || !got;
      if (!got) break;
    }
    if (!done) process(batch);
    std::fflush(stdout);
    if (flow_.incomplete()) warning("unexpected EOF on input");
    report();
  }

  // RADCL_STATS=1: what was traced, for benchmarks (Radiance has no such report in rtrace).
  void report() const {
    const char* want = std::getenv("RADCL_STATS");
    if (!want || std::string(want) != "1") return;
    if (!renderer_) return;
    const render::RenderStats& s = renderer_->stats();
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr,
                 "rtrace: %llu primary, %llu secondary, %llu shadow rays (%llu stepped on the "
                 "device) in %.3f s (%.0f rays/s)\n",
                 static_cast<unsigned long long>(s.primary),
                 static_cast<unsigned long long>(s.secondary),
                 static_cast<unsigned long long>(s.shadow),
                 static_cast<unsigned long long>(s.shadow_steps), secs, s.total() / secs);
  }

private:
  static constexpr std::size_t kWave = 1 << 16;
  const options::RtraceOptions& opt_;
  options::OutputSpec spec_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<ambient::AmbientFile> amb_; // -af with the cache in use
  std::unique_ptr<Caster> caster_;
  options::RayFlow flow_;
  std::string out_;
  bool warned_bad_ = false;
  bool building_ = false;         // batches end at the input's flush points (see run)
  unsigned long since_flush_ = 0; // records read in this run, for -x flush points
  std::uint32_t next_id_ = 0;     // rays read so far (keys the random numbers)
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();

  // Traces and writes a batch; true when the -x/-y count has been reached.
  bool process(std::vector<PendingRay>& batch) {
    std::vector<render::PrimaryRay> rays;
    // Each ray's random numbers are keyed by its place in the whole input, not in its batch,
    // so results do not depend on where the input paused.
    for (const PendingRay& p : batch) {
      const std::uint32_t id = next_id_++;
      if (!p.bad && p.length > 0)
        rays.push_back({p.org, p.dir, opt_.limit_distance ? p.length : 0.0, id});
    }
    std::vector<render::PrimaryResult> res(rays.size());
    if (!rays.empty()) {
      if (renderer_) {
        renderer_->render(rays, res);
        cli::sync_ambient(amb_.get(), *renderer_);
      } else
        caster_->cast(rays, res);
    }
    std::size_t k = 0;
    bool stop = false;
    for (const PendingRay& p : batch) {
      bool flush;
      if (!p.bad && p.length > 0) {
        write(p, res[k++]);
        flush = flow_.ray_done();
      } else {
        out_.clear();
        options::RayOutput o = p.bad ? options::RayOutput::empty({0, 0, 0}, {0, 0, 0})
                                     : options::RayOutput::empty(p.org, p.dir);
        options::append_record(out_, spec_.per_ray, o, opt_.out_format);
        std::fwrite(out_.data(), 1, out_.size(), stdout);
        flush = p.bad ? flow_.ray_done() : flow_.flush_request();
        if (p.bad && !warned_bad_) {
          warning("ray with NaN or infinite numbers, zero output");
          warned_bad_ = true;
        }
      }
      if (flush) std::fflush(stdout);
      if (flow_.record_done()) {
        stop = true;
        break;
      }
    }
    batch.clear();
    std::fflush(stdout);
    return stop;
  }

  void write(const PendingRay& p, const render::PrimaryResult& r) {
    const render::CompiledScene& cs = renderer_ ? renderer_->compiled() : caster_->cs;
    options::RayOutput o;
    o.origin = p.org;
    o.direction = p.dir;
    if (opt_.immediate_irradiance) {
      // What Radiance traces for -I: from just in front of the point, back at it.
      for (int i = 0; i < 3; ++i) {
        o.origin[i] = p.org[i] + 1.1e-4 * p.dir[i];
        o.direction[i] = -p.dir[i];
      }
    }
    o.value = r.value;
    o.std_error = r.std_error;
    o.point = o.origin;
    if (r.hit) {
      o.first_length = o.effective_length = o.unmirrored_length = r.t;
      o.point = r.point;
      o.unperturbed_normal = r.normal;
      double dn = r.normal[0] * p.dir[0] + r.normal[1] * p.dir[1] + r.normal[2] * p.dir[2];
      for (int i = 0; i < 3; ++i)
        o.normal[i] = dn > 0 ? -r.normal[i] : r.normal[i];
      perturb(o.normal, dn > 0 ? -1.0 : 1.0, r.pert, p.dir);
      if (r.surface < cs.surfaces.size()) {
        o.surface = cs.surface_names[r.surface];
        o.modifier = cs.modifier_names[r.surface];
        o.material = cs.material_names[r.surface];
      }
    } else if (r.surface < cs.surfaces.size()) { // a distant source faces the ray
      for (int i = 0; i < 3; ++i)
        o.normal[i] = o.unperturbed_normal[i] = -o.direction[i];
      o.surface = cs.surface_names[r.surface];
      o.modifier = cs.modifier_names[r.surface];
      o.material = cs.material_names[r.surface];
    }
    // Primary rays carry coefficient 1: their contribution is their value. The mirrored part
    // and its length come from the first hit's pure specular reflection, as Radiance's.
    o.contribution = r.value;
    o.mirrored = r.mirrored;
    rc_object_type type = r.surface < cs.surfaces.size()
                              ? static_cast<rc_object_type>(cs.surfaces[r.surface].type)
                              : RC_OBJ_SPHERE;
    bool flat = type == RC_OBJ_POLYGON || type == RC_OBJ_RING;
    // Seen through glass (or a flat dielectric), the unmirrored image lies behind it: the
    // transmitted rays' lengths add, as Radiance's m_glass/m_dielectric set rxt.
    if (r.hit && r.through_t >= 0 && r.surface < cs.surfaces.size()) {
      if (render::seen_through(cs, cs.surfaces[r.surface].material, flat))
        o.unmirrored_length = o.effective_length = r.t + r.through_t;
    }
    if (r.hit && r.mirror_t >= 0) {
      // A flat mirror's image lies behind it (the reflected ray's length adds); a curved one's
      // is taken at the surface, as Radiance's m_normal/m_glass do.
      o.mirrored_length = r.t + (flat ? r.mirror_t : 0.0);
      if (bright(o.mirrored) > 0.5 * bright(o.value)) o.effective_length = o.mirrored_length;
    }
    o.derive_unmirrored();
    out_.clear();
    write_traced(r);
    // Radiance writes nothing (not even a newline) when no letter precedes t/T.
    if (!spec_.per_ray.empty()) options::append_record(out_, spec_.per_ray, o, opt_.out_format);
    std::fwrite(out_.data(), 1, out_.size(), stdout);
  }

  // Trace mode: every ray of the primary's tree, children before their parent, each indented
  // by its number of ancestors; -te/-ti filter by the modifier of the surface hit.
  void write_traced(const render::PrimaryResult& r) {
    if (!spec_.trace_mode()) return;
    const render::CompiledScene& cs = renderer_->compiled();
    const options::ModifierList& list = opt_.trace_list;
    for (const render::TracedRay& t : r.traced) {
      bool named = t.surface < cs.surfaces.size();
      if (list.kind != options::ModifierList::Kind::None) {
        if (!named) {
          if (list.kind == options::ModifierList::Kind::Include) continue;
        } else {
          const std::string& mod = cs.modifier_names[t.surface];
          bool listed = std::find(list.names.begin(), list.names.end(), mod) != list.names.end();
          if (listed != (list.kind == options::ModifierList::Kind::Include)) continue;
        }
      }
      options::RayOutput o;
      o.origin = t.org;
      o.direction = t.dir;
      o.value = t.value;
      o.contribution = t.contribution;
      o.coefficient = t.coef;
      o.weight = t.weight;
      o.point = t.org;
      if (t.hit) {
        o.first_length = o.effective_length = o.unmirrored_length = t.t;
        o.point = t.point;
        o.unperturbed_normal = t.normal;
        double dn = t.normal[0] * t.dir[0] + t.normal[1] * t.dir[1] + t.normal[2] * t.dir[2];
        for (int i = 0; i < 3; ++i)
          o.normal[i] = dn > 0 ? -t.normal[i] : t.normal[i];
      } else if (named) { // a distant source faces the ray
        for (int i = 0; i < 3; ++i)
          o.normal[i] = o.unperturbed_normal[i] = -t.dir[i];
      }
      if (named) {
        o.surface = cs.surface_names[t.surface];
        o.modifier = cs.modifier_names[t.surface];
        o.material = cs.material_names[t.surface];
      }
      o.derive_unmirrored();
      options::append_record(out_, spec_.per_traced, o, opt_.out_format, t.depth);
    }
  }
};

int rtrace_main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  const bool server = cli::is_persist_server();
  cli::PersistMode pmode = cli::PersistMode::Single;
  const std::string pfile = cli::find_persist_file(args, &pmode);
  // A control file that exists already: attach to its server, as Radiance does on reading the
  // option (later invocations need no other arguments).
  struct stat pst;
  if (!server && !pfile.empty() && ::stat(pfile.c_str(), &pst) == 0)
    return cli::attach_persist(pfile, args[0]);
  options::RtraceCommand cmd = options::parse_rtrace_command_line(args, scene::find_on_raypath);
  // Headers and messages name the command as Radiance does (fixargv0), expanded words after.
  if (!cmd.args.empty()) cmd.args[0] = program_name();
  if (cmd.action == options::ParsedCommand::Action::PrintDefaults) {
    std::fputs(options::format_rtrace_defaults(cmd.opt).c_str(), stdout);
    return 0;
  }
  if (cmd.action == options::ParsedCommand::Action::PrintVersion) {
    // Radiance's form, "RADIANCE <release> ...": tools read the release from the second word.
    std::printf("RADIANCE 5.4a radcl %s (rtrace)\n", RADCL_VERSION);
    return 0;
  }
  if (!cmd.opt.error_file.empty() && !std::freopen(cmd.opt.error_file.c_str(), "a", stderr))
    throw FatalError("cannot open error file \"" + cmd.opt.error_file + "\"");
  g_warnings = cmd.opt.warnings;
  if (!g_warnings) set_warning_sink(quiet_warning);
  if (cmd.operand >= cmd.args.size()) throw FatalError("missing octree argument");
  std::vector<std::string> inputs(cmd.args.begin() + static_cast<long>(cmd.operand),
                                  cmd.args.end());

  options::OutputSpec spec = options::parse_output_spec(cmd.opt.output_spec);
  options::check_output_format(cmd.opt.output_spec, cmd.opt.out_format);
  options::check_output_spec(cmd.opt.output_spec, spec, cmd.opt.render,
                             cmd.opt.immediate_irradiance);

  // Refuse what would silently give other answers than Radiance's.
  if (spec.trace_mode()) cmd.opt.nproc = 1; // as Radiance: trace mode runs one process
  if (!cmd.opt.render.photon_maps.empty()) throw FatalError("photon maps (-ap) are not supported");
  const bool persist = cmd.opt.persist != options::RtraceOptions::Persist::None;
  if (persist && !server && !cli::create_persist_file(cmd.opt.persist_file))
    return cli::attach_persist(cmd.opt.persist_file, args[0]); // another one was quicker
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(std::max(1, cmd.opt.nproc)));
  std::future<void> device_start; // the device starts while the scene loads
  if (!spec.cast_only && !persist) device_start = device::start_default_context();
  scene::LoadedScene ls = scene::load_scene(inputs);
  std::unique_ptr<Tracer> tracer;
  cli::PersistJobs jobs;
  jobs.prepare = [&] {
    // Ray casting needs no OpenCL device at all.
    device::Context* ctx = spec.cast_only ? nullptr : &device::default_context();
    tracer = std::make_unique<Tracer>(cmd, ls, ctx);
  };
  // One run over standard input: what each persistent job repeats.
  jobs.serve = [&] {
    if (cmd.opt.header) {
      options::RtraceHeader h;
      h.octree_lines = ls.main.header;
      h.command.assign(cmd.args.begin(), cmd.args.begin() + static_cast<long>(cmd.operand));
      h.software = std::string("radcl ") + RADCL_VERSION;
      h.time = std::time(nullptr);
      h.ncomp = spec.ncomp;
      h.out_format = cmd.opt.out_format;
      std::fputs(options::format_rtrace_header(h).c_str(), stdout);
      if (cmd.opt.xres > 0 && cmd.opt.yres > 0)
        std::fputs(options::format_resolution(cmd.opt.xres, cmd.opt.yres).c_str(), stdout);
    }
    std::fflush(stdout);
    cli::FdInputBuf buf(0);
    std::istream in(&buf);
    tracer->run(in, buf);
  };
  jobs.keep_stderr = !cmd.opt.error_file.empty();
  if (server)
    return cli::run_persist_server(cmd.opt.persist_file, args[0],
                                   cmd.opt.persist == options::RtraceOptions::Persist::Parallel
                                       ? cli::PersistMode::Parallel
                                       : cli::PersistMode::Single,
                                   jobs);
  jobs.prepare();
  jobs.serve();
  if (persist) cli::start_persist_server(args); // leaves the scene loaded for later runs
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  radcl::use_huge_pages(argv);
  radcl::keep_freed_memory();
  return radcl::run_main("rtrace", rtrace_main, argc, argv);
}

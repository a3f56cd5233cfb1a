// rpict: renders a view of a scene to a picture with Radiance's options, header and sampling
// (../shared/docs/radiance/cli-rtrace-rpict.md §4, ../shared/docs/radiance/picture-format.md §6),
// written as it grows; other formats by extension (.exr, .tif, .png). -S renders a sequence of
// views read from standard input, -P/-PP leave a persistent server behind (persist.h).
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <tbb/global_control.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "fd_input.h"
#include "frame_name.h"
#include "persist.h"
#include "progress.h"
#include "radcl/device/context.h"
#include "radcl/image/depth.h"
#include "radcl/image/image_io.h"
#include "radcl/image/picture.h"
#include "radcl/image/view_ray.h"
#include "radcl/options/rpict_options.h"
#include "radcl/render/picture/picture_loop.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/raypath.h"
#include "radcl/util/allocator.h"
#include "radcl/util/error.h"
#include "render_settings.h"

namespace {

using namespace radcl;

void quiet_warning(const std::string&) {}

std::string read_stdin() {
  std::string data;
  char buf[65536];
  ssize_t n;
  while ((n = ::read(0, buf, sizeof buf)) > 0)
    data.append(buf, static_cast<std::size_t>(n));
  return data;
}

render::RenderSettings settings_from(const options::RenderOptions& r) {
  render::RenderSettings s = cli::render_settings(r);
  s.low_discrepancy = !r.uncorrelated; // rpict's -u-: pixels stratify each other
  return s;
}

// Where the picture goes: a Radiance picture streamed scanline by scanline (stdout or an .hdr
// file opened by the caller), or another format written once the image is complete.
class Output {
public:
  Output(std::ostream* stream, const std::string& path, const image::PictureHeader& header, int w,
         int h, const image::Salvage* recovered)
      : path_(path), w_(w), h_(h), os_(stream) {
    streaming_ = stream != nullptr;
    if (streaming_) {
      writer_ =
          std::make_unique<image::PictureWriter>(*os_, header, image::Resolution::standard(w, h));
      if (recovered)
        for (int y = 0; y < recovered->complete; ++y)
          writer_->write_scanline(std::span<const image::Rgbe>(
              recovered->pixels.data() + static_cast<std::size_t>(y) * w, w));
      writer_->flush();
    } else {
      image_.width = w;
      image_.height = h;
      image_.rgb.resize(static_cast<std::size_t>(w) * h);
      opts_.header = header;
    }
  }

  void rows(const render::PictureRows& r, image::DepthWriter* z) {
    for (int y = 0; y < r.count; ++y) {
      std::span<const std::array<float, 3>> row(r.pixels.data() + static_cast<std::size_t>(y) * w_,
                                                w_);
      if (streaming_) {
        std::vector<image::Color> c(row.begin(), row.end());
        writer_->write_scanline(std::span<const image::Color>(c));
      } else {
        std::copy(row.begin(), row.end(),
                  image_.rgb.begin() + static_cast<std::size_t>(r.first + y) * w_);
      }
      if (z) z->write_scanline(std::span<const float>(r.depth.data() + std::size_t(y) * w_, w_));
    }
    if (streaming_) writer_->flush();
  }

  void finish(const std::vector<float>* depth) {
    if (streaming_) {
      writer_->flush();
      if (!os_->good()) throw FatalError("write error in render");
      return;
    }
    if (depth) image_.depth = *depth;
    image::write_image(path_, image_, opts_);
  }

private:
  std::string path_;
  int w_, h_;
  std::ostream* os_;
  bool streaming_ = true;
  std::unique_ptr<image::PictureWriter> writer_;
  image::FloatImage image_;
  image::ImageWriteOptions opts_;
};

bool is_integer(const std::string& s) {
  std::size_t i = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
  if (i >= s.size()) return false;
  for (; i < s.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

// The loaded scene and renderer, and how one run of rpict (one job in persistent mode) turns
// its views into pictures (Radiance's rpict(): frames, recovery, never overwriting).
class Pictures {
public:
  Pictures(const options::RpictCommand& cmd, const std::vector<std::string>& args,
           const scene::LoadedScene& ls)
      : cmd_(cmd), opt_(cmd.opt), args_(args), ls_(ls) {}

  void prepare() {
    settings_ = settings_from(opt_.render);
    amb_ = cli::setup_ambient(settings_, opt_.render, ls_, args_.empty() ? "rpict" : args_[0],
                              cmd_.operand < args_.size() ? args_[cmd_.operand] : "");
    renderer_ = std::make_unique<render::Renderer>(ls_, settings_, device::default_context());
  }

  void run() {
    view_ = opt_.view; // every job starts from the command line's view
    have_last_ = false;
    lines_ = std::make_unique<cli::FdInputBuf>(0);
    in_ = std::make_unique<std::istream>(lines_.get());
    common_written_ = false;
    cli::Progress progress(args_[0], opt_.report_interval);
    const std::string& pout = opt_.output_file;
    int seq = opt_.sequence_start > 0 ? opt_.sequence_start : 0;
    std::string recover = opt_.recover_file;
    if (seq > 0 && !recover.empty() && is_integer(recover)) {
      // Skip to the frame to recover; its file is the one to salvage.
      int rn = std::atoi(recover.c_str());
      if (rn < seq) throw FatalError("recover frame less than start frame");
      if (pout.empty()) throw FatalError("missing output file specification");
      for (; seq < rn; ++seq)
        if (!next_view()) throw FatalError("unexpected EOF on view input");
      (void)options::setup_view(view_);
      recover = cli::frame_name(pout, seq);
    }
    if (!pout.empty() && !recover.empty()) {
      // Recovering into the output file itself: move the old one aside first.
      std::string name = cli::frame_name(pout, seq);
      if (recover == name) {
        std::filesystem::path p(name);
        std::string tmpl = (p.parent_path() / "rfXXXXXX").string();
        int fd = ::mkstemp(tmpl.data());
        if (fd >= 0) ::close(fd);
        if (fd < 0 || std::rename(name.c_str(), tmpl.c_str()) < 0) {
          int e = errno;
          if (fd >= 0) ::unlink(tmpl.c_str());
          if (e != ENOENT) throw FatalError("cannot rename \"" + name + "\" to \"" + tmpl + "\"");
          warning("new output file \"" + name + "\"");
          recover.clear();
        } else {
          recover = tmpl;
        }
      }
    }
    int npicts = 0;
    do {
      if (seq && !next_view()) break;
      std::unique_ptr<std::ofstream> file;
      std::string name;
      bool radiance = true;
      if (!pout.empty()) {
        name = cli::frame_name(pout, seq);
        // Any name that is not another format's is a Radiance picture, as Radiance writes
        // every name (rad's raw pictures end in .unf).
        auto kind = image::image_kind(name);
        radiance = !kind || *kind == image::ImageKind::radiance;
        // Exclusive open: an existing frame is never overwritten, only skipped.
        int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd < 0) {
          if (errno != EEXIST || !recover.empty() || name == pout)
            throw FatalError("cannot open output file \"" + name + "\"");
          (void)options::setup_view(view_);
          continue;
        }
        ::close(fd);
        if (radiance)
          file = std::make_unique<std::ofstream>(name, std::ios::binary | std::ios::trunc);
      }
      try {
        render_frame(seq, file ? file.get() : (pout.empty() ? &std::cout : nullptr), name, radiance,
                     recover, progress);
      } catch (...) { // a picture this run began is complete or absent
        if (!name.empty() && recover.empty()) {
          file.reset();
          std::remove(name.c_str());
        }
        throw;
      }
      recover.clear();
      ++npicts;
    } while (seq++);
    if (npicts == 0) warning("no output produced");
  }

private:
  const options::RpictCommand& cmd_;
  const options::RpictOptions& opt_;
  const std::vector<std::string>& args_;
  const scene::LoadedScene& ls_;
  render::RenderSettings settings_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<ambient::AmbientFile> amb_; // -af with the cache in use
  bool overture_done_ = false;
  options::View view_, last_;
  bool have_last_ = false;
  std::unique_ptr<cli::FdInputBuf> lines_;
  std::unique_ptr<std::istream> in_;
  bool common_written_ = false;

  // The overture (rad's low-resolution rpict run that only fills the ambient file): before a
  // frame whose cache radcl builds, the view at an eighth of its resolution is rendered and
  // discarded, so the cache's records are spread over the whole view in large batches before
  // the picture's first band rather than grown band by band. Once per process: later frames
  // find the records. RADCL_OVERTURE=0 leaves it out.
  void overture(const render::PictureSettings& full) {
    if (overture_done_ || !settings_.make_records) return;
    overture_done_ = true;
    if (const char* e = std::getenv("RADCL_OVERTURE"); e && std::string(e) == "0") return;
    render::PictureSettings ps = full;
    ps.xres = std::max(1, full.xres / 8);
    ps.yres = std::max(1, full.yres / 8);
    ps.ps = 1;
    ps.first_row = 0;
    ps.pm = 0;
    ps.previous = nullptr;
    render::render_picture(*renderer_, view_, ps, [&](const render::PictureRows&) {
      cli::sync_ambient(amb_.get(), *renderer_);
    });
  }

  // Radiance's nextview(): the next view line of standard input changes the current view (the
  // one before it becomes the previous view, for -pm). False at the end of the input.
  bool next_view() {
    last_ = view_;
    have_last_ = true;
    std::string line;
    while (std::getline(*in_, line)) {
      // rpict reads lines of at most 255 characters; the rest of a longer one is another.
      for (std::size_t at = 0; at < std::max<std::size_t>(line.size(), 1); at += 255) {
        std::string part = line.substr(at, 255);
        if (options::is_view_line(part, args_[0]) && options::scan_view_line(view_, part) > 0)
          return true;
      }
    }
    return false;
  }

  image::PictureHeader header(int seq, double pa, bool common) const {
    image::PictureHeader h;
    if (common) {
      for (const std::string& l : ls_.main.header)
        h.lines.push_back(l);
      if (ls_.main.header.empty()) h.add_id();
      h.add_command(std::vector<std::string>(args_.begin(), args_.begin() + cmd_.operand));
      h.add_software(std::string("radcl ") + RADCL_VERSION);
    }
    if (seq) h.add_frame(seq);
    h.add_view(options::format_view(view_));
    if (pa < 0.99 || pa > 1.01) h.add_pixaspect(pa);
    h.add_dates(std::time(nullptr));
    h.add_primaries();
    h.add_format();
    return h;
  }

  void render_frame(int seq, std::ostream* os, const std::string& name, bool radiance,
                    const std::string& recover, cli::Progress& progress) {
    // Resolution after the view's aspect (and, when recovering, the old picture's size).
    int xres = opt_.xres, yres = opt_.yres;
    double pa = opt_.pixel_aspect;
    std::unique_ptr<image::Salvage> old;
    if (!recover.empty()) {
      old = std::make_unique<image::Salvage>(image::salvage_picture(recover));
      for (const std::string& v : old->header.views())
        options::scan_view_line(view_, v);
      xres = old->resolution.scanline_length();
      yres = old->resolution.num_scanlines();
      pa = 0;
    }
    std::string err = options::setup_view(view_);
    if (!err.empty()) throw FatalError(err);
    pa = image::normalize_aspect(image::view_aspect(view_), xres, yres, pa);
    if (seq && opt_.report_interval > 0) {
      std::fprintf(stderr, "FRAME %d:%s\n", seq, options::format_view(view_).c_str());
      std::fflush(stderr);
    }
    // On standard output a sequence's frames share the first one's leading lines.
    const bool common = os != &std::cout || !common_written_;
    if (os == &std::cout) common_written_ = true;

    if (xres <= 0 || yres <= 0) warning("empty output picture");
    Output out(radiance ? os : nullptr, name, header(seq, pa, common), xres, yres, old.get());
    std::unique_ptr<image::DepthWriter> zout;
    std::vector<float> depth;
    // A non-Radiance output gets the depth as a channel too (EXR's Z).
    bool keep_depth = !opt_.z_file.empty() && !radiance;
    if (!opt_.z_file.empty())
      zout = std::make_unique<image::DepthWriter>(cli::frame_name(opt_.z_file, seq), xres,
                                                  old ? old->complete : 0);

    render::PictureSettings ps;
    ps.xres = xres;
    ps.yres = yres;
    ps.ps = opt_.pixel_sample;
    ps.pt = opt_.pixel_threshold;
    ps.compare_depth = !opt_.z_file.empty(); // as rpict, which compares depths only with -z
    ps.pj = opt_.pixel_jitter;
    ps.pd = opt_.pixel_aperture;
    ps.seed = settings_.seed;
    ps.first_row = old ? old->complete : 0;
    options::View last = last_;
    if (have_last_ && opt_.pixel_motion > 1e-6 && options::setup_view(last).empty()) {
      ps.pm = opt_.pixel_motion;
      ps.previous = &last;
    }

    progress.update(static_cast<double>(ps.first_row) / std::max(1, yres),
                    renderer_->stats().total(), true);
    if (xres > 0 && yres > 0) overture(ps);
    if (xres > 0 && yres > 0)
      render::render_picture(*renderer_, view_, ps, [&](const render::PictureRows& rows) {
        out.rows(rows, zout.get());
        cli::sync_ambient(amb_.get(), *renderer_);
        if (keep_depth) depth.insert(depth.end(), rows.depth.begin(), rows.depth.end());
        progress.update(static_cast<double>(rows.first + rows.count) / yres,
                        renderer_->stats().total());
      });
    if (zout) zout->close();
    out.finish(keep_depth ? &depth : nullptr);
    progress.finish(renderer_->stats().total());
    if (old) std::filesystem::remove(recover);
  }
};

int rpict_main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  const bool server = cli::is_persist_server();
  const std::string pfile = cli::find_persist_file(args, nullptr);
  // A control file that exists already: attach to its server, as Radiance does on reading the
  // option (later invocations need no other arguments).
  struct stat pst;
  if (!server && !pfile.empty() && ::stat(pfile.c_str(), &pst) == 0)
    return cli::attach_persist(pfile, args[0]);
  options::RpictCommand cmd = options::parse_rpict_command_line(args, scene::find_on_raypath);
  // Headers and messages name the command as Radiance does (fixargv0), expanded words after.
  if (!cmd.args.empty()) cmd.args[0] = program_name();
  options::RpictOptions& opt = cmd.opt;
  if (cmd.action == options::ParsedCommand::Action::PrintDefaults) {
    std::fputs(options::format_rpict_defaults(opt).c_str(), stdout);
    return 0;
  }
  if (cmd.action == options::ParsedCommand::Action::PrintVersion) {
    // Radiance's form, "RADIANCE <release> ...": tools read the release from the second word.
    std::printf("RADIANCE 5.4a radcl %s (rpict)\n", RADCL_VERSION);
    return 0;
  }
  if (!opt.error_file.empty() && !std::freopen(opt.error_file.c_str(), "a", stderr))
    throw FatalError("cannot open error file \"" + opt.error_file + "\"");
  if (!opt.warnings) set_warning_sink(quiet_warning);
  std::string octree = options::rpict_octree(cmd);
  const bool persist = opt.persist != options::RtraceOptions::Persist::None;
  if (persist) {
    if (!opt.recover_file.empty()) throw FatalError("persist option used with recover file");
    if (opt.sequence_start <= 0) throw FatalError("persist option only for sequences");
  }
  if (opt.pixel_motion > 0 && opt.sequence_start <= 0)
    warning("-pm needs a view sequence (-S): no motion blur");
  if (persist && !server && !cli::create_persist_file(opt.persist_file))
    return cli::attach_persist(opt.persist_file, args[0]); // another one was quicker

  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              std::max<std::size_t>(1, std::thread::hardware_concurrency()));
  std::future<void> device_start; // the device starts while the scene loads
  if (!persist) device_start = device::start_default_context();
  // No octree argument: the octree comes on standard input (never with -S, whose views do).
  scene::LoadedScene ls = octree.empty() ? scene::load_octree_data(read_stdin(), "standard input")
                                         : scene::load_scene({octree});
  Pictures pictures(cmd, cmd.args, ls); // the words as expanded: cmd.operand counts those
  cli::PersistJobs jobs;
  jobs.prepare = [&] { pictures.prepare(); };
  jobs.serve = [&] { pictures.run(); };
  jobs.keep_stderr = !opt.error_file.empty();
  if (server)
    return cli::run_persist_server(opt.persist_file, args[0],
                                   opt.persist == options::RtraceOptions::Persist::Parallel
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
  return radcl::run_main("rpict", rpict_main, argc, argv);
}

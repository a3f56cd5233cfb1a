// rpict: renders a view of a scene to a picture with Radiance's options, header and sampling
// (cli-rtrace-rpict.md §4, picture-format.md §6), written as it grows; other formats by
// extension (.exr, .tif, .png).
#include <cstdio>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <tbb/global_control.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "progress.h"
#include "radcl/device/context.h"
#include "radcl/image/depth.h"
#include "radcl/image/image_io.h"
#include "radcl/image/picture.h"
#include "radcl/image/view_ray.h"
#include "radcl/options/rpict_options.h"
#include "radcl/render/picture.h"
#include "radcl/render/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/raypath.h"
#include "radcl/util/error.h"
#include "render_settings.h"

namespace {

using namespace radcl;

void quiet_warning(const std::string&) {}

render::RenderSettings settings_from(const options::RenderOptions& r) {
  render::RenderSettings s = cli::render_settings(r);
  s.low_discrepancy = !r.uncorrelated; // rpict's -u-: pixels stratify each other
  return s;
}

// Where the picture goes: a Radiance picture streamed scanline by scanline (stdout or an .hdr
// file), or another format written once the image is complete.
class Output {
public:
  Output(const std::string& path, const image::PictureHeader& header, int w, int h,
         const image::Salvage* recovered)
      : path_(path), w_(w), h_(h) {
    auto kind = path.empty() ? std::optional(image::ImageKind::radiance) : image::image_kind(path);
    if (!kind) throw FatalError("unknown output picture type \"" + path + "\"");
    streaming_ = *kind == image::ImageKind::radiance;
    if (streaming_) {
      std::ostream* os = &std::cout;
      if (!path.empty()) {
        // Never overwrite: rpict opens its output exclusively.
        int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd < 0) throw FatalError("cannot open output file \"" + path + "\"");
        ::close(fd);
        file_ = std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc);
        os = file_.get();
      }
      writer_ =
          std::make_unique<image::PictureWriter>(*os, header, image::Resolution::standard(w, h));
      if (recovered)
        for (int y = 0; y < recovered->complete; ++y)
          writer_->write_scanline(std::span<const image::Rgbe>(
              recovered->pixels.data() + static_cast<std::size_t>(y) * w, w));
      writer_->flush();
    } else {
      if (std::filesystem::exists(path))
        throw FatalError("cannot open output file \"" + path + "\"");
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
      if (file_ && !file_->good()) throw FatalError("write error in render");
      return;
    }
    if (depth) image_.depth = *depth;
    image::write_image(path_, image_, opts_);
  }

private:
  std::string path_;
  int w_, h_;
  bool streaming_ = true;
  std::unique_ptr<std::ofstream> file_;
  std::unique_ptr<image::PictureWriter> writer_;
  image::FloatImage image_;
  image::ImageWriteOptions opts_;
};

int rpict_main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  options::RpictCommand cmd = options::parse_rpict_command_line(args, scene::find_on_raypath);
  options::RpictOptions& opt = cmd.opt;
  if (cmd.action == options::ParsedCommand::Action::PrintDefaults) {
    std::fputs(options::format_rpict_defaults(opt).c_str(), stdout);
    return 0;
  }
  if (cmd.action == options::ParsedCommand::Action::PrintVersion) {
    std::printf("radcl %s (rpict)\n", RADCL_VERSION);
    return 0;
  }
  if (!opt.error_file.empty() && !std::freopen(opt.error_file.c_str(), "a", stderr))
    throw FatalError("cannot open error file \"" + opt.error_file + "\"");
  if (!opt.warnings) set_warning_sink(quiet_warning);
  std::string octree = options::rpict_octree(cmd);
  // Refuse what would silently differ from Radiance.
  if (octree.empty()) throw FatalError("reading the octree from standard input is not supported");
  if (opt.sequence_start > 0) throw FatalError("sequence mode (-S) is not supported yet");
  if (opt.persist != options::RtraceOptions::Persist::None)
    throw FatalError("persistent mode (-P/-PP) is not supported yet");
  if (opt.pixel_motion > 0) warning("-pm needs a view sequence (-S): no motion blur");
  // Radiance averages -av with the cache's values only (ambient.c's avsum): with -aa 0 -aw
  // changes nothing there either.
  if (opt.render.ambient_value_weight > 0 && opt.render.ambient_accuracy > 0)
    warning("-aw needs the irradiance cache's values: the ambient value is used as given");
  if (opt.render.ambient_accuracy > 0 && opt.render.ambient_bounces > 0)
    warning("irradiance cache not available yet: ambient computed without it (as -aa 0)");

  // Resolution after the view's aspect (and, when recovering, the old picture's size).
  int xres = opt.xres, yres = opt.yres;
  double pa = opt.pixel_aspect;
  std::unique_ptr<image::Salvage> old;
  if (!opt.recover_file.empty()) {
    old = std::make_unique<image::Salvage>(image::salvage_picture(opt.recover_file));
    for (const std::string& v : old->header.views())
      options::scan_view_line(opt.view, v);
    std::string err = options::setup_view(opt.view);
    if (!err.empty()) throw FatalError(err);
    xres = old->resolution.scanline_length();
    yres = old->resolution.num_scanlines();
    pa = 0;
  }
  pa = image::normalize_aspect(image::view_aspect(opt.view), xres, yres, pa);

  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              std::max<std::size_t>(1, std::thread::hardware_concurrency()));
  scene::LoadedScene ls = scene::load_scene({octree});
  const render::RenderSettings settings = settings_from(opt.render);
  render::Renderer renderer(ls, settings, device::default_context());

  image::PictureHeader header;
  for (const std::string& l : ls.main.header)
    header.lines.push_back(l);
  if (ls.main.header.empty()) header.add_id();
  header.add_command(std::vector<std::string>(args.begin(), args.begin() + cmd.operand));
  header.add_software(std::string("radcl ") + RADCL_VERSION);
  header.add_view(options::format_view(opt.view));
  if (pa < 0.99 || pa > 1.01) header.add_pixaspect(pa);
  header.add_dates(std::time(nullptr));
  header.add_primaries();
  header.add_format();

  if (xres <= 0 || yres <= 0) warning("empty output picture");
  Output out(opt.output_file, header, xres, yres, old.get());
  std::unique_ptr<image::DepthWriter> zout;
  std::vector<float> depth;
  // A non-Radiance output gets the depth as a channel too (EXR's Z).
  bool keep_depth = !opt.z_file.empty() && !opt.output_file.empty() &&
                    image::image_kind(opt.output_file) != image::ImageKind::radiance;
  if (!opt.z_file.empty())
    zout = std::make_unique<image::DepthWriter>(opt.z_file, xres, old ? old->complete : 0);

  render::PictureSettings ps;
  ps.xres = xres;
  ps.yres = yres;
  ps.ps = opt.pixel_sample;
  ps.pt = opt.pixel_threshold;
  ps.pj = opt.pixel_jitter;
  ps.pd = opt.pixel_aperture;
  ps.seed = settings.seed;
  ps.first_row = old ? old->complete : 0;

  cli::Progress progress(args[0], opt.report_interval);
  progress.update(static_cast<double>(ps.first_row) / std::max(1, yres), 0, true);
  if (xres > 0 && yres > 0)
    render::render_picture(renderer, opt.view, ps, [&](const render::PictureRows& rows) {
      out.rows(rows, zout.get());
      if (keep_depth) depth.insert(depth.end(), rows.depth.begin(), rows.depth.end());
      progress.update(static_cast<double>(rows.first + rows.count) / yres,
                      renderer.stats().total());
    });
  if (zout) zout->close();
  out.finish(keep_depth ? &depth : nullptr);
  progress.finish(renderer.stats().total());
  if (old) std::filesystem::remove(opt.recover_file);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  return radcl::run_main("rpict", rpict_main, argc, argv);
}

// frustum render FILE.yaml -o image.png [--depth depth.png] [--size WxH] [--id ID]
//                [--method zbuffer|scanline] [--threads N]
// FILE is a scene file (top-level `scene:` and optional `conventions:`) or a problem set, whose
// render problem is the one named by --id (default: the first of kind render).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <ostream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/number_options.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/kinds/render.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/raster/certified_frame.hpp"
#include "solver/raster/fill.hpp"
#include "solver/raster_fast/png_writer.hpp"
#include "solver/raster_fast/scene_frame.hpp"
#include "solver/shared/scene_reader.hpp"

namespace frustum::app {

namespace {

// The scene of a scene file or of a problem set's render problem; nullopt after printing why.
std::optional<SceneSpec> load_scene(const RenderOptions& opt, const Output& o) {
  const YamlDocument doc = load_yaml_file(opt.file);
  if (doc.error) {
    o.err << doc.error->format() << "\n";
    return std::nullopt;
  }
  if (doc.root.IsMap() && doc.root["problems"].IsDefined()) {
    const ProblemSet set = load_problem_set(doc, opt.file);  // the file read and parsed once
    for (const Diagnostic& d : set.errors) o.err << d.format() << "\n";
    for (const ProblemSpec& p : set.problems) {
      if (opt.id ? p.id != *opt.id : p.kind != "render") continue;
      if (p.error) {
        o.err << p.error->format() << "\n";
        return std::nullopt;
      }
      if (p.kind != "render") {
        o.err << opt.file << ": problem '" << p.id << "' is of kind " << p.kind << ", not render\n";
        return std::nullopt;
      }
      return std::any_cast<const RenderGiven&>(p.given).spec;
    }
    o.err << opt.file << ": "
          << (opt.id ? "no problem with id '" + *opt.id + "'" : "no problem of kind render")
          << "\n";
    return std::nullopt;
  }
  try {
    GivenReader root(doc.root, opt.file, "", {"title", "conventions", "scene"});
    const Conventions c = read_conventions(doc.root["conventions"], opt.file, "conventions", {});
    GivenReader s = root.child("scene", scene_fields());
    // With the exact inputs: the frame follows the exact rule where the doubles cannot.
    SceneSpec spec = read_scene(s, c, /*keep_exact=*/true);
    root.finish();
    return spec;
  } catch (const InputError& e) {
    o.err << e.diagnostic().format() << "\n";
    return std::nullopt;
  }
}

}  // namespace

std::variant<RenderScene, int> load_render_spec(const RenderOptions& opt, const Output& o) {
  std::optional<SceneSpec> loaded = load_scene(opt, o);
  if (!loaded) return 1;
  RenderScene out{std::move(*loaded), {}};
  Scene& scene = out.spec.scene;
  if (opt.method) scene.scanline = *opt.method == "scanline";
  out.clip_from_world = exact_clip_from_world(out.spec, scene.api);
  if (opt.size) {
    const auto [w, h] = *opt.size;
    if (static_cast<long>(w) * h > kMaxScenePixels) {
      o.err << fmt::format("--size: {} × {} pixels; at most {} in all\n", w, h, kMaxScenePixels);
      return 2;
    }
    // A perspective whose aspect was width/height follows the new size (x scale ∝ 1/aspect):
    // its row x is (x scale, 0, 0, 0), so the exact row x of projection · camera scales too.
    const bool perspective = scene.clip_from_eye(3, 2) != 0 && scene.clip_from_eye(0, 2) == 0;
    if (perspective) {
      scene.clip_from_eye(0, 0) *=
          static_cast<double>(scene.width) * h / (static_cast<double>(scene.height) * w);
      const Exact ratio = GiNaC::numeric(static_cast<long>(scene.width) * h) /
                          GiNaC::numeric(static_cast<long>(scene.height) * w);
      for (int j = 0; j < 4; ++j)
        out.clip_from_world(0, j) = canonical(out.clip_from_world(0, j) * ratio);
    }
    scene.width = w;
    scene.height = h;
  }
  return out;
}

std::variant<Scene, int> load_render_scene(const RenderOptions& opt, const Output& o) {
  std::variant<RenderScene, int> loaded = load_render_spec(opt, o);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  return std::move(std::get<RenderScene>(loaded).spec.scene);
}

std::optional<ThreadTeam> render_team(int threads) {
  if (threads < 2) return std::nullopt;
  return std::optional<ThreadTeam>(std::in_place, std::min(threads, 64));
}

int run_render(const RenderOptions& opt, const Output& o, Frame* target) {
  // One start for the render's four rounds of work in parts (geometry, fill, the PNG's scan and
  // compression), while the scene is read.
  std::optional<ThreadTeam> team = render_team(opt.threads);
  ThreadTeam* const helpers = team ? &*team : nullptr;
  std::variant<RenderScene, int> loaded = load_render_spec(opt, o);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  const Scene& scene = std::get<RenderScene>(loaded).spec.scene;
  const auto start = std::chrono::steady_clock::now();
  Frame own;  // the frame when the caller keeps none
  Frame& frame = target ? *target : own;
  SceneFrameReport report;
  try {
    draw_scene_frame(scene, std::get<RenderScene>(loaded).clip_from_world, opt.depth.has_value(),
                     opt.threads, helpers, frame, &report);
  } catch (const DomainError& e) {
    // The frame's work past its bound, or a coordinate beyond the rasterizer's range, or a sign
    // exact arithmetic could not prove.
    o.err << opt.file << ": scene: " << e.what() << "\n";
    return 1;
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!write_color_png(opt.output, frame.color, opt.threads, helpers)) {
    o.err << opt.output << ": cannot write the image\n";
    return 1;
  }
  if (opt.depth && !write_depth_png(*opt.depth, frame.depth)) {
    o.err << *opt.depth << ": cannot write the depth image\n";
    return 1;
  }
  o.out << fmt::format(
      "{}: {} × {}, {} triangles ({} outside, {} clipped, {} culled, {} drawn) in {:.1f} ms\n{}\n"
      "exact rule: {} triangles decided by exact arithmetic; {} pixels the floats could not "
      "decide traced again, {} of them by exact depths\n",
      opt.output, scene.width, scene.height, report.geometry.triangles, report.geometry.outside,
      report.geometry.clipped, report.geometry.culled, report.geometry.window, ms, report.method,
      report.geometry.exact, report.traced_pixels, report.exact_pixels);
  return 0;
}

Command add_render_command(CLI::App& cli) {
  auto opt = std::make_shared<RenderOptions>();
  auto size = std::make_shared<std::string>();
  auto* render = cli.add_subcommand("render", "Render a scene (or a set's render problem) to PNG");
  render->add_option("file", opt->file, "Scene file (scene:) or problem set")
      ->required()
      ->check(CLI::ExistingFile);
  render->add_option("-o,--output", opt->output, "PNG file to write")->required();
  render->add_option("--depth", opt->depth, "Also write the depth buffer as a grey PNG");
  render->add_option("--size", *size, "Image size WxH (default: the scene's viewport)");
  render->add_option("--id", opt->id, "The render problem of a problem set (default: the first)");
  render->add_option("--method", opt->method, "zbuffer or scanline (default: the scene's method)")
      ->check(CLI::IsMember({"zbuffer", "scanline"}));
  render
      ->add_option(
          "--threads", opt->threads,
          "2 or more: the render shared by that many threads (a modelled scene's geometry "
          "in parts, then the frame in bands; a larger scene streamed, each thread drawing "
          "strips of rows), the same image; default 1")
      ->check(CLI::Range(1, 1024));
  render->footer(examples(
      {"frustum render problems/seeds/paperplane.yaml -o paperplane.png --depth depth.png"}));

  return {render, [opt, size](const Output& o) {
            if (!size->empty()) {
              const auto parsed = parse_size(*size);
              if (const std::string* why = std::get_if<std::string>(&parsed)) {
                o.err << "--size: " << *why << "\n";
                return 2;
              }
              opt->size = std::get<std::pair<int, int>>(parsed);
            }
            return run_render(*opt, o);
          }};
}

}  // namespace frustum::app

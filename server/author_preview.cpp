#include "server/author_preview.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "batch/set_check.hpp"
#include "server/given_tex.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/kinds/render.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"
#include "solver/raster_fast/png_writer.hpp"
#include "solver/raster_fast/scene_frame.hpp"
#include "solver/util/base64.hpp"
#include "solver/visibility/pictures.hpp"

namespace frustum::server {

namespace {

// The render kind's image as `frustum render` draws it, as a data: URL. The PNG goes through a
// private temporary file (mkstemp), read back and removed: the preview is a process of its own.
std::string render_png_url(const RenderGiven& g) {
  Frame frame;
  draw_scene_frame(g.spec.scene, exact_clip_from_world(g.spec, g.spec.scene.api), false, 1, nullptr,
                   frame, nullptr);
  char path[] = "/tmp/frustum-preview-XXXXXX";
  const int fd = ::mkstemp(path);
  if (fd < 0) throw std::runtime_error("no temporary file for the image");
  ::close(fd);
  std::string png;
  const bool written = write_color_png(path, frame.color);
  if (written) {
    std::ifstream in(path, std::ios::binary);
    png.assign(std::istreambuf_iterator<char>(in), {});
  }
  ::unlink(path);
  if (!written || png.empty()) throw std::runtime_error("the image could not be written");
  return "data:image/png;base64," + base64(png);
}

using Json = nlohmann::ordered_json;

Json located(const Diagnostic& d) {
  return Json{{"line", d.where.line},
              {"column", d.where.column},
              {"field", d.field},
              {"message", d.message}};
}

Json sample_json(const SampleOutcome& s) {
  std::string expected;
  if (s.sample->expect) expected = to_string(*s.sample->expect);
  if (s.sample->credit)
    expected += (expected.empty() ? "credit " : ", credit ") + Json(*s.sample->credit).dump();
  return Json{{"problem", s.problem},
              {"field", s.sample->field},
              {"line", s.sample->where.line},
              {"expected", expected},
              {"verdict", to_string(s.verdict)},
              {"credit", s.credit},
              {"ok", s.as_expected},
              {"note", s.sample->note},
              {"message", s.as_expected ? "" : s.mismatch.message}};
}

// Every language a text of the set is given in, the set's own first.
std::vector<Lang> set_langs(const ProblemSet& set) {
  std::set<Lang> given;
  const auto add = [&](const LocalText& t) {
    for (const auto& [lang, text] : t.all()) given.insert(lang);
  };
  add(set.title);
  for (const ProblemSpec& p : set.problems) add(p.text);
  std::vector<Lang> out = {set.lang};
  for (const Lang l : given)
    if (l != set.lang) out.push_back(l);
  return out;
}

Json problem_json(const ProblemSpec& p, const std::string& file, const std::vector<Lang>& langs,
                  Lang lang) {
  Json j{{"id", p.id}, {"kind", p.kind}};
  if (p.error) {
    j["error"] = p.error->format();
    return j;
  }
  Json texts = Json::array();
  for (const Lang l : langs)
    texts.push_back(Json{
        {"lang", std::string(to_string(l))},
        {"text", p.text.empty() ? p.info->summary.in(l) : fill_text(p.text.in(l), p.given_node)}});
  j["texts"] = std::move(texts);
  Json given = Json::array();
  if (p.given_node.IsMap())
    for (auto it = p.given_node.begin(); it != p.given_node.end(); ++it)
      given.push_back(Json{{"name", it->first.as<std::string>()},
                           {"tex", given_tex(it->second)},
                           {"plain", given_plain(it->second)}});
  j["given"] = std::move(given);
  const ProblemResult r = solve_problem(p, file, true);
  if (r.error) {
    j["error"] = r.error->format();
    return j;
  }
  Json key = Json::array();
  for (const std::string& name : p.ask)
    if (const Value* v = r.answers.find(name))
      key.push_back(Json{{"name", name}, {"html", html_math(v->shown(), lang, false)}});
  j["key"] = std::move(key);
  j["derivation_html"] = html_steps(r.derivation.steps(), lang);
  if (p.info->drawable) {
    try {
      PictureOptions options;
      options.api = p.conventions.api;
      options.lang = lang;
      j["figure_svg"] = draw_picture(p.info->drawable(p.given), options).svg;
    } catch (const std::exception& e) {
      j["figure_error"] = e.what();
    }
  }
  if (p.kind == "render") {
    try {
      j["figure_png"] = render_png_url(std::any_cast<const RenderGiven&>(p.given));
    } catch (const std::exception& e) {
      j["figure_error"] = e.what();
    }
  }
  return j;
}

// The set a student works on: their variant when the set varies, else the set itself.
const ProblemSet* variant_of(const ProblemSet& set, const AuthorPreviewRequest& r,
                             std::vector<ProblemSet>& drawn, Json& out) {
  if (r.student.empty() || !set_varies(set)) return &set;
  const auto it = std::find(r.roster.begin(), r.roster.end(), r.student);
  if (it == r.roster.end()) {
    out["student_error"] = "not on the roster";
    return &set;
  }
  drawn = variants_for_class(set, r.roster, false);
  const auto index = static_cast<std::size_t>(it - r.roster.begin());
  if (index >= drawn.size()) return &set;
  for (const Diagnostic& d : drawn[index].all_errors()) out["errors"].push_back(located(d));
  return &drawn[index];
}

std::string preview_json(const AuthorPreviewRequest& request) {
  const ProblemSet set = load_problem_set_from_string(request.yaml, request.name);
  Json out{{"ok", false},
           {"errors", Json::array()},
           {"warnings", Json::array()},
           {"samples", Json::array()},
           {"student", request.student}};
  const SetCheck check = check_set(set);
  for (const Diagnostic& d : check.errors) out["errors"].push_back(located(d));
  for (const Diagnostic& d : check.warnings) out["warnings"].push_back(located(d));
  for (const SampleOutcome& s : check.samples) out["samples"].push_back(sample_json(s));
  out["ok"] = check.ok();
  if (request.check_only) return out.dump();
  std::vector<ProblemSet> drawn;
  const ProblemSet* shown = variant_of(set, request, drawn, out);
  const std::vector<Lang> langs = set_langs(set);
  Json names = Json::array();
  for (const Lang l : langs) names.push_back(std::string(to_string(l)));
  out["langs"] = std::move(names);
  out["problems"] = Json::array();
  for (const ProblemSpec& p : shown->problems)
    out["problems"].push_back(problem_json(p, request.name, langs, set.lang));
  return out.dump();
}

}  // namespace

std::string author_preview_json(const AuthorPreviewRequest& request) {
  try {
    return preview_json(request);
  } catch (const std::exception& e) {
    // What no check foresaw (a variant that cannot be drawn): said, not a crash of the page.
    const Json error{{"line", 0},
                     {"column", 0},
                     {"field", ""},
                     {"message", std::string("cannot preview: ") + e.what()}};
    return Json{{"ok", false}, {"errors", Json::array({error})}}.dump();
  }
}

}  // namespace frustum::server

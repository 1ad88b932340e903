#include "server/author_page.hpp"

#include <fmt/format.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "batch/atomic_file.hpp"
#include "batch/run_program.hpp"
#include "server/author_phrases.hpp"
#include "server/author_preview.hpp"
#include "server/pages.hpp"
#include "server/tokens.hpp"
#include "solver/input/yaml_document.hpp"

namespace frustum::server {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string field(const std::map<std::string, std::string>& form, const std::string& name) {
  const auto it = form.find(name);
  return it == form.end() ? "" : it->second;
}

struct AuthoredSet {
  std::string id;
  fs::path file;
  Lang lang = Lang::En;
};

std::optional<std::string> read_set_file(const fs::path& file) {
  std::string bytes;
  if (read_text_file(file.string(), kMaxAuthoredSetBytes, bytes)) return std::nullopt;
  return bytes;
}

// The preview (or the check alone) of `yaml`, made by a child process of this binary; nothing
// when it failed or ran out of time.
std::optional<Json> run_preview(StudentApp& app, const AuthoredSet& set, const std::string& yaml,
                                const std::string& student, bool check_only) {
  const fs::path dir = fs::path(app.course().dir) / ".frustum" / "author";
  fs::create_directories(dir);
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace);
  const fs::path input = dir / (random_token() + ".yaml");
  {
    std::ofstream out(input, std::ios::binary);
    out << yaml;
    if (!out) return std::nullopt;
  }
  std::vector<std::string> argv = {app.options.self_binary, "serve", app.course().dir,
                                   "--author-preview", set.file.filename().string()};
  if (!student.empty()) argv.insert(argv.end(), {"--author-student", student});
  if (check_only) argv.push_back("--author-check");
  RunOptions options;
  options.stdin_file = input.string();
  options.err = OutputTo::Null;
  options.seconds = app.options.author_seconds;
  options.max_output = 32u << 20;
  const ProgramRun run = run_program(argv, options);
  std::error_code ec;
  fs::remove(input, ec);
  if (run.status != 0 || run.timed_out) return std::nullopt;
  Json j = Json::parse(run.output, nullptr, false);
  if (!j.is_object()) return std::nullopt;
  return j;
}

std::string roster_options(const Course& course) {
  std::string out;
  for (const std::string& s : course.roster)
    out += fmt::format("<option value=\"{}\">", html_escape(s));
  return out;
}

// The check's errors as a list (the page without JavaScript; the module redraws it).
std::string errors_html(const Json& check, Lang lang) {
  std::vector<Json> listed = check.value("errors", std::vector<Json>());
  for (const Json& s : check.value("samples", Json::array()))
    if (!s.value("ok", true)) listed.push_back(s);
  std::string out = fmt::format("<h2>{}</h2>\n", html_escape(kErrors.in(lang)));
  if (listed.empty()) return out + fmt::format("<p>{}</p>\n", kNoErrors.in(lang));
  out += "<ul>\n";
  for (const Json& e : listed)
    out += fmt::format("<li>{} {}: <code>{}</code>: {}</li>\n", kLine.in(lang), e.value("line", 0),
                       html_escape(e.value("field", "")), html_escape(e.value("message", "")));
  return out + "</ul>\n";
}

// The module's words, in the page's language (data-words).
std::string words_json(Lang lang) {
  return Json{{"line", kLine.in(lang)},
              {"errors", kErrors.in(lang)},
              {"noErrors", kNoErrors.in(lang)},
              {"warnings", kWarnings.in(lang)},
              {"samples", kSamples.in(lang)},
              {"expected", kExpected.in(lang)},
              {"graded", kGraded.in(lang)},
              {"statement", kStatement.in(lang)},
              {"key", kAnswerKey.in(lang)},
              {"checking", kChecking.in(lang)},
              {"previewFailed", kPreviewFailed.in(lang)},
              {"given", kGiven.in(lang)},
              {"derivation", kDerivation.in(lang)},
              {"figure", kFigure.in(lang)}}
      .dump();
}

Response author_page(StudentApp& app, const Visitor& v, const AuthoredSet& set, int status,
                     const std::string& yaml, const std::string& base, const std::string& message,
                     const std::string& errors) {
  const Lang lang = set.lang;
  const std::string body = fmt::format(
      "<main class=\"author\" data-set=\"{0}\" data-words=\"{11}\">\n<h1>{1}: {0}.yaml</h1>\n"
      "<p class=\"status\" id=\"status\" role=\"status\">{2}</p>\n"
      "<form method=\"post\" action=\"/instructor/author/{0}/save\" id=\"author-form\">\n"
      "<input type=\"hidden\" name=\"csrf\" value=\"{3}\">\n"
      "<input type=\"hidden\" name=\"base\" value=\"{4}\">\n"
      "<textarea name=\"yaml\" id=\"yaml\" rows=\"32\" cols=\"100\" spellcheck=\"false\">{5}"
      "</textarea>\n"
      "<p><label>{6} <input type=\"text\" name=\"student\" id=\"student\" list=\"roster\" "
      "autocomplete=\"off\"></label><datalist id=\"roster\">{7}</datalist></p>\n"
      "<p><button type=\"submit\" name=\"force\" value=\"0\" id=\"save\">{8}</button> "
      "<button type=\"submit\" name=\"force\" value=\"1\" id=\"save-anyway\">{9}</button></p>\n"
      "</form>\n<section id=\"check\">{10}</section>\n<section id=\"samples\"></section>\n"
      "<section id=\"preview\"></section>\n</main>\n",
      html_escape(set.id), html_escape(kAuthoring.in(lang)), html_escape(message),
      html_escape(v.csrf), html_escape(base), html_escape(yaml),
      html_escape(kPreviewVariant.in(lang)), roster_options(app.course()),
      html_escape(kSave.in(lang)), html_escape(kSaveWithErrors.in(lang)), errors,
      html_escape(words_json(lang)));
  constexpr const char* kHead =
      "<link rel=\"stylesheet\" href=\"/static/codemirror/lib/codemirror.css\">\n"
      "<link rel=\"stylesheet\" href=\"/static/author.css\">\n"
      "<script defer src=\"/static/codemirror/lib/codemirror.js\"></script>\n"
      "<script defer src=\"/static/codemirror/mode/yaml/yaml.js\"></script>\n"
      "<script type=\"module\" src=\"/static/author.js\"></script>\n";
  return html_response(status, page_html(lang, std::string(kAuthoring.in(lang)) + (": " + set.id),
                                         body, v.csrf, false, kHead));
}

bool wants_json(const Request& r) {
  const auto accept = r.header("accept");
  return accept && accept->find("application/json") != std::string::npos;
}

// "20261205T093012.345Z": a history file's name, in the order of the saves.
std::string history_stamp(Millis now) {
  const std::time_t seconds = static_cast<std::time_t>(now / 1000);
  std::tm t{};
  gmtime_r(&seconds, &t);
  return fmt::format("{:04}{:02}{:02}T{:02}{:02}{:02}.{:03}Z", t.tm_year + 1900, t.tm_mon + 1,
                     t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec, static_cast<int>(now % 1000));
}

Response save(StudentApp& app, const Visitor& v, const Request& r, const AuthoredSet& set,
              const std::map<std::string, std::string>& form, Millis now) {
  const std::string yaml = field(form, "yaml");
  const std::string base = field(form, "base");
  const bool force = field(form, "force") == "1";
  const bool json = wants_json(r);
  const Lang lang = set.lang;
  const auto refuse = [&](int status, const Phrase& what, const Json& extra,
                          const std::string& errors) {
    if (!json)
      return author_page(app, v, set, status, yaml, base, std::string(what.in(lang)), errors);
    Json j{{"saved", false}, {"message", what.in(lang)}};
    j.update(extra);
    return json_response(status, j.dump());
  };
  const std::lock_guard lock(app.author_files);  // compare, check and write as one
  const std::optional<std::string> current = read_set_file(set.file);
  if (!current) return message_page(404, lang, kNotFound);
  const std::string version = sha256_hex(*current);
  if (!constant_time_equal(version, base))
    return refuse(409, kChangedOnDisk, Json{{"version", version}}, "");
  const std::optional<Json> check = run_preview(app, set, yaml, "", true);
  if (!check) return refuse(422, kPreviewFailed, Json::object(), "");
  if (!check->value("ok", false) && !force)
    return refuse(422, kCheckFailed, Json{{"check", *check}}, errors_html(*check, lang));
  const std::string kept =
      (fs::path(".frustum") / "history" / set.id / (history_stamp(now) + ".yaml")).string();
  write_file_atomically((fs::path(app.course().dir) / kept).string(), *current);
  write_file_atomically(set.file.string(), yaml);
  app.live.refresh(now);  // the next request serves what was saved (when it loads)
  const std::string saved = sha256_hex(yaml);
  if (!json)
    return author_page(app, v, set, 200, yaml, saved, std::string(kSaved.in(lang)),
                       errors_html(*check, lang));
  return json_response(200, Json{{"saved", true},
                                 {"ok", check->value("ok", false)},
                                 {"version", saved},
                                 {"history", kept},
                                 {"message", kSaved.in(lang)}}
                                .dump());
}

Response preview(StudentApp& app, const AuthoredSet& set,
                 const std::map<std::string, std::string>& form) {
  const std::optional<Json> j =
      run_preview(app, set, field(form, "yaml"), field(form, "student"), false);
  if (!j)
    return json_response(
        503, Json{{"error", "timeout"}, {"message", kPreviewFailed.in(set.lang)}}.dump());
  return json_response(200, j->dump());
}

Response author_request(StudentApp& app, const Visitor& v, const Request& r,
                        const std::string& rest, Millis now) {
  const Lang lang = course_lang(app.course());
  if (v.role != Role::Instructor) return message_page(403, lang, kRefused);
  const auto slash = rest.find('/');
  AuthoredSet set;
  set.id = rest.substr(0, slash);
  const std::string action = slash == std::string::npos ? "" : rest.substr(slash + 1);
  if (!set_id_ok(set.id)) return message_page(404, lang, kNotFound);
  set.file = fs::path(app.course().dir) / (set.id + ".yaml");
  std::error_code ec;
  if (!fs::is_regular_file(set.file, ec)) return message_page(404, lang, kNotFound);
  set.lang = app.course().find(set.id) ? app.course().find(set.id)->set.lang : lang;
  if (action.empty() && r.method == "GET") {
    const std::optional<std::string> yaml = read_set_file(set.file);
    if (!yaml) return message_page(404, lang, kNotFound);
    return author_page(app, v, set, 200, *yaml, sha256_hex(*yaml), "", "");
  }
  if (r.method != "POST" || (action != "preview" && action != "save"))
    return message_page(404, lang, kNotFound);
  if (r.body.size() > 3 * kMaxAuthoredSetBytes) return message_page(413, lang, kTooLarge);
  const auto form = parse_form(r.body);
  if (!same_origin(r) || !csrf_ok(v, r, form)) {
    if (action == "preview" || wants_json(r)) return json_response(403, R"({"error":"refused"})");
    return message_page(403, lang, kRefused);
  }
  if (field(form, "yaml").size() > kMaxAuthoredSetBytes)
    return json_response(413, R"({"error":"too large"})");
  if (const int wait = app.preview_limit.take(v.session_hash, now)) {
    Response t = json_response(429, R"({"error":"too many"})");
    t.set("Retry-After", std::to_string(wait));
    return t;
  }
  if (action == "preview") return preview(app, set, form);
  return save(app, v, r, set, form, now);
}

}  // namespace

Response author_routes(StudentApp& app, const Visitor& v, const Request& r, const std::string& rest,
                       Millis now) {
  try {
    return author_request(app, v, r, rest, now);
  } catch (const StoreError&) {
    throw;
  } catch (const std::exception&) {
    // The course directory cannot be written (a full disk, permissions): nothing was saved.
    return json_response(500, R"({"error":"the set could not be written"})");
  }
}

}  // namespace frustum::server

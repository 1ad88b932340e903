#include "server/answer_api.hpp"

#include <nlohmann/json.hpp>

#include "grader/answer_parser.hpp"
#include "grader/answer_type.hpp"
#include "server/answer_text.hpp"
#include "server/pages.hpp"
#include "server/set_page.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/math_text.hpp"

namespace frustum::server {

namespace {

using Json = nlohmann::ordered_json;

std::string field(const std::map<std::string, std::string>& form, const std::string& name) {
  const auto it = form.find(name);
  return it == form.end() ? "" : it->second;
}

// The asked answer `form` names, in the student's variant; null when there is none.
const AnswerSpec* asked_answer(StudentApp& app, const Visitor& v,
                               const std::map<std::string, std::string>& form,
                               const ProblemSpec** problem, Lang* lang) {
  const CourseSet* set = app.course().find(field(form, "set"));
  const ProblemSet* variant = set ? set->for_student(v.student) : nullptr;
  const ProblemSpec* p = variant ? variant->find(field(form, "problem")) : nullptr;
  const std::string name = field(form, "answer");
  if (!p || p->error || std::find(p->ask.begin(), p->ask.end(), name) == p->ask.end())
    return nullptr;
  *problem = p;
  *lang = variant->lang;
  return p->info->answer(name);
}

// How an answer was read, in the form a student writes it: a plane as its equation
// (ax + by + cz = d), every other answer as the derivations show its value.
MathText read_as(const Value& value, const AnswerSpec& spec) {
  const AnswerType& type = answer_type(spec.kind);
  return type.shown ? type.shown(value) : value.shown();
}

Response too_many(int wait) {
  Response r = json_response(429, R"({"error":"rate"})");
  r.set("Retry-After", std::to_string(wait));
  return r;
}

}  // namespace

Response preview_answer(StudentApp& app, const Visitor& v,
                        const std::map<std::string, std::string>& form, Millis now) {
  if (const int wait = app.preview_limit.take(v.session_hash, now)) return too_many(wait);
  const ProblemSpec* p = nullptr;
  Lang lang = Lang::En;
  const AnswerSpec* spec = asked_answer(app, v, form, &p, &lang);
  if (!spec) return json_response(404, R"({"error":"unknown answer"})");
  const std::string text = field(form, "text");
  if (text.size() > kMaxAnswerChars)
    return json_response(200, json_text(Json{{"ok", false}, {"error", kTooLarge.in(lang)}}, -1));
  if (text.find_first_not_of(" \t") == std::string::npos)
    return json_response(200, R"({"ok":true,"empty":true})");
  const YAML::Node node = answer_node(text);
  Json reading;
  {
    // The parsed value holds exact numbers: made, shown and freed under the lock.
    const std::lock_guard lock(app.exact_math);
    const ParsedAnswer parsed = parse_answer(node, *spec, p->conventions.angles);
    if (!parsed.ok) {
      reading =
          Json{{"ok", false}, {"label", kCannotRead.in(lang)}, {"error", parsed.error.in(lang)}};
    } else {
      const MathText shown = read_as(parsed.value, *spec);
      reading = Json{
          {"ok", true}, {"label", kReadAs.in(lang)}, {"tex", shown.latex}, {"text", shown.unicode}};
    }
  }
  return json_response(200, json_text(reading, -1));
}

Response save_draft(StudentApp& app, const Visitor& v,
                    const std::map<std::string, std::string>& form, Millis now) {
  if (const int wait = app.draft_limit.take(v.session_hash, now)) return too_many(wait);
  const ProblemSpec* p = nullptr;
  Lang lang = Lang::En;
  if (!asked_answer(app, v, form, &p, &lang))
    return json_response(404, R"({"error":"unknown answer"})");
  const std::string text = field(form, "text");
  if (text.size() > kMaxAnswerChars) return json_response(413, R"({"error":"too long"})");
  app.store.save_draft(v.student,
                       Draft{field(form, "set"), p->id, field(form, "answer"), text, now});
  return json_response(200, json_text(Json{{"ok", true}, {"label", kDraftSaved.in(lang)}}, -1));
}

Response submit_answers(StudentApp& app, const Visitor& v, const CourseSet& set,
                        const Request& request, const std::map<std::string, std::string>& form,
                        Millis now) {
  const Lang lang = set.set.lang;
  if (const int wait = app.submit_limit.take(v.session_hash, now))
    return message_page(429, lang, kTooMany, wait);
  const ProblemSet* variant = set.for_student(v.student);
  const ProblemSpec* p = variant ? variant->find(field(form, "problem")) : nullptr;
  if (!p) return message_page(404, lang, kNotFound);
  if (set.policy.closed_for(v.student, now)) return message_page(403, lang, kDeadlinePassed);
  if (set.policy.attempts &&
      attempts_at(app.store.submissions(v.student, set.id), p->id) >= *set.policy.attempts)
    return message_page(403, lang, kNoAttemptsLeft);
  Json answers = Json::object();
  for (const std::string& name : p->ask) {
    const std::string text = field(form, "a." + name);
    if (text.size() > kMaxAnswerChars) return message_page(413, lang, kTooLarge);
    if (text.find_first_not_of(" \t\r\n") != std::string::npos) answers[name] = text;
  }
  if (answers.empty()) return message_page(400, lang, kFillOneAnswer);
  // Committed (durable) before anything says it was received.
  const SubmissionRecord s =
      app.store.submit(NewSubmission{v.student, set.id, set.version, set.variant_id(v.student),
                                     p->id, json_text(answers, -1), now});
  if (request.header("accept").value_or("").find("application/json") != std::string::npos)
    return json_response(202, json_text(Json{{"id", s.id}, {"attempt", s.attempt}}, -1));
  return Response{303, {{"Location", "/set/" + set.id + "#p-" + url_encode(p->id)}}, ""};
}

}  // namespace frustum::server

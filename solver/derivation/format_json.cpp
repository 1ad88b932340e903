#include <cmath>
#include <string_view>
#include <unordered_map>

#include "solver/derivation/formats.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

using json = nlohmann::ordered_json;

json number_json(double v) {
  if (std::isfinite(v) && v == std::trunc(v) && std::abs(v) < 9007199254740992.0)
    return static_cast<long long>(v);
  if (!std::isfinite(v)) return nullptr;
  return v;
}

namespace {

template <typename T, typename F>
json shaped(const Value& v, const std::vector<T>& items, F convert) {
  if (v.shape == Value::Shape::Scalar) return convert(items.at(0));
  json out = json::array();
  if (v.shape == Value::Shape::Matrix) {
    for (int r = 0; r < v.rows; ++r) {
      json row = json::array();
      for (int c = 0; c < v.cols; ++c) row.push_back(convert(items.at(r * v.cols + c)));
      out.push_back(row);
    }
    return out;
  }
  for (const T& x : items) out.push_back(convert(x));
  return out;
}

}  // namespace

json value_json(const Value& v) {
  switch (v.shape) {
    case Value::Shape::Scalar:
    case Value::Shape::Vector:
    case Value::Shape::Matrix:
      return shaped(v, v.numbers, number_json);
    case Value::Shape::Bool:
      return v.flag;
    case Value::Shape::Word:
      return v.word;
    case Value::Shape::WordMap: {
      // Appended, not looked up: ordered_json finds a key by a linear search, so inserting
      // through it is quadratic in the map. A repeated key keeps its first place and its last
      // word, as m[k] = w did.
      json m = json::object();
      auto& object = m.get_ref<json::object_t&>();
      std::unordered_map<std::string_view, std::size_t> place;
      for (const auto& [k, w] : v.entries)
        if (const auto [it, fresh] = place.emplace(k, object.size()); fresh)
          object.emplace_back(k, w);
        else
          (object.begin() + static_cast<std::ptrdiff_t>(it->second))->second = w;
      return m;
    }
    case Value::Shape::WordList:
      return v.words;
    case Value::Shape::Null:
      return nullptr;
  }
  return nullptr;
}

json exact_json(const Value& v) {
  if (v.exact.empty()) return nullptr;
  return shaped(v, v.exact, [](const Exact& e) { return format_exact(e, MathStyle::Plain); });
}

json steps_json(const std::vector<Step>& steps, Lang lang) {
  json out = json::array();
  for (const Step& s : steps) {
    std::string text;
    for (const MathText* m : {&s.formula, &s.substitution, &s.result})
      if (!m->empty()) text += (text.empty() ? "" : "\n") + tr(*m, lang).unicode;
    if (!s.note.empty()) text += (text.empty() ? "" : "\n") + s.note.in(lang);
    json j = {{"title", s.title.in(lang)}, {"text", text}};
    const auto math_json = [&](const MathText& m) {
      const MathText said = tr(m, lang);
      return json{{"text", said.unicode}, {"latex", said.latex}};
    };
    if (!s.formula.empty()) j["formula"] = math_json(s.formula);
    if (!s.substitution.empty()) j["substitution"] = math_json(s.substitution);
    if (!s.result.empty()) j["result"] = math_json(s.result);
    if (s.level != Step::Level::Info)
      j["level"] = s.level == Step::Level::Warning ? "warning" : "note";
    if (!s.answers.empty()) j["answers"] = s.answers;
    out.push_back(j);
  }
  return out;
}

// The instructor's text in the reader's language, and every language given, by code.
json texts_json(const LocalText& t) {
  json out = json::object();
  for (const auto& [lang, text] : t.all()) out[std::string(to_string(lang))] = text;
  return out;
}

json problem_json(const ProblemResult& p, Lang lang) {
  json j = {{"id", p.id}, {"kind", p.kind}};
  if (!p.text.empty()) {
    j["text"] = p.text.in(lang);
    j["texts"] = texts_json(p.text);
  }
  if (p.error) {
    j["error"] = p.error->format();
    return j;
  }
  j["conventions"] = {
      {"api", std::string(to_string(p.conventions.api))},
      {"angles", std::string(to_string(p.conventions.angles))},
      {"handedness", handedness_of(p.conventions) == Handedness::Left ? "left" : "right"}};
  json answers = json::object();
  for (const std::string& name : p.ask) {
    const Value* v = p.answers.find(name);
    if (!v) continue;
    json a = {{"value", value_json(*v)}};
    json e = exact_json(*v);
    if (!e.is_null()) a["exact"] = e;
    a["text"] = tr(v->shown(), lang).unicode;
    answers[name] = a;
  }
  j["answers"] = answers;
  j["steps"] = steps_json(p.derivation.steps(), lang);
  return j;
}

json render_json(const SetResult& set, Lang lang) {
  json j = json::object();
  j["file"] = set.file;
  j["lang"] = std::string(to_string(set.title.lang));  // the set's own: what texts fall back to
  if (!set.title.empty()) {
    j["title"] = set.title.in(lang);
    j["titles"] = texts_json(set.title);
  }
  if (!set.source.empty()) j["source"] = set.source;
  if (!set.errors.empty()) {
    json errs = json::array();
    for (const Diagnostic& d : set.errors) errs.push_back(d.format());
    j["errors"] = errs;
  }
  json problems = json::array();
  for (const ProblemResult& p : set.problems) problems.push_back(problem_json(p, lang));
  j["problems"] = problems;
  return j;
}

}  // namespace frustum

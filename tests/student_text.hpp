// Every piece of prose a student reads, gathered for the language and internal-reference tests:
// the steps' titles and notes and the words inside their formulas (every bundled set and
// generated variants of every kind in every API convention, typeset_corpus.hpp), the common
// mistakes and trivial answers the grader can name, and the grader's feedback on the reviewed
// verdict corpus (tests/verdicts) and on each problem's common mistakes.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "grader/grade.hpp"
#include "solver/problem/solve_precision.hpp"
#include "typeset_corpus.hpp"

namespace frustum::test {

struct StudentText {
  std::string where;  // problem id and what the text is
  Said text;          // in every language (the grader's text: English translated by the catalogue)
};

// A value as a student would write it in an answers file.
inline YAML::Node answer_yaml(const Value& v) {
  YAML::Node n;
  switch (v.shape) {
    case Value::Shape::Scalar:
      n = v.numbers.empty() ? 0.0 : v.numbers[0];
      break;
    case Value::Shape::Vector:
      for (const double x : v.numbers) n.push_back(x);
      break;
    case Value::Shape::Matrix:
      for (int r = 0; r < v.rows; ++r) {
        YAML::Node row;
        for (int c = 0; c < v.cols; ++c)
          row.push_back(v.numbers[static_cast<std::size_t>(r * v.cols + c)]);
        n.push_back(row);
      }
      break;
    case Value::Shape::Bool:
      n = v.flag;
      break;
    case Value::Shape::Word:
      n = v.word;
      break;
    case Value::Shape::WordMap:
      for (const auto& [k, w] : v.entries) n[k] = w;
      break;
    case Value::Shape::WordList:
      for (const std::string& w : v.words) n.push_back(w);
      break;
    case Value::Shape::Null:
      n = "none";
      break;
  }
  return n;
}

inline void add_steps(std::vector<StudentText>& out, const std::string& where,
                      const std::vector<Step>& steps) {
  for (const Step& s : steps) {
    out.push_back({where + " title", s.title});
    if (!s.note.empty()) out.push_back({where + " note", s.note});
    for (const MathText* m : {&s.formula, &s.substitution, &s.result})
      for (const Said& w : m->words) out.push_back({where + " word", w});
  }
}

inline void add_grade(std::vector<StudentText>& out, const GradeReport& r) {
  for (const ProblemGrade& p : r.problems)
    for (const AnswerGrade& a : p.answers) {
      const std::string where = p.id + "." + a.name;
      if (!a.feedback.empty()) out.push_back({where + " feedback", a.feedback});
      if (!a.misconception.empty()) out.push_back({where + " mistake", a.misconception});
      if (!a.wrong_step.empty()) out.push_back({where + " wrong step", a.wrong_step});
    }
}

// Grades one submission of `answers` (problem id → answers) against `set`.
inline GradeReport grade_answers(const ProblemSet& set, const SolvedSet& solved,
                                 const YAML::Node& answers) {
  YAML::Node sub;
  sub["student"] = "corpus";
  sub["answers"] = answers;
  YAML::Emitter text;
  text << sub;
  return grade(set, load_submission_from_string(text.c_str(), "answers.yaml"), &solved);
}

// Every course convention declared away from its default (z_planes: coordinates, fov:
// horizontal, handedness: left), under `api`.
inline Conventions course_conventions(Api api) {
  Conventions c;
  c.api = api;
  c.z_planes = ZPlanes::Coordinates;
  c.fov = FovAxis::Horizontal;
  c.handedness = Handedness::Left;
  return c;
}

// The sets whose problems the texts come from: the bundled ones and, per kind and convention,
// generated variants.
inline std::vector<ProblemSet> student_text_sets(int per_kind = 2) {
  std::vector<ProblemSet> sets;
  for (const std::string& file : bundled_sets()) sets.push_back(load_problem_set(file));
  for (const KindInfo& kind : builtin_kinds().all()) {
    if (!kind.generate) continue;
    ProblemSet set;
    set.file = "generated.yaml";
    for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX})
      for (const bool course : {false, true})
        for (int i = 0; i < per_kind; ++i) {
          ProblemSpec base = default_problem(kind, i % 3 == 1, i % 3 == 2);
          base.conventions.api = api;
          // A course that declares every course convention away from its default.
          if (course) base.conventions = course_conventions(api);
          base.id = kind.name + "-" + std::string(to_string(api)) + (course ? "-course-" : "-") +
                    std::to_string(i);
          ProblemSpec drawn =
              draw_problem(base, "generated.yaml", 2000 + static_cast<std::uint64_t>(i));
          if (!drawn.error) set.problems.push_back(std::move(drawn));
        }
    sets.push_back(std::move(set));
  }
  return sets;
}

inline std::vector<StudentText> student_texts() {
  std::vector<StudentText> out;
  for (const ProblemSet& set : student_text_sets()) {
    const SolvedSet solved = solve_for_grading(set);
    YAML::Node mistaken;
    for (std::size_t i = 0; i < set.problems.size(); ++i) {
      const ProblemSpec& spec = set.problems[i];
      const ProblemResult& r = solved.results[i];
      if (r.error) continue;
      add_steps(out, spec.id, r.derivation.steps());
      // The same problem in each floating backend: its Backend note and warnings.
      if (spec.info->solve_numeric)
        for (const Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
          const ProblemResult n = solve_problem(spec, set.file, true, p);
          if (!n.error)
            add_steps(out, spec.id + " (" + std::string(to_string(p)) + ")", n.derivation.steps());
        }
      for (const auto& [name, v] : r.answers.items())
        for (const Said& w : v.shown().words) out.push_back({spec.id + "." + name + " word", w});
      for (const Misconception& m : solved.mistakes[i]) {
        out.push_back({spec.id + " mistake", m.name});
        out.push_back({spec.id + " mistake feedback", m.feedback});
        if (!m.step.empty()) out.push_back({spec.id + " mistake step", m.step});
      }
      for (const auto& [name, trivial] : solved.judging[i].trivial)
        for (const TrivialAnswer& t : trivial) {
          out.push_back({spec.id + "." + name + " trivial", t.name});
          out.push_back({spec.id + "." + name + " trivial feedback", t.feedback});
        }
      // The grader's feedback on each common mistake, one submission per mistake.
      for (const Misconception& m : solved.mistakes[i]) {
        YAML::Node answers;
        for (const auto& [name, v] : m.answers.items()) answers[spec.id][name] = answer_yaml(v);
        add_grade(out, grade_answers(set, solved, answers));
      }
    }
  }
  // The hard-case suite in every backend: the warnings of overflow, underflow, ill-conditioning
  // and exact decisions.
  for (const auto& e : std::filesystem::directory_iterator(source_path("problems/hard"))) {
    if (e.path().extension() != ".yaml") continue;
    const ProblemSet set = load_problem_set(e.path().string());
    for (const ProblemSpec& spec : set.problems)
      for (const Precision p :
           {Precision::Float, Precision::Double, Precision::LongDouble, Precision::Exact}) {
        const ProblemResult n = solve_problem(spec, set.file, true, p);
        if (!n.error)
          add_steps(out, spec.id + " (" + std::string(to_string(p)) + ")", n.derivation.steps());
      }
  }
  // The reviewed verdict corpus: every case graded, its feedback kept.
  for (const auto& e : std::filesystem::directory_iterator(source_path("tests/verdicts"))) {
    if (e.path().extension() != ".yaml") continue;
    const YAML::Node root = YAML::LoadFile(e.path().string());
    for (const YAML::Node& problem : root["problems"]) {
      YAML::Node p = YAML::Clone(problem);
      p.remove("cases");
      p["id"] = "p";
      p["kind"] = root["kind"];
      YAML::Node set_node;
      set_node["problems"].push_back(p);
      YAML::Emitter set_text;
      set_text << set_node;
      const ProblemSet set = load_problem_set_from_string(set_text.c_str(), e.path().string());
      const SolvedSet solved = solve_for_grading(set);
      for (const YAML::Node& c : problem["cases"]) {
        YAML::Node answers;
        answers["p"] = c["answers"];
        add_grade(out, grade_answers(set, solved, answers));
      }
    }
  }
  return out;
}

// Problems in the students' languages: what the instructor wrote for students in the
// seed, example and hard sets — titles, problem texts with their placeholders filled, statements
// and reasons quoted in steps — as a student reading each language sees it.
struct InstructorText {
  std::string where;
  std::map<Lang, std::string> shown;
};

inline std::vector<InstructorText> instructor_texts() {
  std::vector<InstructorText> out;
  const auto each = [](const auto& f) {
    std::map<Lang, std::string> m;
    for (const Lang lang : {Lang::En, Lang::Ja, Lang::Ru}) m[lang] = f(lang);
    return m;
  };
  for (const std::string& file : bundled_sets()) {
    const SetResult r = solve_set(load_problem_set(file), true);
    if (!r.title.empty())
      out.push_back({file + " title", each([&](Lang l) { return r.title.in(l); })});
    for (const ProblemResult& p : r.problems) {
      const std::string where = file + ": " + p.id;
      if (!p.text.empty())
        out.push_back({where + " text", each([&](Lang l) { return p.text.in(l); })});
      for (const Step& s : p.derivation.steps()) {
        out.push_back({where + " step", each([&](Lang l) { return s.title.in(l); })});
        if (!s.note.empty())
          out.push_back({where + " note", each([&](Lang l) { return s.note.in(l); })});
      }
    }
  }
  return out;
}

}  // namespace frustum::test

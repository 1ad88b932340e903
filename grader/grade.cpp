#include "grader/grade.hpp"

#include "grader/answer_parser.hpp"
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/solve_set.hpp"
#include "solver/kinds/yaml_document.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/util/suggest.hpp"

#include <algorithm>

namespace frustum {

namespace {

Submission load_submission_from(const YamlDocument& doc, const std::string& name) {
  Submission s;
  s.file = name;
  if (doc.error) {
    s.errors.push_back(*doc.error);
    return s;
  }
  if (doc.invalid_utf8) s.errors.push_back(*doc.invalid_utf8);
  const YAML::Node& root = doc.root;
  auto err = [&](const YAML::Node& n, const std::string& field, const std::string& message) {
    s.errors.push_back(Diagnostic{location_of(n, name), field, message});
  };
  if (root.IsNull() && root.Mark().line < 0) {
    s.errors.push_back(Diagnostic{SourceLocation{name, 1, 1}, "",
                                  "the file is empty: expected a mapping with 'student' and 'answers'"});
    return s;
  }
  if (!root.IsMap()) {
    err(root, "", "expected a mapping with 'student' and 'answers'");
    return s;
  }
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (k != "student" && k != "answers")
      err(it->first, k, "unknown field" + did_you_mean(k, {"student", "answers"}));
  }
  if (root["student"].IsDefined()) {
    if (root["student"].IsScalar()) s.student = root["student"].Scalar();
    else err(root["student"], "student", "expected the student's id");
  }
  const YAML::Node answers = root["answers"];
  if (!answers.IsDefined()) err(root, "answers", "missing required field");
  else if (!answers.IsMap()) err(answers, "answers", "expected a mapping of problem id → answers");
  else s.answers = answers;
  return s;
}

}  // namespace

Submission load_submission_from_string(const std::string& yaml, const std::string& name) {
  return load_submission_from(parse_yaml(yaml, name), name);
}

Submission load_submission(const std::string& path) {
  return load_submission_from(load_yaml_file(path), path);
}

namespace {

// Names the common mistake a wrong answer matches, with the step where it goes wrong.
std::optional<Misconception> diagnose(const ProblemSpec& spec, const std::vector<Misconception>& mistakes,
                                      const std::string& name, const Value& got) {
  const AnswerSpec& aspec = *spec.info->answer(name);
  for (const Misconception& m : mistakes) {
    const Value* v = m.answers.find(name);
    if (v && v->shape != Value::Shape::Null &&
        compare(*v, got, aspec, spec.tolerance_for(name), false).verdict == Verdict::Correct)
      return m;
  }
  return std::nullopt;
}

// The student's answers that `name` is recomputed from in error carried forward: along its
// dependencies, the nearest ones the student gave (a given plane supersedes the normal behind
// it for z). Carrying only these spares the kind recomputing what the answer does not need
// (a unit normal from a typed decimal normal is a square root of a large rational).
Answers carry_inputs(const KindInfo& kind, const std::string& name, const Answers& given) {
  Answers out;
  std::vector<std::string> todo = kind.answer(name)->depends_on;
  std::vector<std::string> seen;
  while (!todo.empty()) {
    const std::string d = todo.back();
    todo.pop_back();
    if (std::find(seen.begin(), seen.end(), d) != seen.end()) continue;
    seen.push_back(d);
    if (const Value* v = given.find(d)) {
      out.set(d, *v);
    } else if (const AnswerSpec* spec = kind.answer(d)) {
      todo.insert(todo.end(), spec->depends_on.begin(), spec->depends_on.end());
    }
  }
  return out;
}

ProblemGrade grade_problem(const ProblemSpec& spec, const ProblemResult& solved,
                           const std::vector<Misconception>* known_mistakes, const YAML::Node& student,
                           const std::string& answers_file, std::vector<Diagnostic>& errors) {
  ProblemGrade pg;
  pg.id = spec.id;
  pg.kind = spec.kind;
  pg.max_score = spec.max_score();
  if (solved.error) {
    pg.error = solved.error;
    return pg;
  }
  if (student.IsDefined() && !student.IsNull() && !student.IsMap()) {
    errors.push_back(Diagnostic{location_of(student, answers_file), "answers." + spec.id,
                                "expected a mapping of answer name → value"});
  }
  // Parse every answer first: later answers are judged against the student's earlier ones.
  Answers parsed_answers;
  std::vector<ParsedAnswer> parsed(spec.ask.size());
  for (std::size_t i = 0; i < spec.ask.size(); ++i) {
    const YAML::Node given = student.IsMap() ? student[spec.ask[i]] : YAML::Node();
    if (!given.IsDefined() || given.IsNull()) continue;
    parsed[i] = parse_answer(given, *spec.info->answer(spec.ask[i]));
    if (parsed[i].ok) parsed_answers.set(spec.ask[i], parsed[i].value);
  }
  std::optional<std::vector<Misconception>> own_mistakes;  // when the set was not solved once for all
  for (std::size_t i = 0; i < spec.ask.size(); ++i) {
    const std::string& name = spec.ask[i];
    const AnswerSpec& aspec = *spec.info->answer(name);
    AnswerGrade ag;
    ag.name = name;
    ag.max_score = spec.answer_points(name);
    ag.expected = *solved.answers.find(name);
    const YAML::Node given = student.IsMap() ? student[name] : YAML::Node();
    if (!given.IsDefined() || given.IsNull()) {
      ag.verdict = Verdict::Missing;
      ag.feedback = "no answer given";
    } else if (!parsed[i].ok) {
      ag.got_text = parsed[i].raw;
      ag.verdict = Verdict::Unparseable;
      ag.feedback = parsed[i].error;
    } else {
      ag.got_text = parsed[i].raw;
      ag.got = parsed[i].value;
      const Comparison c = compare(ag.expected, parsed[i].value, aspec, spec.tolerance_for(name), spec.grading.partial);
      ag.verdict = c.verdict;
      ag.score = c.credit * ag.max_score;
      ag.feedback = c.feedback;
      if (ag.verdict != Verdict::Correct && spec.info->misconceptions) {
        if (!known_mistakes && !own_mistakes) own_mistakes = spec.info->misconceptions(spec.given);
        if (const auto m = diagnose(spec, known_mistakes ? *known_mistakes : *own_mistakes, name, parsed[i].value)) {
          ag.misconception = m->name;
          ag.feedback = m->feedback + (ag.feedback.empty() ? "" : " (" + ag.feedback + ")");
          ag.wrong_step = m->step;
        }
      }
      // Error carried forward: right from the student's own wrong earlier answer.
      if (ag.verdict != Verdict::Correct && !aspec.depends_on.empty() && spec.info->carry_forward &&
          spec.grading.ecf > 0) {
        const Answers inputs = carry_inputs(*spec.info, name, parsed_answers);
        const Answers carried = inputs.items().empty() ? Answers{} : spec.info->carry_forward(spec.given, inputs);
        const Value* follow = carried.find(name);
        if (follow && compare(*follow, parsed[i].value, aspec, spec.tolerance_for(name), false).verdict ==
                          Verdict::Correct) {
          const double credit = spec.grading.ecf * ag.max_score;
          if (credit > ag.score) {
            ag.verdict = Verdict::Partial;
            ag.score = credit;
            ag.carried_forward = true;
            // Name the student's own wrong earlier answers it follows from (the kind's direct
            // dependency may be one the student was not asked: unit_normal behind normal).
            std::string from;
            for (const AnswerGrade& earlier : pg.answers)
              if (earlier.got && earlier.verdict != Verdict::Correct)
                from += (from.empty() ? "" : ", ") + earlier.name;
            if (from.empty())
              for (const std::string& d : aspec.depends_on) from += (from.empty() ? "" : ", ") + d;
            ag.feedback = "wrong, but it follows correctly from your own earlier " + from +
                          " (error carried forward: " + format_approx(spec.grading.ecf * 100, 3) + "% of the points)";
          }
        }
      }
    }
    if (!parsed[i].note.empty()) ag.feedback = parsed[i].note + (ag.feedback.empty() ? "" : "; " + ag.feedback);
    if (ag.verdict != Verdict::Correct) ag.derivation = solved.derivation.steps_for(name);
    pg.score += ag.score;
    pg.answers.push_back(std::move(ag));
  }
  if (student.IsMap()) {
    for (auto it = student.begin(); it != student.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      if (std::find(spec.ask.begin(), spec.ask.end(), k) == spec.ask.end())
        errors.push_back(Diagnostic{location_of(it->first, answers_file), "answers." + spec.id + "." + k,
                                    "not asked in this problem" + did_you_mean(k, spec.ask)});
    }
  }
  return pg;
}

}  // namespace

SolvedSet solve_for_grading(const ProblemSet& set) {
  SolvedSet s;
  for (const ProblemSpec& spec : set.problems) {
    s.results.push_back(solve_problem(spec, set.file, true));
    std::vector<Misconception> m;
    if (!s.results.back().error && spec.info && spec.info->misconceptions) {
      try {
        m = spec.info->misconceptions(spec.given);
      } catch (const std::exception&) {
      }
    }
    s.mistakes.push_back(std::move(m));
  }
  return s;
}

GradeReport grade(const ProblemSet& set, const Submission& submission, const SolvedSet* solved) {
  GradeReport r;
  r.set_file = set.file;
  r.answers_file = submission.file;
  r.student = submission.student;
  r.errors = set.errors;
  r.errors.insert(r.errors.end(), submission.errors.begin(), submission.errors.end());
  for (const ProblemSpec& spec : set.problems) {
    // A const lookup of a missing key gives an invalid node: every answer is then missing.
    const YAML::Node found = submission.answers.IsMap() ? submission.answers[spec.id] : YAML::Node();
    const YAML::Node student = found.IsDefined() ? found : YAML::Node();
    ProblemGrade pg;
    try {
      const std::size_t index = static_cast<std::size_t>(&spec - set.problems.data());
      if (solved && index < solved->results.size()) {
        pg = grade_problem(spec, solved->results[index], &solved->mistakes[index], student, submission.file, r.errors);
      } else {
        pg = grade_problem(spec, solve_problem(spec, set.file, true), nullptr, student, submission.file, r.errors);
      }
    } catch (const std::exception& e) {
      pg.id = spec.id;
      pg.max_score = spec.max_score();
      pg.error = Diagnostic{spec.where, spec.field, std::string("cannot grade: ") + e.what()};
    }
    r.score += pg.score;
    r.max_score += pg.max_score;
    r.problems.push_back(std::move(pg));
  }
  if (submission.answers.IsMap()) {
    std::vector<std::string> ids;
    for (const ProblemSpec& p : set.problems) ids.push_back(p.id);
    for (auto it = submission.answers.begin(); it != submission.answers.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      if (!set.find(k))
        r.errors.push_back(Diagnostic{location_of(it->first, submission.file), "answers." + k,
                                      "no problem with this id in " + set.file + did_you_mean(k, ids)});
    }
  }
  return r;
}

}  // namespace frustum

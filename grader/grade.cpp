#include "grader/grade.hpp"

#include <algorithm>
#include <optional>

#include "grader/answer_parser.hpp"
#include "grader/student_id.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/util/suggest.hpp"

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
    s.errors.push_back(
        Diagnostic{SourceLocation{name, 1, 1}, "",
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
    if (root["student"].IsScalar()) {
      StudentId id = read_student_id(root["student"].Scalar());
      if (id.problem)
        err(root["student"], "student", *id.problem);
      else
        s.student = std::move(id.id);
    } else
      err(root["student"], "student", "expected the student's id");
  }
  const YAML::Node answers = root["answers"];
  if (!answers.IsDefined())
    err(root, "answers", "missing required field");
  else if (!answers.IsMap())
    err(answers, "answers", "expected a mapping of problem id → answers");
  else
    s.answers = answers;
  return s;
}

}  // namespace

Submission load_submission_from_string(const std::string& yaml, const std::string& name) {
  return load_submission_from(parse_yaml(yaml, name, kMaxAnswerNodes), name);
}

Submission load_submission(const std::string& path) {
  return load_submission_from(load_yaml_file(path, kMaxAnswerNodes), path);
}

namespace {

constexpr Phrase kNoAnswerGiven{"no answer given", "解答がありません", "ответа нет"};
// How it was read, then what the comparison found.
constexpr Phrase kReadThen{"{0}; {1}", "{0}; {1}", "{0}; {1}"};
constexpr Phrase kInParentheses{"({0})", "({0})", "({0})"};
constexpr Phrase kAnd{"{0} and {1}", "{0} と {1}", "{0} и {1}"};
constexpr Phrase kOr{"{0} or {1}", "{0}または{1}", "{0} или {1}"};
constexpr Phrase kWhatTwoMistakesGive{
    "This is what a {0} or {1} gives; your other answers do not show which.",
    "これは「{0}」または「{1}」で生じる値です. 他の解答からはどちらかは分かりません.",
    "Так получается при ошибке «{0}» или «{1}»; по остальным ответам не видно, при какой."};
constexpr Phrase kWhatMistakesGive{
    "This is what a {0} gives; your other answers do not show which.",
    "これは「{0}」で生じる値です. 他の解答からはどれかは分かりません.",
    "Так получается при одной из ошибок: {0}; по остальным ответам не видно, при какой."};
constexpr Phrase kFollowsFromACopy{
    "It follows from your own {0}, which is copied from the given: nothing is carried forward "
    "from it.",
    "あなた自身の `{0}` から導かれていますが, それは与えられた値の写しなので, "
    "誤りの持ち越しはありません.",
    "Это следует из вашего `{0}`, но он скопирован из данных задачи: баллы с него не "
    "переносятся."};
constexpr Phrase kFollowsFromATrivialAnswer{
    "It follows from your own {0}, which is the {1} and takes no work: nothing is carried forward "
    "from it.",
    "あなた自身の `{0}` から導かれていますが, それは{1}で計算を要しないので, "
    "誤りの持ち越しはありません.",
    "Это следует из вашего `{0}`, но это {1} — ответ без вычислений: баллы с него не "
    "переносятся."};
constexpr Phrase kFollowsFromNoWork{
    "It follows from your own {0}, which is computed from an answer that takes no work: nothing "
    "is carried forward from it.",
    "あなた自身の `{0}` から導かれていますが, それは計算を要しない解答から求めたものなので, "
    "誤りの持ち越しはありません.",
    "Это следует из вашего `{0}`, но он получен из ответа, не требующего вычислений: баллы с него "
    "не переносятся."};
constexpr Phrase kRightForYourOwnOne{
    "right for your own {0}, which is also right (the key used another, equally right, choice)",
    "あなた自身の `{0}` に対して正しく, それも正しい (正解例は別の, 同じく正しい選び方をしている)",
    "верно для вашего `{0}`, который тоже верен (в ключе выбран другой, столь же верный вариант)"};
constexpr Phrase kRightForYourOwnSeveral{
    "right for your own {0}, which are also right (the key used another, equally right, choice)",
    "あなた自身の `{0}` に対して正しく, それらも正しい (正解例は別の, "
    "同じく正しい選び方をしている)",
    "верно для ваших `{0}`, которые тоже верны (в ключе выбран другой, столь же верный вариант)"};
constexpr Phrase kCarriedForward{
    "wrong, but it follows correctly from your own earlier {0} (error carried forward: {1} of the "
    "points)",
    "誤りですが, あなた自身の前の解答から正しく導かれています (`{0}`; 誤りの持ち越し: 配点の {1})",
    "неверно, но правильно следует из вашего предыдущего ответа `{0}` (перенос ошибки: {1} "
    "баллов)"};

bool all_zero_vector(const Value& v) {
  if (v.numbers.size() < 2) return false;
  for (const double x : v.numbers)
    if (x != 0) return false;
  return true;
}

// The student's answers that `name` is recomputed from in error carried forward: along its
// dependencies, the nearest ones the student gave (a given plane supersedes the normal behind
// it for z). Carrying only these spares the kind recomputing what the answer does not need
// (a unit normal from a typed decimal normal is a square root of a large rational).
template <typename Present>
std::vector<std::string> carry_inputs(const KindInfo& kind, const std::string& name,
                                      Present present) {
  std::vector<std::string> out;
  std::vector<std::string> todo = kind.answer(name)->depends_on;
  std::vector<std::string> seen;
  while (!todo.empty()) {
    const std::string d = todo.back();
    todo.pop_back();
    if (std::find(seen.begin(), seen.end(), d) != seen.end()) continue;
    seen.push_back(d);
    if (present(d)) {
      out.push_back(d);
    } else if (const AnswerSpec* spec = kind.answer(d)) {
      todo.insert(todo.end(), spec->depends_on.begin(), spec->depends_on.end());
    }
  }
  return out;
}

// "a, b and c" (`joiner`: kAnd or kOr), each item in the reader's language.
Said listed(const std::vector<Said>& items, const Phrase& joiner) {
  Said out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i == 0)
      out = items[i];
    else if (i + 1 == items.size())
      out = say(joiner, out, items[i]);
    else
      out.append(Said::verbatim(", ")).append(items[i]);
  }
  return out;
}

Said name_list(const std::vector<std::string>& names) {
  std::vector<Said> items;
  for (const std::string& n : names) items.push_back(Said::verbatim(n));
  return listed(items, kAnd);
}

// One problem's grading: the student's parsed answers, each graded in turn against the key,
// the named mistakes and the student's own earlier answers.
class ProblemGrader {
 public:
  ProblemGrader(const ProblemSpec& spec, const ProblemResult& solved,
                const std::vector<Misconception>& mistakes, const ProblemJudging& judging)
      : spec_(spec), solved_(solved), mistakes_(mistakes), judging_(judging) {}

  void parse(const YAML::Node& student) {
    parsed_.resize(spec_.ask.size());
    verdicts_.reserve(spec_.ask.size());
    for (std::size_t i = 0; i < spec_.ask.size(); ++i) {
      const YAML::Node given = student.IsMap() ? student[spec_.ask[i]] : YAML::Node();
      if (!given.IsDefined() || given.IsNull()) continue;
      parsed_[i] = parse_answer(given, *spec_.info->answer(spec_.ask[i]), spec_.conventions.angles);
      if (parsed_[i].ok) answers_.set(spec_.ask[i], parsed_[i].value);
    }
  }

  AnswerGrade grade(std::size_t i, const YAML::Node& student) {
    const std::string& name = spec_.ask[i];
    AnswerGrade ag;
    ag.name = name;
    whole_trivial_ = false;
    ag.max_score = spec_.answer_points(name);
    ag.expected = *solved_.answers.find(name);
    const YAML::Node given = student.IsMap() ? student[name] : YAML::Node();
    if (!given.IsDefined() || given.IsNull()) {
      ag.verdict = Verdict::Missing;
      ag.feedback = Said(kNoAnswerGiven);
    } else if (!parsed_[i].ok) {
      ag.got_text = parsed_[i].raw;
      ag.verdict = Verdict::Unparseable;
      ag.feedback = parsed_[i].error;
    } else {
      ag.got_text = parsed_[i].raw;
      ag.got = parsed_[i].value;
      judge(ag);
    }
    if (parsed_[i].ok && !parsed_[i].note.empty())
      ag.feedback =
          ag.feedback.empty() ? parsed_[i].note : say(kReadThen, parsed_[i].note, ag.feedback);
    verdicts_.emplace_back(name, ag.verdict);
    // A trivial answer (zero, a given copied back, the identity…) carries nothing forward, and
    // neither does a wrong answer computed from one, unless it earned carried credit of its own
    // from another, worked earlier answer.
    if (ag.got && ag.verdict != Verdict::Correct) {
      if (whole_trivial_ || all_zero_vector(*ag.got)) {
        trivial_.push_back(name);
        whole_.emplace_back(name, whole_trivial_ && !ag.misconception.empty()
                                      ? ag.misconception
                                      : Said(kZeroVectorAnswer));
      } else if (!ag.carried_forward && !trivial_inputs(name).empty()) {
        trivial_.push_back(name);
      }
    }
    if (ag.verdict != Verdict::Correct) ag.derivation = solved_.derivation.steps_for(name);
    return ag;
  }

 private:
  AnswerRules rules(const std::string& name, bool credit) const {
    AnswerRules r = judging_.rules(spec_, name);
    if (!credit) r.partial = false;
    return r;
  }

  // The student's earlier answers `name` is computed from that are trivial.
  std::vector<std::string> trivial_inputs(const std::string& name) const {
    std::vector<std::string> out;
    for (const std::string& d :
         carry_inputs(*spec_.info, name, [&](const std::string& n) { return answers_.find(n); }))
      if (d != name && is_trivial(d)) out.push_back(d);
    return out;
  }

  bool is_trivial(const std::string& name) const {
    if (std::find(trivial_.begin(), trivial_.end(), name) != trivial_.end()) return true;
    const Value* v = answers_.find(name);
    return v && all_zero_vector(*v) && verdict_of(name) != Verdict::Correct;
  }

  std::optional<Verdict> verdict_of(const std::string& name) const {
    for (const auto& [n, v] : verdicts_)
      if (n == name) return v;
    return std::nullopt;
  }

  void judge(AnswerGrade& ag) {
    const std::string& name = ag.name;
    Comparison c = compare(ag.expected, *ag.got, rules(name, true));
    // Another choice the method leaves open (the view vector from another vertex): right too.
    if (c.verdict != Verdict::Correct)
      for (const AlsoRight& a : judging_.also_right)
        if (a.answer == name &&
            compare(a.value, *ag.got, rules(name, false)).verdict == Verdict::Correct) {
          c = Comparison{Verdict::Correct, 1.0, a.why, {}, false, {}};
          break;
        }
    ag.verdict = c.verdict;
    ag.score = c.credit * ag.max_score;
    ag.feedback = c.feedback;
    whole_trivial_ = c.no_work && ag.verdict != Verdict::Correct;
    if (!c.trivial.empty()) ag.misconception = c.trivial;
    if (ag.verdict == Verdict::Correct) return;
    if (!c.mistake.empty()) ag.misconception = c.mistake;
    if (c.trivial.empty()) diagnose(ag);
    // A named mistake as a whole earns no component credit: it is what the question tests.
    if (!ag.misconception.empty() && ag.verdict == Verdict::Partial) {
      ag.verdict = Verdict::Incorrect;
      ag.score = 0;
    }
    // A trivial answer as a whole is named as such and never "follows" from anything.
    if (!whole_trivial_) carry_forward(ag);
  }

  // Names the common mistake the answer matches, when it is true of the student's own answers:
  // every other answer the mistake changes that the student gave must be what it gives.
  void diagnose(AnswerGrade& ag) {
    std::vector<const Misconception*> fits;
    for (const Misconception& m : mistakes_) {
      const Value* v = m.answers.find(ag.name);
      if (!v || v->shape == Value::Shape::Null) continue;
      if (compare(*v, *ag.got, rules(ag.name, false)).verdict != Verdict::Correct) continue;
      bool agrees = true;
      for (const auto& [other, value] : m.answers.items()) {
        const Value* theirs = other == ag.name ? nullptr : answers_.find(other);
        if (theirs && value.shape != Value::Shape::Null &&
            compare(value, *theirs, rules(other, false)).verdict != Verdict::Correct)
          agrees = false;
      }
      if (agrees && std::none_of(fits.begin(), fits.end(),
                                 [&](const Misconception* f) { return f->name == m.name; }))
        fits.push_back(&m);
    }
    if (fits.size() == 1) {
      ag.misconception = fits[0]->name;
      ag.wrong_step = fits[0]->step;
      // Said in the form the student wrote (an equation, not the list it would explain).
      Said said = fits[0]->feedback;
      for (const auto& [form, feedback] : fits[0]->feedback_by_form)
        if (form == form_of(ag.name)) said = feedback;
      ag.feedback = ag.feedback.empty() ? said : said + say(kInParentheses, ag.feedback);
    } else if (fits.size() > 1) {
      std::vector<Said> names;
      for (const Misconception* f : fits) names.push_back(f->name);
      const Said which = names.size() == 2 ? say(kWhatTwoMistakesGive, names[0], names[1])
                                           : say(kWhatMistakesGive, listed(names, kOr));
      ag.feedback = ag.feedback.empty() ? which : which + say(kInParentheses, ag.feedback);
    }
  }

  // The form the student wrote an answer in (ParsedAnswer::form).
  const std::string& form_of(const std::string& name) const {
    static const std::string none;
    for (std::size_t i = 0; i < spec_.ask.size() && i < parsed_.size(); ++i)
      if (spec_.ask[i] == name) return parsed_[i].form;
    return none;
  }

  // Is the answer what the kind recomputes from these earlier answers of the student's?
  bool follows(const AnswerGrade& ag, Answers inputs) const {
    // The answer itself too: where the method allows choices (the plane through any vertex),
    // the kind recomputes the one the student made.
    inputs.set(ag.name, *ag.got);
    const Answers carried = spec_.info->carry_forward(spec_.given, inputs);
    const Value* follow = carried.find(ag.name);
    return follow && compare(*follow, *ag.got, rules(ag.name, false)).verdict == Verdict::Correct;
  }

  // A wrong answer that follows from trivial earlier answers is told why it earns nothing.
  void say_trivial_inputs(AnswerGrade& ag) const {
    const std::vector<std::string> used = trivial_inputs(ag.name);
    if (used.empty()) return;
    Answers inputs;
    for (const std::string& n : carry_inputs(*spec_.info, ag.name, [&](const std::string& d) {
           return d != ag.name && answers_.find(d);
         }))
      inputs.set(n, *answers_.find(n));
    if (!follows(ag, inputs)) return;
    // One sentence per input, saying what it is (a copy of the given, the zero vector…): never
    // a mistake the student did not make. Each is translated whole.
    for (const std::string& n : used) {
      const auto whole =
          std::find_if(whole_.begin(), whole_.end(), [&](const auto& w) { return w.first == n; });
      const Said why = whole == whole_.end() ? say(kFollowsFromNoWork, n)
                       : whole->second == Said(kCopiedFromTheGiven)
                           ? say(kFollowsFromACopy, n)
                           : say(kFollowsFromATrivialAnswer, n, whole->second);
      if (!ag.feedback.empty() && !ag.feedback.en().ends_with('.'))
        ag.feedback.append(Said::verbatim("."));
      ag.feedback += why;
    }
  }

  // Error carried forward: right from the student's own earlier answers. When every earlier
  // answer it was recomputed from is itself right (a normal scaled by 2), so is this one.
  void carry_forward(AnswerGrade& ag) {
    const AnswerSpec& aspec = *spec_.info->answer(ag.name);
    if (aspec.depends_on.empty() || !spec_.info->carry_forward || spec_.grading.ecf <= 0) return;
    Answers inputs;
    for (const std::string& n : carry_inputs(*spec_.info, ag.name, [&](const std::string& d) {
           return d != ag.name && answers_.find(d) && !is_trivial(d);
         }))
      inputs.set(n, *answers_.find(n));
    if (inputs.items().empty() || !follows(ag, inputs)) {
      say_trivial_inputs(ag);
      return;
    }
    std::vector<std::string> wrong, right;
    for (const auto& [n, v] : inputs.items())
      (verdict_of(n) == Verdict::Correct ? right : wrong).push_back(n);
    if (wrong.empty()) {
      ag.verdict = Verdict::Correct;
      ag.score = ag.max_score;
      ag.misconception = {};
      ag.wrong_step = {};
      ag.feedback =
          say(right.size() == 1 ? kRightForYourOwnOne : kRightForYourOwnSeveral, name_list(right));
      return;
    }
    const double credit = spec_.grading.ecf * ag.max_score;
    if (credit <= ag.score) return;
    ag.verdict = Verdict::Partial;
    ag.score = credit;
    ag.carried_forward = true;
    ag.feedback =
        say(kCarriedForward, name_list(wrong), format_approx(spec_.grading.ecf * 100, 3) + "%");
  }

  const ProblemSpec& spec_;
  const ProblemResult& solved_;
  const std::vector<Misconception>& mistakes_;
  const ProblemJudging& judging_;
  std::vector<ParsedAnswer> parsed_;
  Answers answers_;                                        // the parsed ones, by name
  std::vector<std::pair<std::string, Verdict>> verdicts_;  // graded so far
  std::vector<std::string> trivial_;  // trivial answers, and wrong ones computed from them
  // Those of them that are trivial answers themselves, with what each is ("zero vector").
  std::vector<std::pair<std::string, Said>> whole_;
  bool whole_trivial_ = false;  // the answer being judged is a trivial answer as a whole
};

ProblemGrade grade_problem(const ProblemSpec& spec, const ProblemResult& solved,
                           const std::vector<Misconception>& mistakes,
                           const ProblemJudging& judging, const YAML::Node& student,
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
  ProblemGrader grader(spec, solved, mistakes, judging);
  grader.parse(student);
  pg.answers.reserve(spec.ask.size());
  for (std::size_t i = 0; i < spec.ask.size(); ++i) {
    AnswerGrade ag = grader.grade(i, student);
    pg.score += ag.score;
    pg.answers.push_back(std::move(ag));
  }
  if (student.IsMap()) {
    for (auto it = student.begin(); it != student.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      if (std::find(spec.ask.begin(), spec.ask.end(), k) == spec.ask.end())
        errors.push_back(Diagnostic{location_of(it->first, answers_file),
                                    "answers." + spec.id + "." + k,
                                    "not asked in this problem" + did_you_mean(k, spec.ask)});
    }
  }
  return pg;
}

std::vector<Misconception> mistakes_of(const ProblemSpec& spec, const ProblemResult& solved) {
  if (solved.error || !spec.info || !spec.info->misconceptions) return {};
  try {
    return spec.info->misconceptions(spec.given);
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace

AnswerRules ProblemJudging::rules(const ProblemSpec& spec, const std::string& name) const {
  AnswerRules r;
  r.spec = spec.info->answer(name);
  r.tol = spec.tolerance_for(name);
  r.partial = spec.grading.partial;
  r.linear_matrix = spec.grading.linear_matrix;
  for (const auto& [n, s] : scales)
    if (n == name) r.scale = &s;
  for (const auto& [n, t] : trivial)
    if (n == name) r.trivial = &t;
  return r;
}

ProblemJudging prepare_judging(const ProblemSpec& spec, const Answers& key) {
  ProblemJudging j;
  if (!spec.info) return j;
  if (spec.info->scales) {
    try {
      j.scales = spec.info->scales(spec.given, key);
    } catch (const std::exception&) {
      j.scales.clear();  // the defaults judge every answer
    }
  }
  if (spec.info->also_right) {
    try {
      j.also_right = spec.info->also_right(spec.given);
    } catch (const std::exception&) {
      j.also_right.clear();  // the key alone is right
    }
  }
  std::optional<std::vector<GivenList>> given;
  for (const std::string& name : spec.ask) {
    const Value* v = key.find(name);
    const AnswerSpec* a = spec.info->answer(name);
    if (!v || !a || v->numbers.size() < 2) continue;
    if (!given) given = given_lists(spec.given_node);
    j.trivial.emplace_back(name, trivial_answers(*v, a->kind, *given, spec.conventions.api));
  }
  return j;
}

SolvedSet solve_for_grading(const ProblemSet& set) {
  SolvedSet s;
  for (const ProblemSpec& spec : set.problems) {
    s.results.push_back(solve_problem(spec, set.file, true));
    // Each key as students see it, formatted once for the class rather than on every page.
    Answers keys;
    for (const auto& [name, value] : s.results.back().answers.items()) {
      Value key = value;
      if (key.display.empty()) key.display = value.shown();
      keys.set(name, std::move(key));
    }
    s.results.back().answers = std::move(keys);
    s.mistakes.push_back(mistakes_of(spec, s.results.back()));
    s.judging.push_back(s.results.back().error ? ProblemJudging{}
                                               : prepare_judging(spec, s.results.back().answers));
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
    const YAML::Node found =
        submission.answers.IsMap() ? submission.answers[spec.id] : YAML::Node();
    const YAML::Node student = found.IsDefined() ? found : YAML::Node();
    ProblemGrade pg;
    try {
      const std::size_t index = static_cast<std::size_t>(&spec - set.problems.data());
      if (solved && index < solved->results.size()) {
        pg = grade_problem(spec, solved->results[index], solved->mistakes[index],
                           solved->judging[index], student, submission.file, r.errors);
      } else {
        const ProblemResult result = solve_problem(spec, set.file, true);
        const ProblemJudging judging =
            result.error ? ProblemJudging{} : prepare_judging(spec, result.answers);
        pg = grade_problem(spec, result, mistakes_of(spec, result), judging, student,
                           submission.file, r.errors);
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
        r.errors.push_back(
            Diagnostic{location_of(it->first, submission.file), "answers." + k,
                       "no problem with this id in " + set.file + did_you_mean(k, ids)});
    }
  }
  return r;
}

}  // namespace frustum

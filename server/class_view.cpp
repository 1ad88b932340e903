#include "server/class_view.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

namespace frustum::server {

namespace {

double median(std::vector<int> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

void count_verdict(AnswerCount& c, const std::string& verdict) {
  if (verdict == "correct")
    ++c.right;
  else if (verdict == "partial")
    ++c.partly;
  else if (verdict == "unparseable")
    ++c.unreadable;
  else
    ++c.wrong;
}

// A problem's verdict from its answers': right when every answer is, unreadable when none
// scored and one could not be read, partly right when some credit, else wrong.
std::string problem_verdict(const GradeRecord& g, const std::map<std::string, std::string>& v) {
  const bool all_right =
      std::all_of(v.begin(), v.end(), [](const auto& a) { return a.second == "correct"; });
  if (!v.empty() && all_right && g.score >= g.max_score) return "correct";
  if (g.score > 0) return "partial";
  for (const auto& [name, verdict] : v)
    if (verdict == "unparseable") return "unparseable";
  return "incorrect";
}

}  // namespace

const SubmissionRecord* ClassView::latest(const std::string& student,
                                          const std::string& problem) const {
  for (auto it = submissions.rbegin(); it != submissions.rend(); ++it)
    if (it->student == student && it->problem == problem) return &*it;
  return nullptr;
}

const GradeRecord* ClassView::graded(const SubmissionRecord& s) const {
  const auto it = grades.find(s.id);
  return it == grades.end() || it->second.failed ? nullptr : &it->second;
}

ClassView read_class(Store& store, const CourseSet& set) {
  ClassView view;
  view.set = &set;
  view.submissions = store.set_submissions(set.id, kMaxClassSubmissions + 1);
  if (view.submissions.size() > kMaxClassSubmissions) {
    view.truncated = true;
    view.submissions.resize(kMaxClassSubmissions);
  }
  for (GradeRecord& g : store.latest_grades(set.id)) view.grades[g.submission] = std::move(g);
  return view;
}

std::map<std::string, std::string> answer_verdicts(const GradeRecord& grade) {
  std::map<std::string, std::string> out;
  const nlohmann::json result = nlohmann::json::parse(grade.result, nullptr, false);
  if (!result.is_object() || !result.contains("answers") || !result["answers"].is_array())
    return out;
  for (const auto& a : result["answers"])
    if (a.is_object() && a.value("name", "") != "") out[a["name"]] = a.value("verdict", "");
  return out;
}

std::vector<AnswerCount> answer_counts(const ClassView& view) {
  // Latest submission and attempts of each (problem, student), in one pass.
  std::map<std::pair<std::string, std::string>, std::pair<const SubmissionRecord*, int>> last;
  for (const SubmissionRecord& s : view.submissions) {
    auto& [latest, attempts] = last[{s.problem, s.student}];
    latest = &s;
    ++attempts;
  }
  std::vector<AnswerCount> out;
  for (const ProblemSpec& p : view.set->set.problems) {
    AnswerCount problem{p.id, ""};
    std::map<std::string, AnswerCount> answers;
    std::map<std::string, std::vector<int>> answer_attempts;
    std::vector<int> attempts;
    for (auto it = last.lower_bound({p.id, ""}); it != last.end() && it->first.first == p.id;
         ++it) {
      const SubmissionRecord& s = *it->second.first;
      ++problem.submitted;
      attempts.push_back(it->second.second);
      const GradeRecord* g = view.graded(s);
      if (!g) continue;
      const std::map<std::string, std::string> verdicts = answer_verdicts(*g);
      count_verdict(problem, problem_verdict(*g, verdicts));
      for (const auto& [name, verdict] : verdicts) {
        if (verdict == "missing") continue;
        AnswerCount& a = answers[name];
        ++a.submitted;
        count_verdict(a, verdict);
        answer_attempts[name].push_back(it->second.second);
      }
    }
    problem.median_attempts = median(attempts);
    out.push_back(problem);
    for (const std::string& name : p.ask) {
      AnswerCount a = answers[name];
      a.problem = p.id;
      a.answer = name;
      a.median_attempts = median(answer_attempts[name]);
      out.push_back(a);
    }
  }
  return out;
}

std::vector<MistakeRow> frequent_mistakes(const ClassView& view, std::size_t limit) {
  std::map<std::tuple<std::string, std::string, std::string>, std::set<std::string>> made;
  std::set<std::pair<std::string, std::string>> seen;  // (problem, student): latest only
  for (auto it = view.submissions.rbegin(); it != view.submissions.rend(); ++it) {
    if (!seen.insert({it->problem, it->student}).second) continue;
    const GradeRecord* g = view.graded(*it);
    if (!g) continue;
    const nlohmann::json result = nlohmann::json::parse(g->result, nullptr, false);
    if (!result.is_object() || !result.contains("answers") || !result["answers"].is_array())
      continue;
    for (const auto& a : result["answers"]) {
      const std::string mistake = a.is_object() ? a.value("mistake", "") : "";
      if (!mistake.empty()) made[{it->problem, a.value("name", ""), mistake}].insert(it->student);
    }
  }
  std::vector<MistakeRow> out;
  for (const auto& [key, students] : made)
    out.push_back(MistakeRow{std::get<0>(key), std::get<1>(key), std::get<2>(key),
                             std::vector<std::string>(students.begin(), students.end())});
  std::stable_sort(out.begin(), out.end(), [](const MistakeRow& a, const MistakeRow& b) {
    return a.students.size() > b.students.size();
  });
  if (out.size() > limit) out.resize(limit);
  return out;
}

std::vector<BatchRow> gradebook_rows(const Course& course, const ClassView& view) {
  std::vector<BatchRow> rows;
  const std::vector<ProblemSpec>& problems = view.set->set.problems;
  std::map<std::pair<std::string, std::string>, std::vector<const SubmissionRecord*>> by;
  for (const SubmissionRecord& s : view.submissions) by[{s.student, s.problem}].push_back(&s);
  for (const std::string& student : course.roster) {
    if (!view.set->for_student(student)) continue;
    BatchRow row;
    row.student = student;
    bool any = false, pending = false;
    for (std::size_t i = 0; i < problems.size(); ++i) {
      row.max_score += problems[i].max_score();
      double score = 0;
      // The latest graded submission counts; a later one still being graded is pending.
      const auto mine = by.find({student, problems[i].id});
      if (mine != by.end())
        for (auto it = mine->second.rbegin(); it != mine->second.rend(); ++it) {
          any = true;
          if (const GradeRecord* g = view.graded(**it)) {
            score = g->score * view.set->policy.credit_factor((*it)->attempt);
            break;
          }
          if (!view.grades.count((*it)->id)) pending = true;
        }
      row.problem_scores.push_back(score);
      row.score += score;
    }
    row.status = !any ? "error" : pending ? "pending" : "graded";
    if (!any) {
      row.message = "no submission";
      row.problem_scores.clear();
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace frustum::server

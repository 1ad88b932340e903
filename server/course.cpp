#include "server/course.hpp"

#include <algorithm>
#include <filesystem>

#include "server/tokens.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/variants.hpp"

namespace frustum::server {

namespace fs = std::filesystem;

bool set_id_ok(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '-' || c == '_';
  });
}

std::optional<CourseSet> load_course_set(const std::string& file,
                                         const std::vector<std::string>& roster,
                                         std::vector<Diagnostic>& errors) {
  const fs::path path(file);
  CourseSet s;
  s.id = path.stem().string();
  s.file = path.string();
  if (!set_id_ok(s.id)) {
    errors.push_back(Diagnostic{SourceLocation{s.file, 0, 0}, "",
                                "a served set's file name may hold only letters, digits, "
                                "- and _ (it is part of the set's address)"});
    return std::nullopt;
  }
  std::string bytes;
  if (const auto error = read_text_file(s.file, kMaxYamlFileBytes, bytes)) {
    errors.push_back(*error);
    return std::nullopt;
  }
  s.version = sha256_hex(bytes);
  const YamlDocument doc = parse_yaml(bytes, s.file);
  s.set = load_problem_set(doc, s.file);
  const std::vector<Diagnostic> set_errors = s.set.all_errors();
  if (!set_errors.empty()) {
    errors.insert(errors.end(), set_errors.begin(), set_errors.end());
    return std::nullopt;
  }
  s.policy = read_serve_policy(doc.root, s.file);
  // An extension for someone not on the roster is a typo that would leave the student meant
  // without it: the set is not served until it is fixed.
  bool unknown = false;
  const YAML::Node extensions = doc.root["extensions"];
  if (extensions.IsDefined() && extensions.IsMap())
    for (auto it = extensions.begin(); it != extensions.end(); ++it)
      if (std::find(roster.begin(), roster.end(), it->first.Scalar()) == roster.end()) {
        errors.push_back(
            Diagnostic{location_of(it->first, s.file), "extensions." + it->first.Scalar(),
                       "'" + it->first.Scalar() + "' is not on the roster (roster.csv)"});
        unknown = true;
      }
  if (unknown) return std::nullopt;
  if (set_varies(s.set)) {
    const std::vector<ProblemSet> drawn = variants_for_class(s.set, roster, false);
    for (std::size_t i = 0; i < roster.size(); ++i) {
      const std::vector<Diagnostic> e = drawn[i].all_errors();
      errors.insert(errors.end(), e.begin(), e.end());
      s.variants.emplace(roster[i], drawn[i]);
    }
  }
  return s;
}

const ProblemSet* CourseSet::for_student(const std::string& student) const {
  if (variants.empty()) return &set;
  const auto it = variants.find(student);
  return it == variants.end() ? nullptr : &it->second;
}

std::string CourseSet::variant_id(const std::string& student) const {
  const ProblemSet* v = for_student(student);
  if (!v || !v->variant) return "";
  return "student:" + v->variant->student +
         (v->variant->draw > 1 ? "#" + std::to_string(v->variant->draw) : "");
}

const CourseSet* Course::find(const std::string& id) const {
  for (const CourseSet& s : sets)
    if (s.id == id) return &s;
  return nullptr;
}

bool Course::enrolled(const std::string& student) const {
  return std::find(roster.begin(), roster.end(), student) != roster.end();
}

bool Course::instructs(const std::string& id) const {
  return std::find(instructors.begin(), instructors.end(), id) != instructors.end();
}

Course load_course(const std::string& dir, const std::vector<std::string>& roster) {
  Course course;
  course.dir = dir;
  course.roster = roster;
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files)
    if (auto s = load_course_set(f.string(), roster, course.errors))
      course.sets.push_back(std::move(*s));
  return course;
}

}  // namespace frustum::server

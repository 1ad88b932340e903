#include "solver/input/text_reader.hpp"

#include "solver/input/given_reader.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

[[noreturn]] void fail_at(const YAML::Node& n, const std::string& file, const std::string& field,
                          const std::string& message) {
  throw InputError(Diagnostic{location_of(n, file), field, message});
}

std::string one_text(const YAML::Node& n, const std::string& file, const std::string& field,
                     std::size_t max_bytes) {
  if (!n.IsScalar()) fail_at(n, file, field, "expected text");
  if (max_bytes > 0 && n.Scalar().size() > max_bytes)
    fail_at(n, file, field, "longer than " + std::to_string(max_bytes) + " bytes");
  return n.Scalar();
}

}  // namespace

LocalText read_local_text(const YAML::Node& n, const std::string& file, const std::string& field,
                          Lang own, std::size_t max_bytes) {
  LocalText out;
  out.lang = own;
  if (!n.IsMap()) {
    if (!n.IsScalar())
      fail_at(n, file, field, "expected text, or a mapping by language like {en: …, ja: …, ru: …}");
    out.text = one_text(n, file, field, max_bytes);
    return out;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string code = it->first.IsScalar() ? it->first.Scalar() : "";
    const std::optional<Lang> lang = parse_lang(code);
    if (!lang)
      fail_at(it->first, file, field + "." + code,
              "'" + code + "' is not a language of Frustum (en, ja, ru)");
    std::string text = one_text(it->second, file, field + "." + code, max_bytes);
    if (*lang == own)
      out.text = std::move(text);
    else
      out.translations[*lang] = std::move(text);
  }
  if (!n[std::string(to_string(own))].IsDefined())
    fail_at(n, file, field + "." + std::string(to_string(own)),
            "missing: the text in the set's own language (lang: " + std::string(to_string(own)) +
                "), which readers of other languages fall back to");
  return out;
}

YAML::Node local_text_node(const YAML::Node& n, Lang lang, Lang own) {
  if (!n.IsDefined() || !n.IsMap()) return n;
  const YAML::Node chosen = n[std::string(to_string(lang))];
  return chosen.IsDefined() ? chosen : n[std::string(to_string(own))];
}

}  // namespace frustum

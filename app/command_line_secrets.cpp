#include "app/command_line_secrets.hpp"

#include <cstring>

namespace frustum::app {

SecretSpan password_in(std::string_view arg) {
  // A URL's user information: scheme://user:PASSWORD@host…
  if (const std::size_t scheme = arg.find("://"); scheme != std::string_view::npos) {
    const std::size_t start = scheme + 3;
    const std::size_t end = std::min(arg.find_first_of("/?#", start), arg.size());
    const std::string_view authority = arg.substr(start, end - start);
    const std::size_t at = authority.rfind('@');
    if (at != std::string_view::npos) {
      const std::size_t colon = authority.substr(0, at).find(':');
      if (colon != std::string_view::npos && at > colon + 1)
        return {start + colon + 1, at - colon - 1};
    }
  }
  // A libpq key/value string, or a URL parameter: password=PASSWORD
  constexpr std::string_view kKey = "password=";
  for (std::size_t at = arg.find(kKey); at != std::string_view::npos; at = arg.find(kKey, at + 1)) {
    if (at > 0 && arg[at - 1] != ' ' && arg[at - 1] != '?' && arg[at - 1] != '&') continue;
    const std::size_t start = at + kKey.size();
    const std::size_t end = std::min(arg.find_first_of(" &", start), arg.size());
    if (end > start) return {start, end - start};
  }
  return {};
}

void hide_passwords(int argc, char** argv, std::ostream& err) {
  bool found = false;
  for (int i = 1; i < argc; ++i) {
    const SecretSpan s = password_in(argv[i]);
    if (s.length == 0) continue;
    std::memset(argv[i] + s.offset, 'x', s.length);
    found = true;
  }
  if (found)
    err << "warning: a password on the command line is readable by other users of this machine "
           "while the command starts; give it in PGPASSWORD, ~/.pgpass or FRUSTUM_DB instead\n";
}

}  // namespace frustum::app

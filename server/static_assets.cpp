#include "server/static_assets.hpp"

#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "solver/derivation/formats.hpp"

namespace frustum::server {

namespace {

constexpr const char* kCodeMirrorDir = "/usr/share/javascript/codemirror";

struct Asset {
  const char* name;
  const char* text;
};

#define FRUSTUM_ASSET(name, text) Asset{name, text},
constexpr Asset kAssets[] = {
#include "server_assets.inc"
};
#undef FRUSTUM_ASSET

std::string content_type(const std::string& path) {
  const auto ends = [&](const char* e) {
    const std::string s(e);
    return path.size() >= s.size() && path.compare(path.size() - s.size(), s.size(), s) == 0;
  };
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  if (ends(".woff2")) return "font/woff2";
  return "application/octet-stream";
}

// KaTeX's files, read once on first use (immutable afterwards).
const std::map<std::string, std::string>& katex() {
  static const std::map<std::string, std::string> files = [] {
    std::map<std::string, std::string> out;
    for (auto& [path, bytes] : katex_files()) out.emplace(path, std::move(bytes));
    return out;
  }();
  return files;
}

// CodeMirror 5 from Debian's libjs-codemirror: the editor and its YAML mode, read once.
const std::map<std::string, std::string>& codemirror() {
  static const std::map<std::string, std::string> files = [] {
    std::map<std::string, std::string> out;
    for (const char* name : {"lib/codemirror.js", "lib/codemirror.css", "mode/yaml/yaml.js"}) {
      std::ifstream in(std::string(kCodeMirrorDir) + "/" + name, std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      if (in) out.emplace(name, bytes.str());
    }
    return out;
  }();
  return files;
}

Response file_response(const std::string& path, const std::string& bytes) {
  return Response{200,
                  {{"Content-Type", content_type(path)}, {"Cache-Control", "public, max-age=3600"}},
                  bytes};
}

}  // namespace

std::optional<Response> static_asset(const std::string& path) {
  for (const Asset& a : kAssets)
    if (path == a.name) return file_response(path, a.text);
  constexpr std::string_view kKatex = "katex/";
  if (path.rfind(kKatex, 0) == 0) {
    const auto it = katex().find(path.substr(kKatex.size()));
    if (it != katex().end()) return file_response(path, it->second);
  }
  constexpr std::string_view kCodeMirror = "codemirror/";
  if (path.rfind(kCodeMirror, 0) == 0) {
    const auto it = codemirror().find(path.substr(kCodeMirror.size()));
    if (it != codemirror().end()) return file_response(path, it->second);
  }
  return std::nullopt;
}

}  // namespace frustum::server

// libFuzzer target: a problem set from arbitrary bytes is loaded, solved with derivations and
// rendered in every format. The library promises never to throw, crash or hang on any input.
#include <cstddef>
#include <cstdint>
#include <string>

#include "solver/derivation/formats.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/solve_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const frustum::ProblemSet set = frustum::load_problem_set_from_string(text, "fuzz.yaml");
  for (const frustum::Diagnostic& d : set.all_errors()) (void)d.format();
  const frustum::SetResult result = frustum::solve_set(set, true);
  (void)frustum::render_text(result, frustum::TextStyle{});
  (void)frustum::render_markdown(result);
  (void)frustum::json_text(frustum::render_json(result));
  return 0;
}

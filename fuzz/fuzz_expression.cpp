// libFuzzer target: the answer-expression parser on arbitrary bytes, as a number and as a
// plane equation in x, y, z; a parsed value is also evaluated to a double.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "solver/core/exact.hpp"
#include "solver/util/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const frustum::ExpressionResult number = frustum::parse_expression(text);
  if (number) {
    const frustum::Exact e = frustum::canonical(*number.value);
    if (frustum::is_real_constant(e)) (void)frustum::to_double(e);
  }
  frustum::ExpressionOptions plane;
  for (const char* name : {"x", "y", "z"}) plane.symbols.emplace(name, GiNaC::symbol(name));
  plane.allow_equation = true;
  (void)frustum::parse_expression(text, plane);
  return 0;
}

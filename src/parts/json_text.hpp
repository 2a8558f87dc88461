// Checks on JSON text shared by the readers (pair files, space files), before the parser
// sees it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cslice::detail {

// Deepest bracket nesting the readers accept. Valid pair files nest five deep and space
// files seven; far deeper input would cost the parser memory and time, and overflow the
// stack wherever a value is dumped or compared (nlohmann recurses once per level).
inline constexpr int kMaxJsonNesting = 32;

// "line L, column C" of a byte offset in the text (both from 1).
std::string line_column_at(std::string_view text, size_t offset);

// The reason, in the readers' words ("invalid JSON at line L, column C: nested deeper than
// 32 levels"), when a bracket outside strings opens deeper than kMaxJsonNesting.
std::optional<std::string> json_nesting_error(std::string_view text);

}  // namespace cslice::detail

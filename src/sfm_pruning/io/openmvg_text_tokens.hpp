// Text scanning shared by the OpenMVG text readers (.feat, matches .txt, pair lists): whitespace
// splitting with line numbers, and strict number parsing so that a garbage token becomes an Error
// naming the file and line instead of a silent zero.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace sfm_pruning::openmvg_text {

// Splits on spaces, tabs and '\r' (so CRLF files read like LF files).
std::vector<std::string_view> SplitWhitespace(std::string_view line);

// Calls `visit(line, line_number)` for every line of `text`, 1-based; a final line without '\n'
// is visited too, an empty tail after the last '\n' is not.
void ForEachLine(std::string_view text, const std::function<void(std::string_view, size_t)>& visit);

// Whole-token parses; false on any trailing character, sign, overflow or empty token.
bool ParseUInt32(std::string_view token, uint32_t* value);
bool ParseUInt64(std::string_view token, uint64_t* value);
bool ParseFloat(std::string_view token, float* value);

// Formats a float the way an iostream with default precision does (%g, 6 significant digits)
// whenever that reads back to the same float, so files from OpenMVG are rewritten byte for byte;
// otherwise uses the fewest extra digits (up to 9) that make the value round-trip exactly.
std::string FormatFloat(float value);

// Reads whitespace-separated tokens across lines, remembering the line of each token for errors.
class TokenScanner {
 public:
  explicit TokenScanner(std::string_view text) : text_(text) {}
  // Next token, or false at the end of the text.
  bool Next(std::string_view* token);
  // 1-based line of the last token returned by Next (or of the end of the text).
  size_t line() const { return line_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_ = 1;
};

}  // namespace sfm_pruning::openmvg_text

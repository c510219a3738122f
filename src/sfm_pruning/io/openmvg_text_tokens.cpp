#include "sfm_pruning/io/openmvg_text_tokens.hpp"

#include <array>
#include <charconv>

namespace sfm_pruning::openmvg_text {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

template <typename T>
bool ParseWhole(std::string_view token, T* value) {
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, *value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

std::vector<std::string_view> SplitWhitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && IsBlank(line[pos])) ++pos;
    const size_t start = pos;
    while (pos < line.size() && !IsBlank(line[pos])) ++pos;
    if (pos > start) tokens.push_back(line.substr(start, pos - start));
  }
  return tokens;
}

void ForEachLine(std::string_view text, const std::function<void(std::string_view, size_t)>& visit) {
  size_t start = 0;
  size_t line_number = 1;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    visit(text.substr(start, end - start), line_number++);
    start = end + 1;
  }
}

bool ParseUInt32(std::string_view token, uint32_t* value) { return ParseWhole(token, value); }
bool ParseUInt64(std::string_view token, uint64_t* value) { return ParseWhole(token, value); }
bool ParseFloat(std::string_view token, float* value) { return ParseWhole(token, value); }

std::string FormatFloat(float value) {
  std::array<char, 64> buffer{};
  for (int precision = 6;; ++precision) {
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                      std::chars_format::general, precision);
    const std::string_view text(buffer.data(), static_cast<size_t>(result.ptr - buffer.data()));
    float back = 0.f;
    // Nine significant digits always round-trip a float; NaN never compares equal, so stop there.
    if (precision >= 9 || (ParseFloat(text, &back) && back == value)) return std::string(text);
  }
}

bool TokenScanner::Next(std::string_view* token) {
  while (pos_ < text_.size() && (IsBlank(text_[pos_]) || text_[pos_] == '\n')) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) return false;
  const size_t start = pos_;
  while (pos_ < text_.size() && !IsBlank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
  *token = text_.substr(start, pos_ - start);
  return true;
}

}  // namespace sfm_pruning::openmvg_text

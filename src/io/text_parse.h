// Private helpers for the text readers: line iteration over a whole file held
// in memory, and number tokens parsed in place with fast_float (no iostreams,
// no allocation per number).
#ifndef EDGEFIT_SRC_IO_TEXT_PARSE_H_
#define EDGEFIT_SRC_IO_TEXT_PARSE_H_

#include <fast_float/fast_float.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace edgefit {
namespace io_internal {

// The prefix of an error on a line of a file: "<name>: line <line>: ".
inline std::string AtLine(const std::string& name, int64_t line) {
  return name + ": line " + std::to_string(line) + ": ";
}

inline bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

inline const char* SkipBlanks(const char* p, const char* end) {
  while (p < end && IsBlank(*p)) ++p;
  return p;
}

// True when [p, end) holds only blanks.
inline bool OnlyBlanks(const char* p, const char* end) { return SkipBlanks(p, end) == end; }

// Parses one floating-point token at *p (leading blanks skipped) and advances
// *p past it. False when the token is not a number or does not end at a blank.
template <typename T>
inline bool ParseReal(const char** p, const char* end, T* value) {
  const char* q = SkipBlanks(*p, end);
  if (q < end && *q == '+') ++q;
  const auto result = fast_float::from_chars(q, end, *value);
  if (result.ec != std::errc() || (result.ptr < end && !IsBlank(*result.ptr))) return false;
  *p = result.ptr;
  return true;
}

// Same for an integer token.
template <typename T>
inline bool ParseInt(const char** p, const char* end, T* value) {
  const char* q = SkipBlanks(*p, end);
  if (q < end && *q == '+') ++q;
  const auto result = std::from_chars(q, end, *value);
  if (result.ec != std::errc() || (result.ptr < end && !IsBlank(*result.ptr))) return false;
  *p = result.ptr;
  return true;
}

// Walks the lines of a text held in memory. `line()` is the 1-based number of
// the line returned last, for messages.
class LineCursor {
 public:
  LineCursor(const char* begin, const char* end, int64_t first_line = 1)
      : p_(begin), end_(end), line_(first_line - 1) {}

  // The next line without its '\n'; false at the end of the text.
  bool Next(const char** line_begin, const char** line_end) {
    if (p_ >= end_) return false;
    const char* nl = static_cast<const char*>(std::memchr(p_, '\n', static_cast<size_t>(end_ - p_)));
    *line_begin = p_;
    *line_end = nl != nullptr ? nl : end_;
    p_ = nl != nullptr ? nl + 1 : end_;
    ++line_;
    return true;
  }
  // Next line that holds anything but blanks.
  bool NextNonBlank(const char** line_begin, const char** line_end) {
    while (Next(line_begin, line_end)) {
      if (!OnlyBlanks(*line_begin, *line_end)) return true;
    }
    return false;
  }
  const char* position() const { return p_; }
  const char* end() const { return end_; }
  int64_t line() const { return line_; }

 private:
  const char* p_;
  const char* end_;
  int64_t line_;
};

// Blank-separated tokens of one line.
inline std::vector<std::string_view> SplitTokens(const char* p, const char* end) {
  std::vector<std::string_view> tokens;
  while (true) {
    p = SkipBlanks(p, end);
    if (p >= end) break;
    const char* q = p;
    while (q < end && !IsBlank(*q)) ++q;
    tokens.emplace_back(p, static_cast<size_t>(q - p));
    p = q;
  }
  return tokens;
}

// Up to 40 characters of a line, for error messages.
inline std::string Excerpt(const char* p, const char* end) {
  std::string s(p, static_cast<size_t>(std::min<std::ptrdiff_t>(end - p, 40)));
  while (!s.empty() && IsBlank(s.back())) s.pop_back();
  return s;
}

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_TEXT_PARSE_H_

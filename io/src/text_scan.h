// Reading the text formats (ASCII STL, OBJ, OFF, ASCII PLY, legacy VTK) out of a file's
// bytes: lines with their numbers, blank-separated tokens, and numbers that are either
// read whole or refused with a message saying which token on which line is wrong.
//
// Numbers are parsed with std::from_chars: locale-independent, no allocation, and a
// token is a number only if every character of it is used ("1.5e3", "-2", "+4"; not
// "1.5x" or "abc"). A value outside the target type's range ("1e400" for double,
// "1e39" for float, "3000000000" for int) is reported as out of range, never clamped.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace blayer::detail {

// Lines of a text, numbered from 1. A line ends at '\n'; a trailing '\r' is dropped.
class TextLines {
 public:
  explicit TextLines(std::string_view text) : text_(text) {}

  // The next line (possibly empty); false at the end of the text.
  bool next(std::string_view* line);
  // The next line that holds something other than blanks once everything from
  // `comment` on is removed (comment == 0: no comments); false at the end.
  bool next_data(std::string_view* line, char comment);
  int line_number() const { return line_; }
  // The bytes after the last line returned (for binary data following a text header).
  std::string_view rest() const { return text_.substr(pos_); }
  bool at_end() const { return pos_ >= text_.size(); }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

// Splits on blanks (space, tab, '\r', '\v', '\f') into *tokens (cleared first).
void split_tokens(std::string_view line, std::vector<std::string_view>* tokens);

// Removes blanks at both ends.
std::string_view trim(std::string_view s);

// Case-insensitive equality with a lower-case keyword.
bool keyword_is(std::string_view token, std::string_view lower_keyword);

enum class NumberStatus { kOk, kNotANumber, kOutOfRange };

NumberStatus parse_double(std::string_view token, double* out);
NumberStatus parse_float(std::string_view token, float* out);
NumberStatus parse_int64(std::string_view token, std::int64_t* out);

// The problem with a token as a phrase for messages: "'abc' is not <expected>" or
// "'1e400' is outside the range of <range>", e.g. expected "a number", range "double".
std::string describe_bad_number(std::string_view token, NumberStatus status, const std::string& expected,
                                const std::string& range);

// Quotes a token for a message, cut to a readable length and with control characters
// shown as '?', so that binary garbage does not end up on the terminal.
std::string quoted(std::string_view token);

}  // namespace blayer::detail

#include "text_scan.h"

#include <cctype>
#include <charconv>
#include <system_error>

namespace blayer::detail {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// from_chars takes no leading '+'; a file may have one ("+1.5").
std::string_view without_plus(std::string_view t) {
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  return t;
}

template <class T>
NumberStatus parse_number(std::string_view token, T* out) {
  token = without_plus(token);
  if (token.empty()) return NumberStatus::kNotANumber;
  T value{};
  const char* end = token.data() + token.size();
  const std::from_chars_result r = std::from_chars(token.data(), end, value);
  if (r.ec == std::errc::result_out_of_range && r.ptr == end) return NumberStatus::kOutOfRange;
  if (r.ec != std::errc() || r.ptr != end) return NumberStatus::kNotANumber;
  *out = value;
  return NumberStatus::kOk;
}

}  // namespace

bool TextLines::next(std::string_view* line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  std::string_view l = text_.substr(pos_, end - pos_);
  if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;  // never past the end: rest() stays valid
  ++line_;
  *line = l;
  return true;
}

bool TextLines::next_data(std::string_view* line, char comment) {
  std::string_view l;
  while (next(&l)) {
    if (comment != 0) l = l.substr(0, l.find(comment));
    l = trim(l);
    if (!l.empty()) {
      *line = l;
      return true;
    }
  }
  return false;
}

void split_tokens(std::string_view line, std::vector<std::string_view>* tokens) {
  tokens->clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) tokens->push_back(line.substr(start, i - start));
  }
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

bool keyword_is(std::string_view token, std::string_view lower_keyword) {
  if (token.size() != lower_keyword.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(token[i])) != lower_keyword[i]) return false;
  return true;
}

NumberStatus parse_double(std::string_view token, double* out) { return parse_number(token, out); }
NumberStatus parse_float(std::string_view token, float* out) { return parse_number(token, out); }
NumberStatus parse_int64(std::string_view token, std::int64_t* out) { return parse_number(token, out); }

std::string describe_bad_number(std::string_view token, NumberStatus status, const std::string& expected,
                                const std::string& range) {
  if (status == NumberStatus::kOutOfRange) return quoted(token) + " is outside the range of " + range;
  return quoted(token) + " is not " + expected;
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string s = "'";
  for (std::size_t i = 0; i < token.size() && i < kShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    s += std::isprint(c) ? static_cast<char>(c) : '?';
  }
  if (token.size() > kShown) s += "...";
  return s + "'";
}

}  // namespace blayer::detail

// OFF (Geomview's Object File Format), ASCII.
//
// Header keyword [ST][C][N]OFF, then the counts "V F [E]" on the same line or the
// next; then V vertex lines and F face lines. '#' starts a comment; blank lines are
// skipped. A vertex line holds x y z, then 3 normal components (N), up to 4 colour
// values (C) and 2 texture coordinates (ST), of which only x y z are used. A face line
// holds n, then n vertex indices (0-based), then optional colour values.
// Not read: binary OFF, 4OFF (homogeneous) and nOFF (other dimensions); each is
// refused by name.
//
// Counts are checked as the file is read, never trusted for allocation: a vertex line
// has a fixed number of tokens for the variant (a face line "3 0 1 2" has one more
// than a plain vertex line), so a header claiming more vertices than the file holds is
// caught at the first face line, and one claiming more faces at the end of the file.
#include <algorithm>
#include <cmath>
#include <vector>

#include "surface_parsers.h"
#include "text_scan.h"

namespace blayer::detail {

namespace {

struct OffVariant {
  int min_vertex_tokens = 3;
  int max_vertex_tokens = 3;
};

// Parses the keyword; on failure returns false and says why in *why.
bool parse_keyword(std::string_view k, OffVariant* v, std::string* why) {
  if (k.size() < 3 || k.substr(k.size() - 3) != "OFF") {
    *why = "expected the keyword OFF (or COFF, NOFF, STOFF, ...)";
    return false;
  }
  std::string_view prefix = k.substr(0, k.size() - 3);
  int extra = 0, colour = 0;
  auto take = [&](std::string_view p) {
    if (prefix.substr(0, p.size()) != p) return false;
    prefix.remove_prefix(p.size());
    return true;
  };
  if (take("ST")) extra += 2;
  if (take("C")) colour = 4;
  if (take("N")) extra += 3;
  if (take("4") || take("n")) {
    *why = "4OFF and nOFF (coordinates in other than 3 dimensions) are not supported";
    return false;
  }
  if (!prefix.empty()) {
    *why = "unknown OFF variant " + quoted(k);
    return false;
  }
  v->min_vertex_tokens = 3 + extra;
  v->max_vertex_tokens = 3 + extra + colour;
  return true;
}

class OffParser {
 public:
  OffParser(std::string_view text, const std::string& name) : lines_(text), name_(name), size_(text.size()) {}

  PolygonSoup parse() {
    header();
    vertices();
    faces();
    if (lines_.next_data(&line_, '#'))
      fail("more data after the header's " + std::to_string(n_faces_) + " faces: " + quoted(line_));
    return std::move(soup_);
  }

 private:
  void header() {
    if (!lines_.next_data(&line_, '#')) fail_at(name_, 0, "no OFF header (the file holds only blanks and comments)");
    split_tokens(line_, &tokens_);
    std::string why;
    if (!parse_keyword(tokens_[0], &variant_, &why)) fail(why);
    std::vector<std::string_view> counts(tokens_.begin() + 1, tokens_.end());
    if (!counts.empty() && counts[0] == "BINARY") fail("binary OFF is not supported; write it as ASCII OFF");
    if (counts.empty()) {
      if (!lines_.next_data(&line_, '#')) fail("the file ends before the vertex and face counts");
      split_tokens(line_, &counts);
    }
    if (counts.size() < 2 || counts.size() > 3) fail("expected the counts 'vertices faces [edges]', found " + quoted(line_));
    n_vertices_ = count(counts[0], "vertex");
    n_faces_ = count(counts[1], "face");
  }

  std::int64_t count(std::string_view token, const char* what) {
    std::int64_t n = 0;
    const NumberStatus s = parse_int64(token, &n);
    if (s != NumberStatus::kOk || n < 0 || n > kMaxClaimedCount)
      fail(std::string("the ") + what + " count " + quoted(token) + " is not an integer in [0, 2^53]");
    return n;
  }

  void vertices() {
    // Each vertex line takes at least 6 bytes ("0 0 0\n"), so the file bounds the count.
    soup_.points.reserve(static_cast<std::size_t>(std::min<std::int64_t>(n_vertices_, size_ / 6)));
    for (std::int64_t i = 0; i < n_vertices_; ++i) {
      const bool more = lines_.next_data(&line_, '#');
      if (more) split_tokens(line_, &tokens_);
      const int n = more ? static_cast<int>(tokens_.size()) : 0;
      if (!more || n < variant_.min_vertex_tokens || n > variant_.max_vertex_tokens) {
        std::string msg = "the header claims " + std::to_string(n_vertices_) + " vertices, the file holds " +
                          std::to_string(i);
        if (more) msg += " (this line is not a vertex: " + quoted(line_) + ")";
        fail(msg);
      }
      if (i == kMaxElementCount) fail("more vertices than an int can index");
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = coordinate(tokens_[k], i);
      soup_.points.push_back(p);
    }
  }

  double coordinate(std::string_view token, std::int64_t vertex) {
    double v = 0.0;
    const NumberStatus s = parse_double(token, &v);
    // The message's prefix is built only for an error, not for every coordinate.
    auto where = [&] { return "vertex " + std::to_string(vertex) + ": "; };
    if (s != NumberStatus::kOk) fail(where() + describe_bad_number(token, s, "a number", "double"));
    if (!std::isfinite(v)) fail(where() + quoted(token) + " is not a finite number");
    return v;
  }

  void faces() {
    soup_.faces.reserve(static_cast<std::size_t>(std::min<std::int64_t>(n_faces_, size_ / 8)));
    for (std::int64_t f = 0; f < n_faces_; ++f) {
      if (!lines_.next_data(&line_, '#'))
        fail("the header claims " + std::to_string(n_faces_) + " faces, the file holds " + std::to_string(f));
      if (f == kMaxElementCount) fail("more faces than an int can index");
      split_tokens(line_, &tokens_);
      std::int64_t n = 0;
      if (parse_int64(tokens_[0], &n) != NumberStatus::kOk || n < 0)
        fail("face " + std::to_string(f) + ": the vertex count " + quoted(tokens_[0]) + " is not an integer >= 0");
      if (n > static_cast<std::int64_t>(tokens_.size()) - 1)
        fail("face " + std::to_string(f) + ": says " + std::to_string(n) + " vertices, the line lists " +
             std::to_string(tokens_.size() - 1));
      std::vector<int> face(static_cast<std::size_t>(n));
      for (std::int64_t k = 0; k < n; ++k) face[k] = index(tokens_[k + 1], f);
      soup_.faces.push_back(std::move(face));
    }
  }

  int index(std::string_view token, std::int64_t face) {
    std::int64_t v = 0;
    const NumberStatus s = parse_int64(token, &v);
    if (s != NumberStatus::kOk || v < -kMaxElementCount - 1 || v > kMaxElementCount)
      fail("face " + std::to_string(face) + ": vertex index " + quoted(token) + " is not an integer in int range");
    return static_cast<int>(v);
  }

  [[noreturn]] void fail(const std::string& what) const { fail_at(name_, lines_.line_number(), what); }

  TextLines lines_;
  const std::string& name_;
  std::int64_t size_;
  OffVariant variant_;
  std::int64_t n_vertices_ = 0, n_faces_ = 0;
  PolygonSoup soup_;
  std::string_view line_;
  std::vector<std::string_view> tokens_;
};

}  // namespace

PolygonSoup parse_off(std::string_view bytes, const std::string& name) { return OffParser(bytes, name).parse(); }

}  // namespace blayer::detail

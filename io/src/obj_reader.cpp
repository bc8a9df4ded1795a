// Wavefront OBJ, the geometry statements of it.
//
// Read: "v x y z [...]" (further values, a weight or a colour, are ignored) and
// "f a b c ..." whose references are "v", "v/vt", "v//vn" or "v/vt/vn": 1-based vertex
// numbers, or negative ones counting back from the last vertex defined so far. A line
// ending in '\' continues on the next. Ignored: texture coordinates, normals, groups,
// materials, smoothing, lines and points, free-form geometry, and any other statement.
// A vertex number 0, or a negative one reaching before the first vertex, is refused
// with its line; a positive number beyond the vertices is left to prepare_surface,
// which reports it against the file's vertex count.
#include <cmath>
#include <string>
#include <vector>

#include "surface_parsers.h"
#include "text_scan.h"

namespace blayer::detail {

namespace {

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& name) : lines_(text), name_(name) {}

  PolygonSoup parse() {
    while (next_statement()) {
      split_tokens(statement_, &tokens_);
      if (tokens_.empty()) continue;
      if (tokens_[0] == "v")
        vertex();
      else if (tokens_[0] == "f")
        face();
    }
    return std::move(soup_);
  }

 private:
  // The next statement with continuation lines joined and the comment removed.
  bool next_statement() {
    std::string_view line;
    if (!lines_.next_data(&line, '#')) return false;
    line_number_ = lines_.line_number();
    if (line.back() != '\\') {
      statement_ = line;
      return true;
    }
    joined_.clear();
    while (!line.empty() && line.back() == '\\') {
      joined_.append(line.substr(0, line.size() - 1)).push_back(' ');
      if (!lines_.next(&line)) break;
      line = trim(line.substr(0, line.find('#')));
    }
    if (line.empty() || line.back() != '\\') joined_.append(line);
    statement_ = joined_;
    return true;
  }

  void vertex() {
    // Message prefixes are built only for an error, not for every vertex.
    auto where = [&] { return "vertex " + std::to_string(soup_.points.size()) + ": "; };
    if (tokens_.size() < 4) fail(where() + "expected 'v x y z'");
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      const NumberStatus s = parse_double(tokens_[k + 1], &p[k]);
      if (s != NumberStatus::kOk) fail(where() + describe_bad_number(tokens_[k + 1], s, "a number", "double"));
      if (!std::isfinite(p[k])) fail(where() + quoted(tokens_[k + 1]) + " is not a finite number");
    }
    soup_.points.push_back(p);
  }

  void face() {
    std::vector<int> f;
    f.reserve(tokens_.size() - 1);
    for (std::size_t i = 1; i < tokens_.size(); ++i) f.push_back(reference(tokens_[i]));
    soup_.faces.push_back(std::move(f));
  }

  // "v", "v/vt", "v//vn", "v/vt/vn" -> 0-based vertex index.
  int reference(std::string_view token) {
    auto where = [&] { return "face " + std::to_string(soup_.faces.size()) + ": "; };
    const std::string_view v = token.substr(0, token.find('/'));
    std::int64_t n = 0;
    const NumberStatus s = parse_int64(v, &n);
    if (s != NumberStatus::kOk || n < -kMaxElementCount || n > kMaxElementCount)
      fail(where() + "vertex reference " + quoted(token) + " is not an integer in int range");
    if (n == 0) fail(where() + "vertex reference 0 (OBJ numbers vertices from 1)");
    const auto defined = static_cast<std::int64_t>(soup_.points.size());
    if (n < 0) {
      if (-n > defined)
        fail(where() + "relative vertex reference " + std::to_string(n) + " reaches before the first vertex (" +
             std::to_string(defined) + " defined so far)");
      return static_cast<int>(defined + n);
    }
    return static_cast<int>(n - 1);
  }

  [[noreturn]] void fail(const std::string& what) const { fail_at(name_, line_number_, what); }

  TextLines lines_;
  const std::string& name_;
  PolygonSoup soup_;
  std::string joined_;
  std::string_view statement_;
  int line_number_ = 0;
  std::vector<std::string_view> tokens_;
};

}  // namespace

PolygonSoup parse_obj(std::string_view bytes, const std::string& name) { return ObjParser(bytes, name).parse(); }

}  // namespace blayer::detail

// STL, binary and ASCII.
//
// Which one: binary when the file's size is exactly 84 + 50 N bytes for the facet count
// N stored little-endian in bytes 80..83 (the rule most readers use, since a binary
// header may itself start with "solid"); otherwise ASCII, which must start with
// "solid". ASCII grammar, keywords in any case, one statement per line:
//   solid [name] / facet [normal nx ny nz] / outer loop / vertex x y z (three times) /
//   endloop / endfacet / ... / endsolid [name]
// Several solids may follow each other; the facet normals are not used (blayer derives
// orientation from the winding). Coordinates are single precision, as STL defines them:
// an ASCII value is rounded to float directly from its digits (no detour through
// double), and one outside float's range is refused.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unordered_map>

#include "surface_parsers.h"
#include "text_scan.h"

namespace blayer::detail {

namespace {

// Corners merged into vertices by exact float equality (+0 and -0 are one value),
// numbered in order of first appearance.
class CornerMerger {
 public:
  explicit CornerMerger(PolygonSoup* soup) : soup_(soup) {}

  int vertex(const std::array<float, 3>& p) {
    Key key{};
    for (int k = 0; k < 3; ++k) {
      const float v = p[k] == 0.0f ? 0.0f : p[k];
      std::memcpy(&key[k], &v, sizeof v);
    }
    const auto [it, inserted] = ids_.try_emplace(key, static_cast<int>(soup_->points.size()));
    if (inserted) soup_->points.push_back({p[0], p[1], p[2]});
    return it->second;
  }

  // Adds the facet unless two of its corners are one vertex.
  void facet(const std::array<std::array<float, 3>, 3>& corners) {
    const int a = vertex(corners[0]), b = vertex(corners[1]), c = vertex(corners[2]);
    if (a == b || b == c || a == c) {
      ++dropped_;
      return;
    }
    soup_->faces.push_back({a, b, c});
  }

  void add_note() const {
    if (dropped_ > 0)
      soup_->notes.push_back("dropped " + std::to_string(dropped_) +
                             " STL facets with two corners at the same point (zero area)");
  }

 private:
  using Key = std::array<std::uint32_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (std::uint32_t v : k) h = (h ^ v) * 1099511628211ull;
      return static_cast<std::size_t>(h);
    }
  };
  PolygonSoup* soup_;
  std::unordered_map<Key, int, KeyHash> ids_;
  long dropped_ = 0;
};

std::uint32_t little_endian_u32(const unsigned char* b) {
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
         static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

float little_endian_float(const unsigned char* b) {
  const std::uint32_t bits = little_endian_u32(b);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

std::string format_float(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
  return buf;
}

PolygonSoup parse_binary(std::string_view bytes, std::uint32_t n_facets, const std::string& name) {
  PolygonSoup soup;
  CornerMerger merger(&soup);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::uint32_t f = 0; f < n_facets; ++f) {
    const unsigned char* rec = data + 84 + 50 * static_cast<std::size_t>(f);
    std::array<std::array<float, 3>, 3> corners;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) {
        const float v = little_endian_float(rec + 12 + 12 * c + 4 * k);
        if (!std::isfinite(v))
          fail_at(name, 0, "facet " + std::to_string(f) + ", corner " + std::to_string(c) +
                               ": coordinate " + format_float(v) + " is not a finite number");
        corners[c][k] = v;
      }
    merger.facet(corners);
  }
  merger.add_note();
  return soup;
}

class AsciiStl {
 public:
  AsciiStl(std::string_view text, const std::string& name) : lines_(text), name_(name), merger_(&soup_) {}

  PolygonSoup parse() {
    while (lines_.next_data(&line_, 0)) {
      split_tokens(line_, &tokens_);
      if (!keyword_is(tokens_[0], "solid")) fail("expected 'solid'");
      solid();
    }
    merger_.add_note();
    return std::move(soup_);
  }

 private:
  // After "solid": facets up to "endsolid" (a missing "endsolid" at the end is tolerated).
  void solid() {
    while (next()) {
      if (keyword_is(tokens_[0], "endsolid")) return;
      if (!keyword_is(tokens_[0], "facet")) fail("expected 'facet' or 'endsolid'");
      facet();
    }
  }

  void facet() {
    if (!next() || tokens_.size() != 2 || !keyword_is(tokens_[0], "outer") || !keyword_is(tokens_[1], "loop"))
      fail("expected 'outer loop'");
    std::array<std::array<float, 3>, 3> corners;
    for (int c = 0; c < 3; ++c) {
      if (!next() || !keyword_is(tokens_[0], "vertex"))
        fail("expected 'vertex x y z' (corner " + std::to_string(c) + " of facet " + std::to_string(n_facets_) +
             "; STL facets are triangles)");
      if (tokens_.size() != 4)
        fail_value("facet " + std::to_string(n_facets_) + ", corner " + std::to_string(c) + ": expected 3 coordinates");
      for (int k = 0; k < 3; ++k) corners[c][k] = coordinate(tokens_[k + 1], c);
    }
    if (!next() || !keyword_is(tokens_[0], "endloop")) fail("expected 'endloop' (STL facets are triangles)");
    if (!next() || !keyword_is(tokens_[0], "endfacet")) fail("expected 'endfacet'");
    merger_.facet(corners);
    ++n_facets_;
  }

  float coordinate(std::string_view token, int corner) {
    float v = 0.0f;
    const NumberStatus s = parse_float(token, &v);
    // The message's prefix is built only for an error: on every coordinate its strings
    // were most of an ASCII file's parse time.
    auto where = [&] { return "facet " + std::to_string(n_facets_) + ", corner " + std::to_string(corner) + ": "; };
    if (s != NumberStatus::kOk)
      fail_value(where() + describe_bad_number(token, s, "a number", "float (STL stores single precision)"));
    if (!std::isfinite(v)) fail_value(where() + quoted(token) + " is not a finite number");
    return v;
  }

  bool next() {
    if (!lines_.next_data(&line_, 0)) {
      at_end_ = true;
      return false;
    }
    split_tokens(line_, &tokens_);
    return true;
  }

  // A statement out of place: says what was expected and what is there instead.
  [[noreturn]] void fail(const std::string& what) {
    if (at_end_) fail_at(name_, lines_.line_number(), "unexpected end of file: " + what);
    fail_at(name_, lines_.line_number(), what + ", found " + quoted(line_));
  }
  // A bad value in a well-formed statement.
  [[noreturn]] void fail_value(const std::string& what) { fail_at(name_, lines_.line_number(), what); }

  TextLines lines_;
  const std::string& name_;
  PolygonSoup soup_;
  CornerMerger merger_;
  std::string_view line_;
  std::vector<std::string_view> tokens_;
  long n_facets_ = 0;
  bool at_end_ = false;
};

bool starts_with_solid(std::string_view bytes) {
  const std::string_view t = trim(bytes.substr(0, 64));
  return t.size() >= 5 && keyword_is(t.substr(0, 5), "solid");
}

}  // namespace

PolygonSoup parse_stl(std::string_view bytes, const std::string& name) {
  if (bytes.size() >= 84) {
    const std::uint32_t n = little_endian_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    if (84 + 50 * static_cast<std::uint64_t>(n) == bytes.size()) return parse_binary(bytes, n, name);
    if (!starts_with_solid(bytes))
      fail_at(name, 0, "neither binary STL (its header's " + std::to_string(n) + " facets need " +
                           std::to_string(84 + 50 * static_cast<std::uint64_t>(n)) + " bytes, the file has " +
                           std::to_string(bytes.size()) + ") nor ASCII STL (which starts with 'solid')");
  } else if (!starts_with_solid(bytes)) {
    fail_at(name, 0, "neither binary STL (" + std::to_string(bytes.size()) +
                         " bytes, fewer than the 84 of a binary header) nor ASCII STL (which starts with 'solid')");
  }
  return AsciiStl(bytes, name).parse();
}

}  // namespace blayer::detail

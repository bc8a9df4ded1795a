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
#include <optional>
#include <unordered_map>
#include <vector>

#include <tbb/parallel_for.h>

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

// An ASCII STL read in pieces side by side, for large files (parsing the perforated
// block's 4.3 MB took 19 ms serially, 11 ms in four pieces on two cores; the merge of
// the corners that follows is serial). The pieces start at 'facet'
// lines; each accepts a strict subset of the grammar: facets exactly as AsciiStl reads
// them, 'endsolid' and 'solid' lines between them in order. A piece that meets anything
// else, or a text whose pieces do not join into one valid sequence (one ending outside
// a solid before a piece that starts inside one), is refused: the serial parser then
// reads the whole text, and its messages for a faulty file are the same as ever. The
// facets go through the one CornerMerger in file order, so the soup is the serial one.
using FacetCorners = std::array<std::array<float, 3>, 3>;

struct StlPiece {
  std::vector<FacetCorners> facets;
  bool ok = false;
  bool ends_in_solid = true;
};

// Where the piece after `from` starts: the first line at or after `from` (a line
// start) whose first token is 'facet'; text.size() when there is none.
std::size_t next_facet_line(std::string_view text, std::size_t from) {
  std::vector<std::string_view> tokens;
  for (std::size_t p = from; p < text.size();) {
    const std::size_t end = std::min(text.find('\n', p), text.size());
    split_tokens(text.substr(p, end - p), &tokens);
    if (!tokens.empty() && keyword_is(tokens[0], "facet")) return p;
    p = end + 1;
  }
  return text.size();
}

// Reads a piece into *piece, whose facets may be reserved already.
void parse_stl_piece(std::string_view text, bool first, StlPiece* piece) {
  TextLines lines(text);
  std::string_view line;
  std::vector<std::string_view> t;
  auto next = [&] {
    if (!lines.next_data(&line, 0)) return false;
    split_tokens(line, &t);
    return true;
  };
  bool in_solid = !first;  // a later piece starts at a facet, inside a solid
  while (next()) {
    if (!in_solid) {
      if (!keyword_is(t[0], "solid")) return;
      in_solid = true;
      continue;
    }
    if (keyword_is(t[0], "endsolid")) {
      in_solid = false;
      continue;
    }
    if (!keyword_is(t[0], "facet")) return;
    if (!next() || t.size() != 2 || !keyword_is(t[0], "outer") || !keyword_is(t[1], "loop")) return;
    FacetCorners corners;
    for (int c = 0; c < 3; ++c) {
      if (!next() || !keyword_is(t[0], "vertex") || t.size() != 4) return;
      for (int k = 0; k < 3; ++k)
        if (parse_float(t[k + 1], &corners[c][k]) != NumberStatus::kOk || !std::isfinite(corners[c][k])) return;
    }
    if (!next() || !keyword_is(t[0], "endloop")) return;
    if (!next() || !keyword_is(t[0], "endfacet")) return;
    piece->facets.push_back(corners);
  }
  piece->ok = true;
  piece->ends_in_solid = in_solid;
}

// Texts below this are read serially: a piece is worth a thread from about here.
constexpr std::size_t kMinPieceBytes = 1 << 20;
constexpr std::size_t kMaxPieces = 16;

}  // namespace

std::optional<PolygonSoup> parse_ascii_stl_in_pieces(std::string_view text) {
  const std::size_t n = std::min(kMaxPieces, text.size() / kMinPieceBytes);
  if (n < 2) return std::nullopt;
  std::vector<std::size_t> start{0};
  for (std::size_t i = 1; i < n; ++i) {
    const std::size_t raw = text.size() / n * i;
    const std::size_t line = std::min(text.find('\n', raw), text.size());
    const std::size_t at = next_facet_line(text, std::min(line + 1, text.size()));
    if (at > start.back() && at < text.size()) start.push_back(at);
  }
  start.push_back(text.size());
  // Each piece's facets reserved here, for as many as its bytes could hold (a facet
  // takes 70 bytes or more): made by the threads, the buffers grew in their own malloc
  // arenas, which kept them resident after the read and lifted the M6 571k's peak from
  // 1.00 to 1.06 GB. Reserved here, they are mappings of their own, returned when freed.
  std::vector<StlPiece> pieces(start.size() - 1);
  for (std::size_t i = 0; i < pieces.size(); ++i) pieces[i].facets.reserve((start[i + 1] - start[i]) / 70 + 1);
  tbb::parallel_for(std::size_t(0), pieces.size(), [&](std::size_t i) {
    parse_stl_piece(text.substr(start[i], start[i + 1] - start[i]), i == 0, &pieces[i]);
  });
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!pieces[i].ok || (i + 1 < pieces.size() && !pieces[i].ends_in_solid)) return std::nullopt;
  PolygonSoup soup;
  CornerMerger merger(&soup);
  for (const StlPiece& piece : pieces)
    for (const FacetCorners& corners : piece.facets) merger.facet(corners);
  merger.add_note();
  return soup;
}

namespace {

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
  if (std::optional<PolygonSoup> soup = parse_ascii_stl_in_pieces(bytes)) return std::move(*soup);
  return AsciiStl(bytes, name).parse();
}

PolygonSoup parse_ascii_stl_serially(std::string_view bytes, const std::string& name) {
  return AsciiStl(bytes, name).parse();
}

}  // namespace blayer::detail

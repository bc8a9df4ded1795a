// Legacy VTK PolyData (.vtk), ASCII and BINARY (big-endian), both cell layouts: the
// classic "POLYGONS n size" with "k i1 .. ik" per cell, and the "OFFSETS" /
// "CONNECTIVITY" arrays of file version 5.
//
// Read: POINTS and POLYGONS. Read past: VERTICES, LINES, dataset FIELD data and
// METADATA blocks. Refused: TRIANGLE_STRIPS (convert them to triangles), a DATASET
// other than POLYDATA. Reading stops at POINT_DATA or CELL_DATA: attributes are not used.
//
// VTK's own legacy reader is not used: it crashes on a POLYGONS size that disagrees
// with the cells that follow, and allocates whatever a header claims. Here every count
// is checked against the data as it is read: ASCII data runs out at the next keyword
// or the end of the file ("POINTS claims 1000 points, the file holds 8"), binary data
// is bounded by the bytes left before anything is read.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "byte_cursor.h"
#include "surface_parsers.h"
#include "text_scan.h"

namespace blayer::detail {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// Blank-separated tokens over the whole text, with line numbers, and the switch to
// binary data that starts on the line after a keyword line.
class TokenStream {
 public:
  explicit TokenStream(std::string_view text) : text_(text) {}

  bool next(std::string_view* token) {
    skip_space();
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    *token = text_.substr(start, pos_ - start);
    return true;
  }
  bool peek(std::string_view* token) {
    const std::size_t pos = pos_;
    const int line = line_;
    const bool ok = next(token);
    pos_ = pos;
    line_ = line;
    return ok;
  }
  // The rest of the current line (for titles), consumed.
  std::string_view rest_of_line() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }
  // Skips to the start of the next line: binary data begins there.
  void to_next_line() {
    rest_of_line();
    if (pos_ < text_.size()) {
      ++pos_;
      ++line_;
    }
  }
  // Skips lines up to and including the next blank one (the end of a METADATA block).
  void skip_through_blank_line() {
    to_next_line();
    while (pos_ < text_.size()) {
      const std::string_view l = trim(rest_of_line());
      to_next_line();
      if (l.empty()) return;
    }
  }
  std::string_view binary() const { return text_.substr(pos_); }
  void advance(std::size_t n) {
    for (std::size_t i = 0; i < n && pos_ < text_.size(); ++i, ++pos_)
      if (text_[pos_] == '\n') ++line_;
  }
  int line() const { return line_; }

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

bool parse_data_type(std::string_view t, Scalar* s) {
  std::string l(t);
  for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  struct Name {
    const char* name;
    Scalar s;
  };
  static const Name kNames[] = {{"char", Scalar::kInt8},           {"unsigned_char", Scalar::kUint8},
                                {"short", Scalar::kInt16},         {"unsigned_short", Scalar::kUint16},
                                {"int", Scalar::kInt32},           {"unsigned_int", Scalar::kUint32},
                                {"long", Scalar::kInt64},          {"unsigned_long", Scalar::kUint64},
                                {"vtktypeint64", Scalar::kInt64},  {"vtktypeuint64", Scalar::kUint64},
                                {"vtkidtype", Scalar::kInt64},     {"float", Scalar::kFloat32},
                                {"double", Scalar::kFloat64}};
  for (const Name& n : kNames)
    if (l == n.name) {
      *s = n.s;
      return true;
    }
  return false;
}

class VtkLegacyParser {
 public:
  VtkLegacyParser(std::string_view text, const std::string& name) : in_(text), name_(name) {}

  PolygonSoup parse() {
    header();
    std::string_view k;
    while (in_.next(&k)) {
      if (keyword_is(k, "points")) points();
      else if (keyword_is(k, "polygons")) cells("POLYGONS", true);
      else if (keyword_is(k, "vertices")) cells("VERTICES", false);
      else if (keyword_is(k, "lines")) cells("LINES", false);
      else if (keyword_is(k, "triangle_strips"))
        fail("triangle strips are not supported; convert them to triangles");
      else if (keyword_is(k, "field")) field();
      else if (keyword_is(k, "metadata")) in_.skip_through_blank_line();
      else if (keyword_is(k, "point_data") || keyword_is(k, "cell_data")) break;
      else fail("unexpected " + quoted(k) + " (expected POINTS, POLYGONS, VERTICES, LINES or the data attributes)");
    }
    return std::move(soup_);
  }

 private:
  void header() {
    const std::string_view first = trim(in_.rest_of_line());
    if (first.rfind("# vtk DataFile Version", 0) != 0)
      fail("not a legacy VTK file (the first line is not '# vtk DataFile Version x.y')");
    in_.to_next_line();
    in_.rest_of_line();  // title
    in_.to_next_line();
    std::string_view t;
    if (!in_.next(&t)) fail("the file ends before ASCII or BINARY");
    if (keyword_is(t, "binary")) binary_ = true;
    else if (!keyword_is(t, "ascii")) fail("expected ASCII or BINARY, found " + quoted(t));
    std::string_view dataset, type;
    if (!in_.next(&dataset) || !keyword_is(dataset, "dataset") || !in_.next(&type))
      fail("expected 'DATASET POLYDATA'");
    if (!keyword_is(type, "polydata")) fail("not a legacy VTK PolyData file (DATASET " + std::string(type) + ")");
  }

  std::int64_t count(const char* what) {
    std::string_view t;
    std::int64_t n = 0;
    if (!in_.next(&t) || parse_int64(t, &n) != NumberStatus::kOk || n < 0 || n > kMaxClaimedCount / 8)
      fail(std::string(what) + ": expected a count in [0, 2^50]" + (t.empty() ? "" : ", found " + quoted(t)));
    return n;
  }

  Scalar data_type(const char* what) {
    std::string_view t;
    Scalar s;
    if (!in_.next(&t) || !parse_data_type(t, &s)) fail(std::string(what) + ": unknown data type " + quoted(t));
    return s;
  }

  // n values of type s: in ASCII the next n tokens, in binary n big-endian values
  // starting on the next line. `what` names the section for messages. Calls
  // take(i, value) for each.
  template <class Take>
  void values(std::int64_t n, Scalar s, const std::string& what, const std::string& unit, int per_unit,
              Take&& take) {
    if (binary_) {
      in_.to_next_line();
      const std::size_t bytes = static_cast<std::size_t>(n) * scalar_size(s);
      if (bytes > in_.binary().size())
        fail(what + " claims " + std::to_string(n / per_unit) + " " + unit + " (" + std::to_string(bytes) +
             " bytes), the " + std::to_string(in_.binary().size()) + " bytes left hold " +
             std::to_string(in_.binary().size() / scalar_size(s) / per_unit));
      ByteCursor c(in_.binary(), ByteOrder::kBig);
      for (std::int64_t i = 0; i < n; ++i) {
        double v = 0.0;
        c.read(s, &v);
        take(i, v);
      }
      in_.advance(bytes);
      return;
    }
    std::string_view t;
    for (std::int64_t i = 0; i < n; ++i) {
      if (!in_.next(&t))
        fail(what + " claims " + std::to_string(n / per_unit) + " " + unit + ", the file holds " +
             std::to_string(i / per_unit));
      double v = 0.0;
      const NumberStatus st = scalar_is_integer(s) ? parse_integer(t, &v) : parse_double(t, &v);
      if (st == NumberStatus::kNotANumber && std::isalpha(static_cast<unsigned char>(t[0])))
        fail(what + " claims " + std::to_string(n / per_unit) + " " + unit + ", the file holds " +
             std::to_string(i / per_unit) + " (then " + quoted(t) + ")");
      if (st != NumberStatus::kOk)
        fail(what + ", " + unit.substr(0, unit.size() - 1) + " " + std::to_string(i / per_unit) + ": " +
             describe_bad_number(t, st, scalar_is_integer(s) ? "an integer" : "a number", "double"));
      take(i, v);
    }
  }

  static NumberStatus parse_integer(std::string_view t, double* v) {
    std::int64_t n = 0;
    const NumberStatus s = parse_int64(t, &n);
    *v = static_cast<double>(n);
    return s;
  }

  void points() {
    const std::int64_t n = count("POINTS");
    const Scalar s = data_type("POINTS");
    soup_.points.reserve(soup_.points.size() + bound(3 * n, s) / 3);
    Vec3 p{0.0, 0.0, 0.0};
    values(3 * n, s, "POINTS", "points", 3, [&](std::int64_t i, double v) {
      if (!std::isfinite(v)) fail("POINTS, point " + std::to_string(i / 3) + ": a coordinate is not a finite number");
      p[i % 3] = v;
      if (i % 3 != 2) return;
      if (soup_.points.size() == static_cast<std::size_t>(kMaxElementCount)) fail("more points than an int can index");
      soup_.points.push_back(p);
    });
  }

  // How many values of type s the data left can hold at most: a bound for reserving.
  std::size_t bound(std::int64_t n, Scalar s) {
    const std::size_t left = binary_ ? in_.binary().size() / scalar_size(s) : in_.binary().size() / 2 + 1;
    return std::min<std::size_t>(static_cast<std::size_t>(n), left);
  }

  // One cell section; keep: its cells become faces.
  void cells(const char* section, bool keep) {
    const std::int64_t n_cells = count(section);
    const std::int64_t size = count(section);
    std::string_view next;
    if (in_.peek(&next) && keyword_is(next, "offsets"))
      offset_cells(section, n_cells, size, keep);
    else
      classic_cells(section, n_cells, size, keep);
  }

  // "k i1 .. ik" per cell, `size` integers in all (int32 in binary files).
  void classic_cells(const std::string& section, std::int64_t n_cells, std::int64_t size, bool keep) {
    if (n_cells > size) fail(section + ": " + std::to_string(n_cells) + " cells cannot fit in " + std::to_string(size) + " integers");
    std::int64_t cell = 0, left_in_cell = -1;
    std::vector<int> face;
    values(size, binary_ ? Scalar::kInt32 : Scalar::kInt64, section, "integers", 1, [&](std::int64_t, double v) {
      if (left_in_cell < 0) {
        if (cell >= n_cells) fail(section + ": more data than its " + std::to_string(n_cells) + " cells");
        if (v < 0 || v > static_cast<double>(size)) fail(section + ", cell " + std::to_string(cell) + ": bad vertex count " + std::to_string(v));
        left_in_cell = static_cast<std::int64_t>(v);
        face.clear();
      } else {
        face.push_back(index(v, section, cell));
        --left_in_cell;
      }
      if (left_in_cell == 0) {
        if (keep) soup_.faces.push_back(face);
        ++cell;
        left_in_cell = -1;
      }
    });
    if (cell != n_cells || left_in_cell >= 0)
      fail(section + ": its " + std::to_string(size) + " integers hold " + std::to_string(cell) +
           " complete cells, the header claims " + std::to_string(n_cells));
  }

  // File version 5: "OFFSETS type" with n_offsets values, "CONNECTIVITY type" with size.
  void offset_cells(const std::string& section, std::int64_t n_offsets, std::int64_t size, bool keep) {
    std::string_view k;
    in_.next(&k);
    const Scalar ot = data_type("OFFSETS");
    std::vector<std::int64_t> offsets;
    offsets.reserve(bound(n_offsets, ot));
    values(n_offsets, ot, section + " OFFSETS", "offsets", 1, [&](std::int64_t i, double v) {
      const double prev = i == 0 ? 0.0 : static_cast<double>(offsets.back());
      if (!(v >= prev && v <= static_cast<double>(size)) || (i == 0 && v != 0.0))
        fail(section + " OFFSETS: offset " + std::to_string(i) + " is " + std::to_string(v) +
             " (offsets start at 0, never decrease and end at the connectivity size " + std::to_string(size) + ")");
      offsets.push_back(static_cast<std::int64_t>(v));
    });
    if (!offsets.empty() && offsets.back() != size)
      fail(section + " OFFSETS: the last offset " + std::to_string(offsets.back()) + " differs from the connectivity size " + std::to_string(size));
    if (!in_.next(&k) || !keyword_is(k, "connectivity")) fail(section + ": expected CONNECTIVITY after the offsets");
    const Scalar ct = data_type("CONNECTIVITY");
    std::vector<int> conn;
    conn.reserve(bound(size, ct));
    values(size, ct, section + " CONNECTIVITY", "indices", 1,
           [&](std::int64_t, double v) { conn.push_back(index(v, section, -1)); });
    if (!keep) return;
    for (std::size_t c = 0; c + 1 < offsets.size(); ++c)
      soup_.faces.emplace_back(conn.begin() + offsets[c], conn.begin() + offsets[c + 1]);
  }

  int index(double v, const std::string& section, std::int64_t cell) {
    if (!(v >= -2147483648.0 && v <= 2147483647.0) || v != std::floor(v))
      fail(section + (cell >= 0 ? ", cell " + std::to_string(cell) : std::string()) + ": point index " +
           std::to_string(v) + " does not fit an int");
    return static_cast<int>(v);
  }

  // "FIELD name n" and n arrays "name components tuples type" with their values.
  void field() {
    std::string_view t;
    in_.next(&t);  // the field's name
    const std::int64_t n = count("FIELD");
    for (std::int64_t a = 0; a < n; ++a) {
      std::string_view array;
      if (!in_.next(&array)) fail("FIELD: the file ends before array " + std::to_string(a));
      const std::int64_t components = count("FIELD array"), tuples = count("FIELD array");
      const Scalar s = data_type("FIELD array");
      if (components > 0 && tuples > kMaxClaimedCount / 8 / components)
        fail("FIELD array " + quoted(array) + " claims more than 2^50 values");
      values(components * tuples, s, "FIELD array " + quoted(array), "values", 1, [](std::int64_t, double) {});
      std::string_view next;
      if (in_.peek(&next) && keyword_is(next, "metadata")) {
        in_.next(&next);
        in_.skip_through_blank_line();
      }
    }
  }

  [[noreturn]] void fail(const std::string& what) const { fail_at(name_, in_.line(), what); }

  TokenStream in_;
  const std::string& name_;
  bool binary_ = false;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup parse_vtk_legacy(std::string_view bytes, const std::string& name) {
  return VtkLegacyParser(bytes, name).parse();
}

}  // namespace blayer::detail

// PLY (Stanford polygon format), ASCII and binary of either byte order.
//
// The header declares elements with counts and typed properties; blayer uses the
// scalar properties x, y, z of element "vertex" and the list property
// "vertex_indices" (or "vertex_index") of element "face", and reads past every other
// element and property by its declared type. Types: char/int8, uchar/uint8,
// short/int16, ushort/uint16, int/int32, uint/uint32, float/float32, double/float64.
// Coordinates keep their declared precision (a float property is read as float, a
// value outside float's range refused); indices must be integers that fit an int.
//
// Counts: in ASCII PLY every element is one line, so a header claiming more vertices
// than the file holds is caught at the first line with a different token count (or the
// end of the file). In binary PLY the smallest size of an element (its scalars plus
// the count of each list) bounds how many the rest of the file can hold, checked
// before anything is read; every list length is checked against the bytes left.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "byte_cursor.h"
#include "surface_parsers.h"
#include "text_scan.h"

namespace blayer::detail {

namespace {

struct PlyProperty {
  std::string name;
  Scalar type = Scalar::kFloat32;
  bool is_list = false;
  Scalar count_type = Scalar::kUint8;  // lists only
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  // header line, for messages
};

enum class PlyFormat { kAscii, kBinaryLittle, kBinaryBig };

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
};

bool parse_scalar_type(std::string_view t, Scalar* s) {
  struct Name {
    const char* a;
    const char* b;
    Scalar s;
  };
  static const Name kNames[] = {
      {"char", "int8", Scalar::kInt8},       {"uchar", "uint8", Scalar::kUint8},
      {"short", "int16", Scalar::kInt16},    {"ushort", "uint16", Scalar::kUint16},
      {"int", "int32", Scalar::kInt32},      {"uint", "uint32", Scalar::kUint32},
      {"float", "float32", Scalar::kFloat32}, {"double", "float64", Scalar::kFloat64}};
  for (const Name& n : kNames)
    if (t == n.a || t == n.b) {
      *s = n.s;
      return true;
    }
  return false;
}

const char* scalar_name(Scalar s) {
  switch (s) {
    case Scalar::kInt8: return "char";
    case Scalar::kUint8: return "uchar";
    case Scalar::kInt16: return "short";
    case Scalar::kUint16: return "ushort";
    case Scalar::kInt32: return "int";
    case Scalar::kUint32: return "uint";
    case Scalar::kInt64: return "int64";
    case Scalar::kUint64: return "uint64";
    case Scalar::kFloat32: return "float";
    case Scalar::kFloat64: return "double";
  }
  return "";
}

// Bounds of an integer scalar type.
void integer_bounds(Scalar s, double* lo, double* hi) {
  const int bits = 8 * scalar_size(s);
  const bool is_signed = s == Scalar::kInt8 || s == Scalar::kInt16 || s == Scalar::kInt32 || s == Scalar::kInt64;
  *lo = is_signed ? -std::ldexp(1.0, bits - 1) : 0.0;
  *hi = is_signed ? std::ldexp(1.0, bits - 1) - 1 : std::ldexp(1.0, bits) - 1;
}

bool is_vertex_indices(const PlyProperty& p) {
  return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

class PlyParser {
 public:
  PlyParser(std::string_view bytes, const std::string& name) : lines_(bytes), name_(name) {}

  PolygonSoup parse() {
    read_header();
    find_used_properties();
    if (header_.format == PlyFormat::kAscii)
      read_ascii_body();
    else
      read_binary_body();
    return std::move(soup_);
  }

 private:
  // ---- header ---------------------------------------------------------------------
  void read_header() {
    std::string_view line;
    if (!lines_.next(&line) || trim(line) != "ply") fail_at(name_, 1, "not a PLY file (the first line is not 'ply')");
    bool have_format = false;
    std::vector<std::string_view> t;
    while (true) {
      if (!lines_.next(&line)) fail("the header has no 'end_header'");
      split_tokens(line, &t);
      if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
      if (t[0] == "end_header") break;
      if (t[0] == "format") {
        format_line(t);
        have_format = true;
      } else if (t[0] == "element") {
        element_line(t);
      } else if (t[0] == "property") {
        property_line(t);
      } else {
        fail("unknown header line " + quoted(line));
      }
    }
    if (!have_format) fail("the header has no 'format' line");
  }

  void format_line(const std::vector<std::string_view>& t) {
    if (t.size() != 3 || t[2] != "1.0") fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    if (t[1] == "ascii") header_.format = PlyFormat::kAscii;
    else if (t[1] == "binary_little_endian") header_.format = PlyFormat::kBinaryLittle;
    else if (t[1] == "binary_big_endian") header_.format = PlyFormat::kBinaryBig;
    else fail("unknown PLY format " + quoted(t[1]));
  }

  void element_line(const std::vector<std::string_view>& t) {
    if (t.size() != 3) fail("expected 'element NAME COUNT'");
    PlyElement e;
    e.name = std::string(t[1]);
    e.line = lines_.line_number();
    const NumberStatus s = parse_int64(t[2], &e.count);
    if (s != NumberStatus::kOk || e.count < 0 || e.count > kMaxClaimedCount)
      fail("element " + quoted(t[1]) + ": the count " + quoted(t[2]) + " is not an integer in [0, 2^53]");
    header_.elements.push_back(std::move(e));
  }

  void property_line(const std::vector<std::string_view>& t) {
    if (header_.elements.empty()) fail("a property before any element");
    PlyProperty p;
    if (t.size() == 5 && t[1] == "list") {
      p.is_list = true;
      if (!parse_scalar_type(t[2], &p.count_type) || !scalar_is_integer(p.count_type))
        fail("list property " + quoted(t[4]) + ": the count type " + quoted(t[2]) + " is not an integer type");
      if (!parse_scalar_type(t[3], &p.type)) fail("unknown property type " + quoted(t[3]));
      p.name = std::string(t[4]);
    } else if (t.size() == 3) {
      if (!parse_scalar_type(t[1], &p.type)) fail("unknown property type " + quoted(t[1]));
      p.name = std::string(t[2]);
    } else {
      fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
    }
    header_.elements.back().properties.push_back(std::move(p));
  }

  // Which element and property slots hold the coordinates and the indices.
  void find_used_properties() {
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& el = header_.elements[e];
      if ((el.name == "vertex" && vertex_element_ >= 0) || (el.name == "face" && face_element_ >= 0))
        fail_at(name_, el.line, "element " + el.name + " is declared twice");
      if (el.name == "vertex") {
        vertex_element_ = static_cast<int>(e);
        for (int k = 0; k < 3; ++k) xyz_[k] = -1;
        for (std::size_t p = 0; p < el.properties.size(); ++p)
          for (int k = 0; k < 3; ++k)
            if (el.properties[p].name == std::string(1, "xyz"[k]) && !el.properties[p].is_list)
              xyz_[k] = static_cast<int>(p);
        for (int k = 0; k < 3; ++k)
          if (xyz_[k] < 0) fail_at(name_, el.line, std::string("element vertex has no scalar property ") + "xyz"[k]);
      } else if (el.name == "face") {
        face_element_ = static_cast<int>(e);
        for (std::size_t p = 0; p < el.properties.size(); ++p)
          if (is_vertex_indices(el.properties[p])) indices_ = static_cast<int>(p);
        if (indices_ < 0) fail_at(name_, el.line, "element face has no list property vertex_indices");
        if (!scalar_is_integer(el.properties[indices_].type))
          fail_at(name_, el.line, "the face list vertex_indices has a non-integer type");
      }
    }
  }

  // ---- values -----------------------------------------------------------------------
  // "vertex 12: " for messages; built only when a message is.
  std::string where(int e, std::int64_t i) const {
    return header_.elements[e].name + " " + std::to_string(i) + ": ";
  }

  void store(int e, int property, double v, std::int64_t i) {
    if (e != vertex_element_) return;
    for (int k = 0; k < 3; ++k)
      if (property == xyz_[k]) {
        if (!std::isfinite(v)) fail(where(e, i) + "coordinate " + "xyz"[k] + " is not a finite number");
        vertex_[k] = v;
      }
  }

  int to_index(double v, int e, std::int64_t i) {
    if (!(v >= -2147483648.0 && v <= 2147483647.0) || v != std::floor(v))
      fail(where(e, i) + "vertex index " + std::to_string(v) + " does not fit an int");
    return static_cast<int>(v);
  }

  // ---- ASCII ------------------------------------------------------------------------
  void read_ascii_body() {
    std::vector<std::string_view> t;
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& el = header_.elements[e];
      if (el.properties.empty()) continue;  // nothing to read
      reserve(static_cast<int>(e), el.count, lines_.rest().size() / 2);
      for (std::int64_t i = 0; i < el.count; ++i) {
        std::string_view line;
        const bool more = lines_.next_data(&line, 0);
        if (more) split_tokens(line, &t);
        if (!more || !ascii_element(static_cast<int>(e), i, t)) {
          std::string msg = "the header claims " + std::to_string(el.count) + " " + el.name +
                            " elements, the file holds " + std::to_string(i);
          if (more) msg += " (this line is not a " + el.name + ": " + quoted(line) + ")";
          fail(msg);
        }
      }
    }
  }

  // Parses one element's line; false when its token count does not match the element.
  bool ascii_element(int e, std::int64_t i, const std::vector<std::string_view>& t) {
    const PlyElement& el = header_.elements[e];
    std::size_t k = 0;
    std::vector<int> face;
    for (std::size_t p = 0; p < el.properties.size(); ++p) {
      const PlyProperty& prop = el.properties[p];
      if (k >= t.size()) return false;
      if (!prop.is_list) {
        store(e, static_cast<int>(p), ascii_value(t[k++], prop.type, e, i, prop), i);
        continue;
      }
      const double n = ascii_value(t[k++], prop.count_type, e, i, prop);
      if (n < 0 || n > static_cast<double>(t.size() - k)) return false;
      const bool used = e == face_element_ && static_cast<int>(p) == indices_;
      for (std::int64_t j = 0; j < static_cast<std::int64_t>(n); ++j) {
        const double v = ascii_value(t[k++], prop.type, e, i, prop);
        if (used) face.push_back(to_index(v, e, i));
      }
    }
    if (k != t.size()) return false;
    finish_element(e, std::move(face));
    return true;
  }

  double ascii_value(std::string_view token, Scalar type, int e, std::int64_t i, const PlyProperty& prop) {
    double v = 0.0;
    NumberStatus s;
    if (type == Scalar::kFloat32) {
      float f = 0.0f;
      s = parse_float(token, &f);
      v = f;
    } else if (type == Scalar::kFloat64) {
      s = parse_double(token, &v);
    } else {
      std::int64_t n = 0;
      s = parse_int64(token, &n);
      double lo, hi;
      integer_bounds(type, &lo, &hi);
      if (s == NumberStatus::kOk && (static_cast<double>(n) < lo || static_cast<double>(n) > hi))
        s = NumberStatus::kOutOfRange;
      v = static_cast<double>(n);
    }
    if (s != NumberStatus::kOk)
      fail(where(e, i) + "property " + prop.name + ": " +
           describe_bad_number(token, s, scalar_is_integer(type) ? "an integer" : "a number",
                               std::string(scalar_name(type)) + " (the type the header declares)"));
    return v;
  }

  // ---- binary -----------------------------------------------------------------------
  void read_binary_body() {
    in_binary_body_ = true;
    ByteCursor in(lines_.rest(), header_.format == PlyFormat::kBinaryBig ? ByteOrder::kBig : ByteOrder::kLittle);
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& el = header_.elements[e];
      std::size_t min_size = 0;
      for (const PlyProperty& p : el.properties) min_size += scalar_size(p.is_list ? p.count_type : p.type);
      const std::size_t can_hold = min_size == 0 ? static_cast<std::size_t>(el.count) : in.remaining() / min_size;
      if (static_cast<std::uint64_t>(el.count) > can_hold)
        fail_at(name_, 0, "the header claims " + std::to_string(el.count) + " " + el.name + " elements of at least " +
                              std::to_string(min_size) + " bytes, the " + std::to_string(in.remaining()) +
                              " bytes left hold at most " + std::to_string(can_hold));
      if (el.properties.empty()) continue;  // nothing to read
      reserve(static_cast<int>(e), el.count, can_hold);
      for (std::int64_t i = 0; i < el.count; ++i) binary_element(static_cast<int>(e), i, in);
    }
  }

  void binary_element(int e, std::int64_t i, ByteCursor& in) {
    const PlyElement& el = header_.elements[e];
    auto value = [&](Scalar s) {
      double v = 0.0;
      if (!in.read(s, &v)) fail_at(name_, 0, where(e, i) + "the file ends inside the element");
      return v;
    };
    std::vector<int> face;
    for (std::size_t p = 0; p < el.properties.size(); ++p) {
      const PlyProperty& prop = el.properties[p];
      if (!prop.is_list) {
        store(e, static_cast<int>(p), value(prop.type), i);
        continue;
      }
      const double n = value(prop.count_type);
      if (n < 0 || n * scalar_size(prop.type) > static_cast<double>(in.remaining()))
        fail_at(name_, 0, where(e, i) + "list " + prop.name + " of " + std::to_string(static_cast<long long>(n)) +
                              " values runs past the end of the file");
      const bool used = e == face_element_ && static_cast<int>(p) == indices_;
      if (!used) {
        in.skip(static_cast<std::size_t>(n) * scalar_size(prop.type));
        continue;
      }
      face.reserve(static_cast<std::size_t>(n));
      for (std::int64_t j = 0; j < static_cast<std::int64_t>(n); ++j) face.push_back(to_index(value(prop.type), e, i));
    }
    finish_element(e, std::move(face));
  }

  // ---- shared -----------------------------------------------------------------------
  void reserve(int e, std::int64_t count, std::size_t bound) {
    const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(count), bound);
    if (e == vertex_element_) soup_.points.reserve(n);
    if (e == face_element_) soup_.faces.reserve(n);
  }

  void finish_element(int e, std::vector<int> face) {
    const std::size_t n = e == vertex_element_ ? soup_.points.size() : soup_.faces.size();
    if ((e == vertex_element_ || e == face_element_) && n == static_cast<std::size_t>(kMaxElementCount))
      fail("more " + header_.elements[e].name + " elements than an int can index");
    if (e == vertex_element_) soup_.points.push_back(vertex_);
    if (e == face_element_) soup_.faces.push_back(std::move(face));
  }

  // Text messages name the line; binary data has none to name.
  [[noreturn]] void fail(const std::string& what) const {
    fail_at(name_, in_binary_body_ ? 0 : lines_.line_number(), what);
  }

  TextLines lines_;
  bool in_binary_body_ = false;
  const std::string& name_;
  PlyHeader header_;
  int vertex_element_ = -1, face_element_ = -1, indices_ = -1;
  int xyz_[3] = {-1, -1, -1};
  Vec3 vertex_{0.0, 0.0, 0.0};
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup parse_ply(std::string_view bytes, const std::string& name) { return PlyParser(bytes, name).parse(); }

}  // namespace blayer::detail

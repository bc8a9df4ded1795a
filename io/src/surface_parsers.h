// One parser per surface format, each from the file's bytes (the contract is in
// blayer/io/read_surface.h). `name` is the file as the user gave it, for messages.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "blayer/io/read_surface.h"

namespace blayer::detail {

PolygonSoup parse_stl(std::string_view bytes, const std::string& name);
// An ASCII STL of 2 MiB or more read in pieces side by side (stl_reader.cpp), or
// nothing where a piece meets anything but well-formed facets and solids: parse_stl then
// reads it with the serial parser, which gives its messages.
std::optional<PolygonSoup> parse_ascii_stl_in_pieces(std::string_view text);
// An ASCII STL read by the serial parser alone: what parse_stl gives, read in pieces or
// not (the tests' oracle).
PolygonSoup parse_ascii_stl_serially(std::string_view bytes, const std::string& name);
PolygonSoup parse_obj(std::string_view bytes, const std::string& name);
PolygonSoup parse_off(std::string_view bytes, const std::string& name);
PolygonSoup parse_ply(std::string_view bytes, const std::string& name);
PolygonSoup parse_vtk_legacy(std::string_view bytes, const std::string& name);
PolygonSoup parse_vtp(std::string_view bytes, const std::string& name);

// "name:line: what" (line > 0) or "name: what", as an InputError.
[[noreturn]] void fail_at(const std::string& name, int line, const std::string& what);

// The largest vertex or face count a file can hold: indices are int.
inline constexpr std::int64_t kMaxElementCount = 2147483647;

// The largest count a header may claim. Larger claims are read like any other and
// fail at the first record the file does not hold, with both numbers in the message;
// 2^53 keeps every count and byte size exact in double and int64 arithmetic.
inline constexpr std::int64_t kMaxClaimedCount = std::int64_t{1} << 53;

}  // namespace blayer::detail

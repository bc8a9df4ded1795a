// What every harness shares: the outcomes a fuzzed input may have. Refusing the input
// (InputError) is the expected outcome of most inputs; any other exception, a crash, a
// hang, a leak or a sanitizer report is a finding. A broken invariant aborts with a
// message, so that libFuzzer saves the input.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/read_surface.h"

namespace blayer::fuzz {

[[noreturn]] inline void broken(const std::string& what) {
  std::fprintf(stderr, "invariant broken: %s\n", what.c_str());
  std::abort();
}

// Surfaces larger than this are parsed but not prepared: the checks' cost would
// dominate the fuzzer's time without exercising anything new.
inline constexpr std::size_t kMaxPreparedFaces = 4096;

// Parses bytes as `format`, then prepares what parsed; both may refuse.
inline void parse_and_prepare(std::string_view bytes, const std::string& format) {
  PolygonSoup soup;
  try {
    soup = parse_polygon_soup(bytes, format, "fuzz." + format);
  } catch (const InputError&) {
    return;
  }
  for (const auto& f : soup.faces)
    if (f.size() > bytes.size()) broken("a face with more vertices than the file has bytes");
  if (soup.faces.size() > kMaxPreparedFaces) return;
  for (bool open : {false, true}) {
    PrepareOptions opt;
    opt.allow_open = open;
    try {
      const PreparedSurface p = prepare_surface(soup, "fuzz." + format, opt);
      for (const Triangle& t : p.surface.triangles)
        for (int v : t)
          if (v < 0 || v >= static_cast<int>(p.surface.points.size())) broken("prepared triangle index out of range");
    } catch (const InputError&) {
    }
  }
}

}  // namespace blayer::fuzz

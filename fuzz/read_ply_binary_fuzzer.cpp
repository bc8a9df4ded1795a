// libFuzzer harness: binary PLY. The first 7 input bytes choose a header (byte order,
// element counts, the coordinate, list-count and index types, an extra property); the
// rest is the body, so every input exercises the binary element reader.
#include <string>

#include "fuzz_support.h"

namespace {

const char* const kTypes[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  if (size < 7) return 0;
  const bool big = data[0] & 1;
  const int n_vertices = data[1] | (data[2] & 0x3) << 8, n_faces = data[3] | (data[4] & 0x3) << 8;
  const char* coord = kTypes[data[5] & 7];
  const char* count = kTypes[(data[6] >> 4) & 7];
  const char* index = kTypes[data[6] & 7];
  std::string file = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                     " 1.0\nelement vertex " + std::to_string(n_vertices) + "\nproperty " + coord + " x\nproperty " +
                     coord + " y\nproperty " + coord + " z\n";
  if (data[5] & 8) file += "property uchar red\n";
  file += "element face " + std::to_string(n_faces) + "\nproperty list " + count + " " + index +
          " vertex_indices\nend_header\n";
  file.append(reinterpret_cast<const char*>(data) + 7, size - 7);
  blayer::fuzz::parse_and_prepare(file, "ply");
  return 0;
}

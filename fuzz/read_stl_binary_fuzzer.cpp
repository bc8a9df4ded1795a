// libFuzzer harness: the input as the facet records of a binary STL. The 84-byte header
// is made to match (facet count = size / 50), so every input takes the binary path.
#include <cstdint>
#include <string>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::uint32_t n = static_cast<std::uint32_t>(size / 50);
  std::string file(80, ' ');
  for (int i = 0; i < 4; ++i) file.push_back(static_cast<char>((n >> (8 * i)) & 0xff));
  file.append(reinterpret_cast<const char*>(data), 50 * static_cast<std::size_t>(n));
  blayer::fuzz::parse_and_prepare(file, "stl");
  return 0;
}

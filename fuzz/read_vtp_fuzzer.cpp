// libFuzzer harness: arbitrary bytes read as a .vtp file, then prepared as a wall.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  blayer::fuzz::parse_and_prepare({reinterpret_cast<const char*>(data), size}, "vtp");
  return 0;
}

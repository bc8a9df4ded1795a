#include "base64.h"

#include <gtest/gtest.h>
#include <vtkBase64Utilities.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace blayer {
namespace {

std::string encoded(const std::vector<unsigned char>& bytes) {
  std::string text(4 * ((bytes.size() + 2) / 3), '?');
  detail::encode_base64(bytes.data(), bytes.size(), reinterpret_cast<unsigned char*>(text.data()));
  return text;
}

TEST(Base64, EncodesTheRfc4648Examples) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="},
      {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, text] : cases)
    EXPECT_EQ(encoded(std::vector<unsigned char>(plain.begin(), plain.end())), text) << plain;
}

// Oracle: VTK's own encoder, on every length up to 100 and on all 256 byte values.
TEST(Base64, AgreesWithVtksEncoderOnEveryLengthAndByte) {
  std::mt19937 rng(64);
  std::vector<unsigned char> bytes(256);
  for (int b = 0; b < 256; ++b) bytes[b] = static_cast<unsigned char>(b);
  for (int len = 0; len <= 100; ++len) {
    std::vector<unsigned char> in(bytes.begin(), bytes.begin() + len);
    std::shuffle(in.begin(), in.end(), rng);
    std::string expected(4 * ((in.size() + 2) / 3), '?');
    vtkBase64Utilities::Encode(in.data(), static_cast<unsigned long>(in.size()),
                               reinterpret_cast<unsigned char*>(expected.data()));
    EXPECT_EQ(encoded(in), expected) << "length " << len;
  }
  std::string expected(4 * 86, '?');
  vtkBase64Utilities::Encode(bytes.data(), 256, reinterpret_cast<unsigned char*>(expected.data()));
  EXPECT_EQ(encoded(bytes), expected);
}

}  // namespace
}  // namespace blayer

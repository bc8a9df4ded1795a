// A .vtp whose compressed-data header claims more than the file can hold is refused
// before VTK allocates the claim, naming the array, in every layout VTK writes: inline
// base64, appended raw and appended base64, with 32- and 64-bit header words (under
// AddressSanitizer VTK's allocation of such a claim would be a sanitizer report, not an
// exception); so is one whose points do not have 3 components.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdint>
#include <string>

#include "blayer/core/errors.h"
#include "blayer/io/read_surface.h"

namespace blayer {
namespace {

struct Layout {
  const char* name;
  int data_mode;     // vtkXMLWriter::Binary (inline) or ::Appended
  bool encode;       // appended data as base64
  bool words_of_64;  // header_type UInt64, else UInt32
};

const Layout kLayouts[] = {
    {"inline base64, UInt32 header", vtkXMLWriter::Binary, true, false},
    {"inline base64, UInt64 header", vtkXMLWriter::Binary, true, true},
    {"appended raw, UInt64 header", vtkXMLWriter::Appended, false, true},
    {"appended raw, UInt32 header", vtkXMLWriter::Appended, false, false},
    {"appended base64, UInt32 header", vtkXMLWriter::Appended, true, false},
};

// A tetrahedron's surface written by VTK, zlib-compressed.
std::string tetra_vtp(const Layout& layout) {
  vtkNew<vtkPoints> points;
  for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) points->InsertNextPoint(p.data());
  vtkNew<vtkCellArray> triangles;
  for (const auto& t : {std::array<vtkIdType, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
    triangles->InsertNextCell(3, t.data());
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->WriteToOutputStringOn();
  writer->SetCompressorTypeToZLib();
  writer->SetDataMode(layout.data_mode);
  writer->SetEncodeAppendedData(layout.encode);
  if (layout.words_of_64)
    writer->SetHeaderTypeToUInt64();
  else
    writer->SetHeaderTypeToUInt32();
  writer->Write();
  return writer->GetOutputString();
}

const std::string kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string decode_base64(const std::string& chars) {
  std::string out;
  for (std::size_t i = 0; i + 4 <= chars.size(); i += 4) {
    std::uint32_t v = 0;
    int pads = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = chars[i + k];
      pads += c == '=';
      v = (v << 6) | (c == '=' ? 0u : static_cast<std::uint32_t>(kBase64.find(c)));
    }
    for (int k = 0; k < 3 - pads; ++k) out.push_back(static_cast<char>((v >> (16 - 8 * k)) & 255));
  }
  return out;
}

std::string encode_base64(const std::string& bytes) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out.push_back(k <= n ? kBase64[(v >> (18 - 6 * k)) & 63] : '=');
  }
  return out;
}

// The file with word `word` of the first array's compressed-data header (the points':
// the tetrahedron has no point data) set to `value`: 0 the block count, 1 the block
// size, 2 the last block's size, 3 the first block's compressed size.
std::string with_header_word(std::string vtp, const Layout& layout, int word, std::uint64_t value) {
  std::size_t at = 0;
  if (layout.data_mode == vtkXMLWriter::Binary) {
    at = vtp.find('>', vtp.find("<DataArray")) + 1;
    while (vtp[at] == ' ' || vtp[at] == '\n') ++at;
  } else {
    at = vtp.find('_', vtp.find("<AppendedData")) + 1;
  }
  const std::size_t w = layout.words_of_64 ? 8 : 4;
  const std::size_t header_bytes = 4 * w;  // one block: count, size, last size, one compressed size
  const bool base64 = layout.data_mode == vtkXMLWriter::Binary || layout.encode;
  const std::size_t chars = base64 ? 4 * ((header_bytes + 2) / 3) : header_bytes;
  std::string header = base64 ? decode_base64(vtp.substr(at, chars)) : vtp.substr(at, chars);
  for (std::size_t b = 0; b < w; ++b) header[word * w + b] = static_cast<char>((value >> (8 * b)) & 255);
  vtp.replace(at, chars, base64 ? encode_base64(header) : header);
  return vtp;
}

std::string read_error(const std::string& vtp) {
  try {
    parse_polygon_soup(vtp, "vtp", "t.vtp");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(VtpPrecheck, EveryLayoutVtkWritesIsReadBack) {
  for (const Layout& layout : kLayouts) {
    const PolygonSoup soup = parse_polygon_soup(tetra_vtp(layout), "vtp", "t.vtp");
    EXPECT_EQ(soup.points.size(), 4u) << layout.name;
    EXPECT_EQ(soup.faces.size(), 4u) << layout.name;
  }
}

TEST(VtpPrecheck, ABlockCountWhoseSizeTableTheFileCannotHoldIsRefusedNamingTheArray) {
  for (const Layout& layout : kLayouts) {
    const std::string msg = read_error(with_header_word(tetra_vtp(layout), layout, 0, 1000000000));
    EXPECT_EQ(msg.rfind("t.vtp: cannot parse the .vtp file: the compressed-data header of DataArray \"Points\" claims "
                        "1000000000 blocks",
                        0),
              0u)
        << layout.name << ": " << msg;
  }
}

TEST(VtpPrecheck, ABlockLargerThanTheAllowanceIsRefused) {
  for (const Layout& layout : kLayouts) {
    const std::uint64_t huge = layout.words_of_64 ? 4000000000000000000ull : 4000000000ull;
    for (int word : {1, 2}) {
      const std::string msg = read_error(with_header_word(tetra_vtp(layout), layout, word, huge));
      EXPECT_NE(msg.find("claims blocks of " + std::to_string(huge) + " bytes decompressed"), std::string::npos)
          << layout.name << ", word " << word << ": " << msg;
    }
  }
}

// VTK divides offsets by the block size, and takes a block past its table of blocks
// when the last block is larger than the others or there are no others.
TEST(VtpPrecheck, AZeroBlockSizeOrALastBlockLargerThanTheOthersOrAloneIsRefused) {
  for (const Layout& layout : kLayouts) {
    EXPECT_NE(read_error(with_header_word(tetra_vtp(layout), layout, 0, 0)).find("claims 0 blocks but a last block of"),
              std::string::npos)
        << layout.name;
    EXPECT_NE(read_error(with_header_word(tetra_vtp(layout), layout, 1, 0)).find("claims 1 blocks of 0 bytes"),
              std::string::npos)
        << layout.name;
    // The tetrahedron's points fit one block of 32768 bytes (the size VTK writes): a
    // last block of 32769 bytes is larger.
    EXPECT_NE(read_error(with_header_word(tetra_vtp(layout), layout, 2, 32769))
                  .find("claims a last block of 32769 bytes, larger than its blocks of 32768 bytes"),
              std::string::npos)
        << layout.name;
  }
}

TEST(VtpPrecheck, CompressedBlocksLongerThanTheRestOfTheFileAreRefused) {
  for (const Layout& layout : kLayouts) {
    const std::string msg = read_error(with_header_word(tetra_vtp(layout), layout, 3, 1000000));
    EXPECT_NE(msg.find("claims 1000000 bytes of compressed blocks"), std::string::npos) << layout.name << ": " << msg;
  }
}

// VTK reads an array that has an offset from the appended data even when its format
// is not "appended".
TEST(VtpPrecheck, AnArrayWithAnOffsetIsCheckedInTheAppendedDataWhateverItsFormatSays) {
  const Layout& raw = kLayouts[2];
  std::string vtp = with_header_word(tetra_vtp(raw), raw, 0, 1000000000);
  const std::size_t at = vtp.find("format=\"appended\"");
  ASSERT_NE(at, std::string::npos);
  vtp.replace(at, 17, "format=\"appen/ed\"");
  EXPECT_NE(read_error(vtp).find("DataArray \"Points\" claims 1000000000 blocks"), std::string::npos)
      << read_error(vtp);
}

// The check reads the header where VTK does: rewriting a word with its own value
// changes nothing, so the helper above patches the header, not some other bytes.
TEST(VtpPrecheck, RewritingAHeaderWordWithItsOwnValueStillReads) {
  for (const Layout& layout : kLayouts) {
    const std::string vtp = tetra_vtp(layout);
    EXPECT_EQ(read_error(with_header_word(vtp, layout, 0, 1)), "") << layout.name;
  }
}

// VTK 9.1 reads such points and fails after taking objects it never frees.
TEST(VtpPrecheck, PointsWithoutThreeComponentsAreRefusedNamingTheCount) {
  std::string vtp = tetra_vtp(kLayouts[2]);
  const std::size_t at = vtp.find("NumberOfComponents=\"3\"", vtp.find("<Points>"));
  ASSERT_NE(at, std::string::npos);
  vtp[at + std::string("NumberOfComponents=\"").size()] = '2';
  EXPECT_EQ(read_error(vtp),
            "t.vtp: cannot parse the .vtp file: the points' DataArray \"Points\" has 2 components per point, not 3");
}

}  // namespace
}  // namespace blayer

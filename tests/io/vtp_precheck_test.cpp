// A .vtp whose compressed-data header claims more than the file can hold is refused
// before VTK allocates the claim, naming the array, in every layout VTK writes: inline
// base64, appended raw and appended base64, with 32- and 64-bit header words, in either
// byte order, on arrays of one block and of several (under
// AddressSanitizer VTK's allocation of such a claim would be a sanitizer report, not an
// exception); so is one whose points do not have 3 components.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "blayer/core/errors.h"
#include "blayer/io/read_surface.h"

namespace blayer {
namespace {

struct Layout {
  const char* name;
  int data_mode;     // vtkXMLWriter::Binary (inline) or ::Appended
  bool encode;       // appended data as base64
  bool words_of_64;  // header_type UInt64, else UInt32
  bool big_endian = false;
};

const Layout kLayouts[] = {
    {"inline base64, UInt32 header", vtkXMLWriter::Binary, true, false},
    {"inline base64, UInt64 header", vtkXMLWriter::Binary, true, true},
    {"appended raw, UInt64 header", vtkXMLWriter::Appended, false, true},
    {"appended raw, UInt32 header", vtkXMLWriter::Appended, false, false},
    {"appended base64, UInt32 header", vtkXMLWriter::Appended, true, false},
    {"appended base64, UInt64 header", vtkXMLWriter::Appended, true, true},
    {"appended raw, UInt64 header, big endian", vtkXMLWriter::Appended, false, true, true},
    {"inline base64, UInt32 header, big endian", vtkXMLWriter::Binary, true, false, true},
};

std::string write_vtp(vtkPolyData* poly, const Layout& layout) {
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
  if (layout.big_endian)
    writer->SetByteOrderToBigEndian();
  else
    writer->SetByteOrderToLittleEndian();
  writer->Write();
  return writer->GetOutputString();
}

// A tetrahedron's surface written by VTK, zlib-compressed: every array one block.
std::string tetra_vtp(const Layout& layout) {
  vtkNew<vtkPoints> points;
  for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) points->InsertNextPoint(p.data());
  vtkNew<vtkCellArray> triangles;
  for (const auto& t : {std::array<vtkIdType, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
    triangles->InsertNextCell(3, t.data());
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  return write_vtp(poly, layout);
}

// 3000 points (36,000 bytes of floats: two blocks of VTK's 32,768) and a strip of 2998
// triangles over them, in a tetrahedron's place for the headers of several blocks.
constexpr int kStripPoints = 3000;
std::string strip_vtp(const Layout& layout) {
  vtkNew<vtkPoints> points;
  for (int i = 0; i < kStripPoints; ++i) points->InsertNextPoint(0.5 * i, i % 2, 0.25 * (i % 3));
  vtkNew<vtkCellArray> triangles;
  for (vtkIdType i = 0; i + 2 < kStripPoints; ++i) {
    const vtkIdType t[3] = {i, i + 1, i + 2};
    triangles->InsertNextCell(3, t);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  return write_vtp(poly, layout);
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

// Where the first array's compressed-data header lies (the points': neither test surface
// has point data), and how it is stored.
struct HeaderSpan {
  std::size_t at = 0;      // its first character
  bool base64 = false;
  std::size_t word = 4;    // bytes per word
  bool big_endian = false;
  std::size_t n_words = 0; // 3 + the number of blocks
  std::size_t chars() const {  // characters the header takes in the file
    return base64 ? 4 * ((n_words * word + 2) / 3) : n_words * word;
  }
};

std::string decode_span(const std::string& vtp, std::size_t at, std::size_t chars, bool base64) {
  return base64 ? decode_base64(vtp.substr(at, chars)) : vtp.substr(at, chars);
}

std::uint64_t word_of(const std::string& header, const HeaderSpan& h, std::size_t i) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < h.word; ++b)
    v = (v << 8) | static_cast<unsigned char>(header[i * h.word + (h.big_endian ? b : h.word - 1 - b)]);
  return v;
}

HeaderSpan first_header(const std::string& vtp, const Layout& layout) {
  HeaderSpan h;
  h.word = layout.words_of_64 ? 8 : 4;
  h.big_endian = layout.big_endian;
  h.base64 = layout.data_mode == vtkXMLWriter::Binary || layout.encode;
  if (layout.data_mode == vtkXMLWriter::Binary) {
    h.at = vtp.find('>', vtp.find("<DataArray")) + 1;
    while (vtp[h.at] == ' ' || vtp[h.at] == '\n') ++h.at;
  } else {
    h.at = vtp.find('_', vtp.find("<AppendedData")) + 1;
  }
  h.n_words = 3;  // 12 or 24 bytes: whole base64 groups
  const std::uint64_t blocks = word_of(decode_span(vtp, h.at, h.chars(), h.base64), h, 0);
  h.n_words = 3 + blocks;
  return h;
}

// The first array's header words.
std::vector<std::uint64_t> header_words(const std::string& vtp, const Layout& layout) {
  const HeaderSpan h = first_header(vtp, layout);
  const std::string header = decode_span(vtp, h.at, h.chars(), h.base64);
  std::vector<std::uint64_t> words;
  for (std::size_t i = 0; i < h.n_words; ++i) words.push_back(word_of(header, h, i));
  return words;
}

// The file with word `word` of the first array's compressed-data header set to
// `value`: 0 the block count, 1 the block size, 2 the last block's size, 3 + i block
// i's compressed size.
std::string with_header_word(std::string vtp, const Layout& layout, std::size_t word, std::uint64_t value) {
  const HeaderSpan h = first_header(vtp, layout);
  std::string header = decode_span(vtp, h.at, h.chars(), h.base64);
  for (std::size_t b = 0; b < h.word; ++b)
    header[word * h.word + (h.big_endian ? h.word - 1 - b : b)] = static_cast<char>((value >> (8 * b)) & 255);
  vtp.replace(h.at, h.chars(), h.base64 ? encode_base64(header) : header);
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

// The file's text with the first `from` after `after` replaced by `to`.
std::string replaced(std::string s, const std::string& after, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from, s.find(after));
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

// VTK reads appended data as base64 unless their encoding is "raw".
TEST(VtpPrecheck, AppendedDataWithoutAnEncodingAreCheckedAsBase64) {
  const Layout& b64 = kLayouts[4];
  const std::string vtp = replaced(with_header_word(tetra_vtp(b64), b64, 0, 1000000000), "<AppendedData",
                                   "encoding=\"base64\"", "");
  EXPECT_NE(read_error(vtp).find("claims 1000000000 blocks"), std::string::npos) << read_error(vtp);
}

// VTK reads an array with an offset attribute from the appended data, at 0 when the
// offset does not parse, and whatever its tag is named.
TEST(VtpPrecheck, AnOffsetThatDoesNotParseIsReadAsZero) {
  const Layout& raw = kLayouts[2];
  const std::string vtp =
      replaced(with_header_word(tetra_vtp(raw), raw, 0, 1000000000), "<Points>", "offset=\"0\"", "offset=\"x\"");
  EXPECT_NE(read_error(vtp).find("claims 1000000000 blocks"), std::string::npos) << read_error(vtp);
}

TEST(VtpPrecheck, AnArrayUnderAnotherTagNameIsCheckedToo) {
  const Layout& raw = kLayouts[2];
  std::string vtp = with_header_word(tetra_vtp(raw), raw, 0, 1000000000);
  vtp = replaced(vtp, "<Points>", "<DataArray", "<DataArrax");
  const std::size_t tag_end = vtp.find('>', vtp.find("<DataArrax"));
  if (vtp[tag_end - 1] != '/') vtp = replaced(vtp, "<DataArrax", "</DataArray>", "</DataArrax>");
  EXPECT_NE(read_error(vtp).find("DataArrax \"Points\" claims 1000000000 blocks"), std::string::npos)
      << read_error(vtp);
}

// The helpers read and write the header where VTK does: every word written back with
// its own value leaves a file that reads, on one block and on several.
TEST(VtpPrecheck, EveryHeaderWordWrittenBackWithItsOwnValueStillReads) {
  for (const Layout& layout : kLayouts)
    for (const std::string& vtp : {tetra_vtp(layout), strip_vtp(layout)}) {
      const std::vector<std::uint64_t> words = header_words(vtp, layout);
      ASSERT_GE(words.size(), 4u) << layout.name;
      for (std::size_t w = 0; w < words.size(); ++w)
        EXPECT_EQ(read_error(with_header_word(vtp, layout, w, words[w])), "") << layout.name << ", word " << w;
    }
}

TEST(VtpPrecheck, ThePointsOfSeveralBlocksReadBackAndTheirLastBlocksSizeIsChecked) {
  for (const Layout& layout : kLayouts) {
    const std::string vtp = strip_vtp(layout);
    const PolygonSoup soup = parse_polygon_soup(vtp, "vtp", "t.vtp");
    EXPECT_EQ(soup.points.size(), static_cast<std::size_t>(kStripPoints)) << layout.name;
    EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(kStripPoints - 2)) << layout.name;
    const std::vector<std::uint64_t> words = header_words(vtp, layout);
    ASSERT_EQ(words[0], 2u) << layout.name;  // 36,000 bytes in blocks of 32,768
    EXPECT_NE(read_error(with_header_word(vtp, layout, 4, 1000000)).find("bytes of compressed blocks"),
              std::string::npos)
        << layout.name;
  }
}

// A tetrahedron in ASCII with `point_data` inside PointData and `polys` as its
// NumberOfPolys.
std::string ascii_tetra(const std::string& point_data, const std::string& polys = "4") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"" + polys + "\">\n<PointData>" + point_data +
         "</PointData>\n<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
         "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Polys>"
         "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 2 1 0 1 3 1 2 3 0 3 2</DataArray>"
         "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6 9 12</DataArray></Polys>\n"
         "</Piece></PolyData></VTKFile>\n";
}

// VTK sizes the points and the point- and cell-data arrays from the element counts
// before it reads them; VTK 9.1 leaks what it made when that allocation fails.
TEST(VtpPrecheck, CountsWhoseArraysExceedTheAllowanceAreRefusedNamingThem) {
  EXPECT_EQ(read_error(ascii_tetra("")), "");
  EXPECT_EQ(read_error(ascii_tetra("<DataArray type=\"Float64\" Name=\"p\" NumberOfComponents=\"2\" "
                                   "format=\"ascii\">1 2 3 4 5 6 7 8</DataArray>")),
            "");
  const std::string wide = read_error(ascii_tetra(
      "<DataArray type=\"Float64\" Name=\"p\" NumberOfComponents=\"100000000\" format=\"ascii\">1</DataArray>"));
  EXPECT_NE(wide.find("DataArray \"p\" of 100000000 components per point needs 3200000000 bytes"), std::string::npos)
      << wide;
  const std::string polys = read_error(ascii_tetra("", "1000000000"));
  EXPECT_NE(polys.find("the pieces claim NumberOfPolys=1000000000 in all, 4000000004 bytes or more"),
            std::string::npos)
      << polys;
}

// VTK sizes its arrays for all the pieces together: counts each within the allowance
// are refused when their sum is not.
TEST(VtpPrecheck, CountsAreSummedOverThePieces) {
  const std::string one = ascii_tetra("", "400000000");
  EXPECT_EQ(read_error(one).find("NumberOfPolys="), std::string::npos) << read_error(one);
  const std::size_t piece = one.find("<Piece"), end = one.find("</Piece>") + 8;
  std::string two = one;
  two.insert(end, one.substr(piece, end - piece));
  const std::string error = read_error(two);
  EXPECT_NE(error.find("the pieces claim NumberOfPolys=800000000 in all"), std::string::npos) << error;
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

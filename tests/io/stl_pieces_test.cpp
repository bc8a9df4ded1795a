// Large ASCII STL files are read in pieces side by side (stl_reader.cpp); the soup must
// be the serial parser's, and a faulty file must get the serial parser's message.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <optional>
#include <string>

#include "blayer/core/errors.h"
#include "surface_parsers.h"

namespace blayer {
namespace {

// A facet of a wavy strip, written in one of several spellings that the grammar allows:
// upper-case keywords, leading blanks, CRLF endings, blank lines, no facet normal.
void add_facet(std::string* s, int i, int j, bool flip) {
  auto x = [](int a) { return std::to_string(0.001 * a); };
  auto z = [](int a, int b) { return std::to_string(0.01 * std::sin(0.1 * a + 0.2 * b)); };
  const std::string eol = (i + j) % 7 == 0 ? "\r\n" : "\n";
  const std::string ind = (i % 3 == 0) ? "  " : "";
  *s += ind + ((i % 5 == 0) ? "FACET NORMAL 0 0 1" : (i % 5 == 1) ? "facet" : "facet normal 0 0 1") + eol;
  if (j % 11 == 0) *s += "\n";
  *s += ind + "  outer loop" + eol;
  const int a[3][2] = {{i, j}, {i + 1, j + (flip ? 1 : 0)}, {i + (flip ? 0 : 1), j + 1}};
  for (const auto& c : a) *s += ind + "    vertex " + x(c[0]) + " " + x(c[1]) + " " + z(c[0], c[1]) + eol;
  *s += ind + "  endloop" + eol + ind + "endfacet" + eol;
}

// About 3 MB: three solids, the last one without its 'endsolid', and one facet with two
// corners at one point (dropped, with a note).
std::string large_ascii_stl() {
  std::string s;
  for (int solid = 0; solid < 3; ++solid) {
    s += "solid part" + std::to_string(solid) + "\n";
    for (int i = 0; i < 60; ++i)
      for (int j = 0; j < 60; ++j) {
        add_facet(&s, i + 70 * solid, j, false);
        add_facet(&s, i + 70 * solid, j, true);
      }
    if (solid == 1) s += "facet\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n";
    if (solid < 2) s += "endsolid part" + std::to_string(solid) + "\n";
  }
  return s;
}

void expect_same_soup(const PolygonSoup& a, const PolygonSoup& b) {
  EXPECT_EQ(a.points, b.points);
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f) ASSERT_EQ(a.faces[f], b.faces[f]) << f;
  EXPECT_EQ(a.notes, b.notes);
}

std::string serial_error(const std::string& text) {
  try {
    detail::parse_ascii_stl_serially(text, "big.stl");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StlInPieces, ALargeFileReadInPiecesIsTheSerialSoup) {
  const std::string text = large_ascii_stl();
  ASSERT_GT(text.size(), 2u << 20);
  const std::optional<PolygonSoup> pieces = detail::parse_ascii_stl_in_pieces(text);
  ASSERT_TRUE(pieces.has_value()) << "a well-formed file was refused";
  const PolygonSoup serial = detail::parse_ascii_stl_serially(text, "big.stl");
  EXPECT_EQ(serial.faces.size(), 3u * 60 * 60 * 2);
  ASSERT_EQ(serial.notes.size(), 1u);
  expect_same_soup(*pieces, serial);
  expect_same_soup(detail::parse_stl(text, "big.stl"), serial);
}

// Faults deep inside the file, where a piece meets them, or where pieces join: each is
// refused by the pieces and gets the serial parser's message (with its line number).
// The start of the first line at or after the line following byte `from` whose first
// word is "facet" in any case: where the reader starts a piece (stl_reader.cpp).
std::size_t piece_start_after(const std::string& text, std::size_t from) {
  for (std::size_t p = text.find('\n', from) + 1; p < text.size(); p = text.find('\n', p) + 1) {
    const std::size_t word = text.find_first_not_of(" \t", p);
    std::string head = text.substr(word, 5);
    for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (head == "facet") return p;
  }
  return text.size();
}

TEST(StlInPieces, AFaultAnywhereGetsTheSerialMessage) {
  const std::string good = large_ascii_stl();
  const std::size_t middle = good.find("facet", good.size() / 2);
  // Where the first piece ends: an 'endsolid' there leaves it whole and the next piece
  // starts inside no solid, which only the join of the pieces sees.
  const std::size_t join = piece_start_after(good, good.size() / 3);
  const std::size_t late = good.find("vertex", good.size() * 7 / 8);
  const std::string faulty[] = {
      good.substr(0, late) + "vertex 1 2\n" + good.substr(good.find('\n', late) + 1),     // a missing coordinate
      good.substr(0, late) + "vertex 1 2 1e40\n" + good.substr(good.find('\n', late) + 1),  // beyond float
      good.substr(0, middle) + "endsolid\n" + good.substr(middle),                        // facets outside a solid
      good.substr(0, middle) + "facet\nouter loop\nvertex 0 0 0\n" + good.substr(middle),   // a cut facet
      good.substr(0, middle) + "quad\n" + good.substr(middle),                            // not STL
      good + "endsolid part2\nfacet\n",                                                   // a facet after the end
      good.substr(0, join) + "endsolid\n" + good.substr(join),                            // the same at a join
  };
  for (const std::string& text : faulty) {
    EXPECT_FALSE(detail::parse_ascii_stl_in_pieces(text).has_value());
    const std::string expected = serial_error(text);
    ASSERT_FALSE(expected.empty()) << "the serial parser accepted a faulty file";
    try {
      detail::parse_stl(text, "big.stl");
      ADD_FAILURE() << "accepted: " << expected;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  }
}

TEST(StlInPieces, SmallFilesAreReadSerially) {
  std::string text = "solid s\n";
  add_facet(&text, 0, 0, false);
  text += "endsolid s\n";
  EXPECT_FALSE(detail::parse_ascii_stl_in_pieces(text).has_value());
  expect_same_soup(detail::parse_stl(text, "small.stl"), detail::parse_ascii_stl_serially(text, "small.stl"));
}

}  // namespace
}  // namespace blayer

// The inputs that real CAD exports and typos produce, run as a user would: each is
// refused with exit status 1, one "error:" message naming the file, the element and the
// problem, the same on every run, and no output file; or it is handled correctly.
#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>

#include "../io/temp_dir.h"
#include "../io/test_surfaces.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::append;
using testing::box;
using testing::off_text;
using testing::run_blayer;
using testing::TempDir;

// Every run here is small; anything slower than this is a hang.
constexpr int kHangSeconds = 20;

// Runs `blayer extrude FILE -o OUT.vtu EXTRA` and expects a clean refusal whose message
// contains every fragment; returns stderr.
std::string expect_refused(const TempDir& dir, const std::string& file, const std::vector<std::string>& fragments,
                           const std::string& extra = "") {
  const std::string out = dir.file("out.vtu");
  const auto r = run_blayer("extrude " + dir.file(file) + " -o " + out + " " + extra, dir.file(""), kHangSeconds);
  EXPECT_EQ(r.signal, 0) << file << " (killed: a crash or a hang)";
  EXPECT_EQ(r.status, 1) << file << "\n" << r.out << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  for (const std::string& f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in\n" << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  return r.err;
}

std::string cube_stl(const std::string& first_corner) {
  PolygonSoup c = box({0, 0, 0}, {1, 1, 1});
  std::string s = "solid cube\n";
  bool first = true;
  for (const auto& f : c.faces) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (int v : f) {
      const Vec3& p = c.points[v];
      s += "vertex " + (first ? first_corner : std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2])) + "\n";
      first = false;
    }
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid cube\n";
}

TEST(HostileInput, StlWithANonNumericCoordinateIsRefusedIdenticallyOnEveryRun) {
  TempDir dir;
  dir.write("inf.stl", cube_stl("inf 0 0"));
  const std::string first = expect_refused(dir, "inf.stl", {"inf.stl:4: facet 0, corner 0: 'inf' is not a finite number"});
  for (int run = 1; run < 8; ++run) EXPECT_EQ(expect_refused(dir, "inf.stl", {}), first) << "run " << run;
}

TEST(HostileInput, OffHeaderClaimingATrillionVerticesFailsAtOnceSayingWhatTheFileHolds) {
  TempDir dir;
  std::string text = off_text(box({0, 0, 0}, {1, 1, 1}));
  text.replace(text.find("8 12 0"), 6, "1000000000000 12 0");
  dir.write("claims.off", text);
  expect_refused(dir, "claims.off", {"claims.off:11: the header claims 1000000000000 vertices, the file holds 8"});
}

TEST(HostileInput, OffCoordinatesBeyondFloatRangeAreReadAsDoublesAndHugeOnesRefusedAsSuch) {
  TempDir dir;
  dir.write("e40.off", off_text(box({0, 0, 0}, {1e40, 1e40, 1e40})));
  const auto r = run_blayer("extrude " + dir.file("e40.off") + " -o " + dir.file("e40.vtu"), dir.file(""), kHangSeconds);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("e40.vtu")));
  dir.write("e300.off", off_text(box({0, 0, 0}, {1e300, 1, 1})));
  const std::string err = expect_refused(dir, "e300.off", {"coordinates too large to compute with", "vertex 1 at (1e+300, 0, 0)"});
  EXPECT_EQ(err.find("refers to vertex"), std::string::npos) << err;
}

TEST(HostileInput, ASurfacePassingThroughItselfIsRefusedNamingTheTriangles) {
  TempDir dir;
  PolygonSoup folded = box({0, 0, 0}, {1, 1, 1});
  folded.points[6] = {-0.5, 0.5, 0.5};
  dir.write("folded.off", off_text(folded));
  expect_refused(dir, "folded.off", {"self-intersections", "triangle 2 [vertices 4, 5, 6] and triangle 10 [vertices 3, 0, 4]"});
}

TEST(HostileInput, TwoOverlappingBodiesAreRefusedNamingBothComponents) {
  TempDir dir;
  PolygonSoup s = box({0, 0, 0}, {1, 1, 1});
  append(&s, box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  dir.write("overlap.off", off_text(s));
  expect_refused(dir, "overlap.off", {"intersecting components", "components 0 and 1"});
}

// The layers of a cavity's wall grow into the cavity: every column top of the inner
// box's vertices lies inside the inner box (one column per point, so that envelope
// points 8..15 are the inner box's).
TEST(HostileInput, ACavityInsideABodyGetsItsLayersInsideTheCavity) {
  TempDir dir;
  PolygonSoup s = box({0, 0, 0}, {3, 3, 3});
  append(&s, box({1, 1, 1}, {2, 2, 2}));
  dir.write("hollow.off", off_text(s));
  const auto r = run_blayer("extrude " + dir.file("hollow.off") + " -o " + dir.file("h.vtu") + " --layers 2" +
                                " --fan-angle 0 --first-height 0.01 --envelope " + dir.file("env.vtp"),
                            dir.file(""), kHangSeconds);
  ASSERT_EQ(r.status, 0) << r.err;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(dir.file("env.vtp").c_str());
  reader->Update();
  vtkPolyData* env = reader->GetOutput();
  ASSERT_EQ(env->GetNumberOfPoints(), 16);
  for (vtkIdType v = 8; v < 16; ++v) {
    double p[3];
    env->GetPoint(v, p);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(p[k], 1.0) << "column top of inner vertex " << v << " left the cavity";
      EXPECT_LT(p[k], 2.0) << "column top of inner vertex " << v << " left the cavity";
    }
  }
}

TEST(HostileInput, OptionsOutOfRangeAreRefusedNamingTheOptionAsTyped) {
  TempDir dir;
  dir.write("t.off", testing::tetra_off());
  expect_refused(dir, "t.off", {"--proximity-safety", "(0, 0.5]", "'0.8'"}, "--proximity-safety 0.8");
  expect_refused(dir, "t.off", {"--growth-ratio", "> 0", "'0'"}, "--growth-ratio 0");
  expect_refused(dir, "t.off", {"--threads", ">= 0", "'-3'"}, "--threads -3");
  dir.write("case.toml", "input = \"t.off\"\nproximity-safety = 0.8\n");
  const auto r = run_blayer("extrude --config " + dir.file("case.toml") + " -o " + dir.file("out.vtu"), dir.file(""));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("case.toml: key 'proximity-safety'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("proximity_safety"), std::string::npos) << r.err;
  // The value is quoted as written, not as the 17 digits of the nearest double.
  EXPECT_NE(r.err.find("(got '0.8')"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace blayer

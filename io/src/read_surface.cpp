#include "blayer/io/read_surface.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#include <zlib.h>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "blayer/core/errors.h"
#include "blayer/io/atomic_file.h"

namespace blayer {

namespace {

namespace fs = std::filesystem;
using OpenMesh::IO::BaseImporter;

// Receives OpenMesh's parsed vertices and faces as they are in the file. Going through
// an importer rather than an OpenMesh mesh keeps non-manifold and badly oriented faces
// (a mesh kernel would drop or re-wire them before they could be reported) and keeps
// double coordinates when the reader provides them.
class SoupImporter : public BaseImporter {
 public:
  explicit SoupImporter(PolygonSoup* soup) : soup_(soup) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return push({p[0], p[1], p[2]});
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override { return push({p[0], p[1], p[2]}); }
  OpenMesh::VertexHandle add_vertex() override { return push({0.0, 0.0, 0.0}); }
  OpenMesh::FaceHandle add_face(const VHandles& idx) override {
    std::vector<int> f;
    f.reserve(idx.size());
    for (const auto& vh : idx) f.push_back(vh.idx());
    soup_->faces.push_back(std::move(f));
    return OpenMesh::FaceHandle(static_cast<int>(soup_->faces.size()) - 1);
  }
  void set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& p) override {
    if (vh.idx() >= 0 && vh.idx() < static_cast<int>(soup_->points.size()))
      soup_->points[vh.idx()] = {p[0], p[1], p[2]};
  }
  size_t n_vertices() const override { return soup_->points.size(); }
  size_t n_faces() const override { return soup_->faces.size(); }
  size_t n_edges() const override { return 0; }

  // Attributes blayer does not use.
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

 private:
  OpenMesh::VertexHandle push(const Vec3& p) {
    soup_->points.push_back(p);
    return OpenMesh::VertexHandle(static_cast<int>(soup_->points.size()) - 1);
  }
  PolygonSoup* soup_;
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Decompresses a .gz file into a temporary file beside the system's temp dir and
// returns its path; the caller removes it.
std::string gunzip_to_temp(const std::string& path, const std::string& inner_ext) {
  gzFile in = gzopen(path.c_str(), "rb");
  if (!in) throw InputError(path + ": cannot open file");
  const std::string tmp = unique_temp_path(fs::temp_directory_path().string() + "/blayer-input", "." + inner_ext);
  std::ofstream out(tmp, std::ios::binary);
  char buf[1 << 16];
  int n = 0;
  while ((n = gzread(in, buf, sizeof buf)) > 0) out.write(buf, n);
  const bool failed = n < 0 || !out;
  gzclose(in);
  out.close();
  if (failed) {
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot decompress (corrupt gzip data)");
  }
  return tmp;
}

// OpenMesh's ASCII readers parse coordinates as float. For the ASCII formats whose
// vertex lines are unambiguous (plain OFF, OBJ) the coordinates are read again as
// double, in file order; the count must match what OpenMesh read, else its values stay.
// STL is float by definition (binary) or merged by float keys (ASCII), and PLY keeps
// OpenMesh's values.
bool reread_double_coordinates(const std::string& file, const std::string& fmt, std::vector<Vec3>* points) {
  std::ifstream in(file);
  std::vector<Vec3> pts;
  pts.reserve(points->size());
  std::string line;
  auto parse3 = [](const char* c, Vec3* out) {
    char* end = nullptr;
    for (int k = 0; k < 3; ++k) {
      (*out)[k] = std::strtod(c, &end);
      if (end == c) return false;
      c = end;
    }
    return true;
  };
  if (fmt == "obj") {
    while (std::getline(in, line)) {
      if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
      Vec3 p;
      if (!parse3(line.c_str() + 2, &p)) return false;
      pts.push_back(p);
    }
  } else if (fmt == "off") {
    auto next_data_line = [&]() {
      while (std::getline(in, line)) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first != std::string::npos && line[first] != '#') return true;
      }
      return false;
    };
    if (!next_data_line() || line.rfind("OFF", 0) != 0) return false;
    std::string counts = line.substr(3);
    if (counts.find_first_not_of(" \t\r") == std::string::npos) {
      if (!next_data_line()) return false;
      counts = line;
    }
    const long nv = std::strtol(counts.c_str(), nullptr, 10);
    if (nv != static_cast<long>(points->size())) return false;
    for (long i = 0; i < nv; ++i) {
      Vec3 p;
      if (!next_data_line() || !parse3(line.c_str(), &p)) return false;
      pts.push_back(p);
    }
  } else {
    return false;
  }
  if (pts.size() != points->size()) return false;
  *points = std::move(pts);
  return true;
}

PolygonSoup read_with_openmesh(const std::string& file, const std::string& shown_name) {
  PolygonSoup soup;
  SoupImporter importer(&soup);
  OpenMesh::IO::Options opt;
  if (!OpenMesh::IO::IOManager().read(file, importer, opt))
    throw InputError(shown_name + ": cannot parse the file as " + surface_format(shown_name));
  if (!opt.check(OpenMesh::IO::Options::Binary))
    reread_double_coordinates(file, surface_format(shown_name), &soup.points);
  return soup;
}

PolygonSoup read_with_vtk(const std::string& file, const std::string& shown_name, bool xml) {
  vtkSmartPointer<vtkPolyData> poly;
  if (xml) {
    vtkNew<vtkXMLPolyDataReader> r;
    if (!r->CanReadFile(file.c_str())) throw InputError(shown_name + ": not a VTK XML PolyData (.vtp) file");
    r->SetFileName(file.c_str());
    r->Update();
    if (r->GetErrorCode() != 0) throw InputError(shown_name + ": cannot parse the .vtp file");
    poly = r->GetOutput();
  } else {
    vtkNew<vtkPolyDataReader> r;
    r->SetFileName(file.c_str());
    if (!r->IsFilePolyData()) throw InputError(shown_name + ": not a legacy VTK PolyData file");
    r->Update();
    poly = r->GetOutput();
  }
  if (!poly) throw InputError(shown_name + ": no PolyData in file");
  PolygonSoup soup;
  const vtkIdType np = poly->GetNumberOfPoints();
  soup.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i) poly->GetPoint(i, soup.points[i].data());
  if (poly->GetNumberOfStrips() > 0)
    throw InputError(shown_name + ": triangle strips are not supported; convert them to triangles");
  vtkCellArray* polys = poly->GetPolys();
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);) soup.faces.emplace_back(ids, ids + n);
  return soup;
}

}  // namespace

std::string surface_format(const std::string& path) {
  std::string name = lower(fs::path(path).filename().string());
  if (ends_with(name, ".gz")) name.resize(name.size() - 3);
  const auto dot = name.rfind('.');
  return dot == std::string::npos ? std::string() : name.substr(dot + 1);
}

PolygonSoup read_polygon_soup(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": no such file");
  if (fs::file_size(path, ec) == 0) throw InputError(path + ": the file is empty");
  const std::string fmt = surface_format(path);
  const bool gz = ends_with(lower(path), ".gz");
  const bool vtk_xml = fmt == "vtp", vtk_legacy = fmt == "vtk";
  const bool openmesh = fmt == "stl" || fmt == "obj" || fmt == "off" || fmt == "ply";
  if (!vtk_xml && !vtk_legacy && !openmesh)
    throw InputError(path + ": unknown surface format '" + fmt + "' (expected stl, obj, off, ply, vtp or vtk)");

  std::string file = path;
  if (gz) file = gunzip_to_temp(path, fmt);
  struct Cleanup {
    std::string f;
    bool on;
    ~Cleanup() {
      if (on) std::remove(f.c_str());
    }
  } cleanup{file, gz};
  if (openmesh) return read_with_openmesh(file, path);
  return read_with_vtk(file, path, vtk_xml);
}

}  // namespace blayer

#include "blayer/io/cgns_writer.h"

#include <array>
#include <limits>
#include <vector>

#include "blayer/core/errors.h"
#include "cgns_library.h"

namespace blayer {

namespace {

// Every CGNS call goes through this: a non-zero status becomes an IoError.
class CgnsFile {
 public:
  CgnsFile(const std::string& path, const std::string& target)
      : cg(detail::cgns_library(target)), target_(target) {
    check(cg.open(path.c_str(), CG_MODE_WRITE, &fn_), "cannot create the file");
  }
  ~CgnsFile() {
    if (fn_ >= 0) cg.close(fn_);
  }
  CgnsFile(const CgnsFile&) = delete;
  CgnsFile& operator=(const CgnsFile&) = delete;

  int fn() const { return fn_; }
  void check(int status, const char* what) const {
    if (status != CG_OK) throw IoError(target_ + ": " + what + " (CGNS: " + cg.get_error() + ")");
  }
  void close() {
    const int status = cg.close(fn_);
    fn_ = -1;
    check(status, "cannot finish the file");
  }

  const detail::CgnsLibrary& cg;

 private:
  std::string target_;
  int fn_ = -1;
};

struct VolumeSection {
  CellType type;
  CGNS_ENUMT(ElementType_t) cgns_type;
  const char* name;
  std::array<int, 8> from_vtk;  // CGNS node k is VTK corner from_vtk[k]
};

const std::array<VolumeSection, 4> kVolumeSections = {{
    {CellType::kTet, CGNS_ENUMV(TETRA_4), "Tetrahedra", {0, 1, 2, 3}},
    {CellType::kPyramid, CGNS_ENUMV(PYRA_5), "Pyramids", {0, 1, 2, 3, 4}},
    {CellType::kWedge, CGNS_ENUMV(PENTA_6), "Prisms", {0, 2, 1, 3, 5, 4}},
    {CellType::kHex, CGNS_ENUMV(HEXA_8), "Hexahedra", {0, 1, 2, 3, 4, 5, 6, 7}},
}};

CGNS_ENUMT(BCType_t) bc_type(PatchKind k) {
  switch (k) {
    case PatchKind::kWall: return CGNS_ENUMV(BCWall);
    case PatchKind::kFarfield: return CGNS_ENUMV(BCFarfield);
    case PatchKind::kSymmetry: return CGNS_ENUMV(BCSymmetryPlane);
    case PatchKind::kOpen: return CGNS_ENUMV(BCGeneral);
  }
  return CGNS_ENUMV(BCGeneral);
}

void check_size_limits(const SolverMesh& m, const std::string& target) {
  const std::size_t limit = static_cast<std::size_t>(std::numeric_limits<cgsize_t>::max());
  auto refuse = [&](const std::string& what, std::size_t n) {
    throw IoError(target + ": " + what + " (" + std::to_string(n) +
                  ") exceeds the CGNS library's limit of 2^31-1 (it was built with 32-bit sizes); "
                  "write OpenFOAM, SU2 or Gmsh MSH instead");
  };
  if (m.cells.points.size() > limit) refuse("the number of points", m.cells.points.size());
  if (m.cells.n_cells() + m.n_boundary_faces() > limit) refuse("the number of elements", m.cells.n_cells() + m.n_boundary_faces());
  for (const VolumeSection& s : kVolumeSections)
    if (m.n_cells_of(s.type) * corner_count(s.type) > limit)
      refuse(std::string("the connectivity of the ") + s.name, m.n_cells_of(s.type) * corner_count(s.type));
  if (5 * m.n_boundary_faces() > limit) refuse("the boundary connectivity", 5 * m.n_boundary_faces());
}

void write_coordinates(const CgnsFile& f, int base, int zone, const SolverMesh& m) {
  const char* names[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  std::vector<double> xyz(m.cells.points.size());
  for (int d = 0; d < 3; ++d) {
    for (std::size_t p = 0; p < xyz.size(); ++p) xyz[p] = m.cells.points[p][d];
    int c = 0;
    f.check(f.cg.coord_write(f.fn(), base, zone, CGNS_ENUMV(RealDouble), names[d], xyz.data(), &c),
            "cannot write the coordinates");
    // A length: exponent 1 of mass, length, time, temperature, angle = (0, 1, 0, 0, 0).
    const double length_exponents[5] = {0, 1, 0, 0, 0};
    f.check(f.cg.go_to(f.fn(), base, "Zone_t", zone, "GridCoordinates_t", 1, "DataArray_t", c, "end"),
            "cannot reach a coordinate array");
    f.check(f.cg.exponents_write(CGNS_ENUMV(RealDouble), length_exponents), "cannot write the coordinates' dimensions");
  }
}

// Writes the volume sections; returns the next free element number.
cgsize_t write_volume_sections(const CgnsFile& f, int base, int zone, const SolverMesh& m) {
  cgsize_t next = 1;
  std::vector<cgsize_t> conn;
  for (const VolumeSection& s : kVolumeSections) {
    const int n = corner_count(s.type);
    conn.clear();
    for (std::size_t c = 0; c < m.cells.n_cells(); ++c) {
      if (m.cells.cell_types[c] != s.type) continue;
      const PointId* nodes = m.cells.cell_nodes(c);
      for (int k = 0; k < n; ++k) conn.push_back(static_cast<cgsize_t>(nodes[s.from_vtk[k]] + 1));
    }
    if (conn.empty()) continue;
    const cgsize_t count = static_cast<cgsize_t>(conn.size() / n);
    int section = 0;
    f.check(f.cg.section_write(f.fn(), base, zone, s.name, s.cgns_type, next, next + count - 1, 0, conn.data(), &section),
            "cannot write a cell section");
    next += count;
  }
  return next;
}

// One element section of a patch's faces with n nodes (3 or 4), numbered from first.
// Returns the number of faces written.
cgsize_t write_face_section(const CgnsFile& f, int base, int zone, const SolverMesh& m, const BoundaryPatch& p,
                            int n, const std::string& name, cgsize_t first) {
  std::vector<cgsize_t> conn;
  for (std::size_t i = p.start; i < p.start + p.size; ++i)
    if (m.faces.n_nodes[i] == n)
      for (int k = 0; k < n; ++k) conn.push_back(static_cast<cgsize_t>(m.faces.nodes[i][k] + 1));
  const cgsize_t count = static_cast<cgsize_t>(conn.size() / n);
  if (count == 0) return 0;
  int section = 0;
  f.check(f.cg.section_write(f.fn(), base, zone, name.c_str(), n == 3 ? CGNS_ENUMV(TRI_3) : CGNS_ENUMV(QUAD_4), first,
                           first + count - 1, 0, conn.data(), &section),
          "cannot write a boundary section");
  return count;
}

void write_patch(const CgnsFile& f, int base, int zone, const SolverMesh& m, const BoundaryPatch& p, cgsize_t first) {
  // A patch of triangles and quads gets two sections with consecutive element numbers
  // (MIXED sections need the offsets array of newer CGNS files, which older readers lack).
  std::size_t n_tri = 0;
  for (std::size_t i = p.start; i < p.start + p.size; ++i) n_tri += m.faces.n_nodes[i] == 3;
  const bool both = n_tri > 0 && n_tri < p.size;
  const cgsize_t n_written = write_face_section(f, base, zone, m, p, 3, both ? p.name + "_tri" : p.name, first);
  write_face_section(f, base, zone, m, p, 4, both ? p.name + "_quad" : p.name, first + n_written);
  const cgsize_t last = first + static_cast<cgsize_t>(p.size) - 1;

  int family = 0, family_bc = 0;
  f.check(f.cg.family_write(f.fn(), base, p.name.c_str(), &family), "cannot write a family");
  f.check(f.cg.fambc_write(f.fn(), base, family, "FamBC", bc_type(p.kind), &family_bc), "cannot write a family BC");

  const cgsize_t range[2] = {first, last};
  int bc = 0;
  f.check(f.cg.boco_write(f.fn(), base, zone, p.name.c_str(), bc_type(p.kind), CGNS_ENUMV(PointRange), 2, range, &bc),
          "cannot write a boundary condition");
  f.check(f.cg.boco_gridlocation_write(f.fn(), base, zone, bc, CGNS_ENUMV(FaceCenter)),
          "cannot write a boundary condition's location");
  f.check(f.cg.go_to(f.fn(), base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", bc, "end"), "cannot reach a boundary condition");
  f.check(f.cg.famname_write(p.name.c_str()), "cannot write a boundary condition's family name");
}

}  // namespace

void write_cgns(const SolverMesh& mesh, const std::string& path, const std::string& target) {
  check_size_limits(mesh, target);
  CgnsFile f(path, target);
  int base = 0, zone = 0;
  f.check(f.cg.base_write(f.fn(), "blayer", 3, 3, &base), "cannot write the base");
  // Coordinates are in the input surface's length unit, which blayer does not know.
  f.check(f.cg.go_to(f.fn(), base, "end"), "cannot reach the base");
  f.check(f.cg.dataclass_write(CGNS_ENUMV(NormalizedByUnknownDimensional)), "cannot write the data class");
  cgsize_t size[3] = {static_cast<cgsize_t>(mesh.cells.points.size()), static_cast<cgsize_t>(mesh.cells.n_cells()), 0};
  f.check(f.cg.zone_write(f.fn(), base, "fluid", size, CGNS_ENUMV(Unstructured), &zone), "cannot write the zone");
  write_coordinates(f, base, zone, mesh);
  cgsize_t next = write_volume_sections(f, base, zone, mesh);
  for (const BoundaryPatch& p : mesh.patches) {
    write_patch(f, base, zone, mesh, p, next);
    next += static_cast<cgsize_t>(p.size);
  }
  f.close();
}

}  // namespace blayer

#include "tetgen_adapter.h"

#include <tetgen.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace blayer::fill_detail {
namespace {

template <typename T>
T* copy_array(const std::vector<T>& v) {
  if (v.empty()) return nullptr;
  T* p = new T[v.size()];
  std::memcpy(p, v.data(), v.size() * sizeof(T));
  return p;
}

template <typename T>
void put_array(std::string& out, const std::vector<T>& v) {
  const std::int64_t n = static_cast<std::int64_t>(v.size());
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <typename T>
void get_array(const std::string& in, std::size_t& pos, std::vector<T>& v) {
  std::int64_t n = 0;
  if (pos + sizeof n > in.size()) throw std::runtime_error("truncated TetGen result");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  if (n < 0 || static_cast<std::uint64_t>(n) > (in.size() - pos) / sizeof(T))
    throw std::runtime_error("truncated TetGen result");
  v.resize(static_cast<std::size_t>(n));
  // An empty vector's data() may be null, and memcpy's arguments must not be, even
  // for zero bytes (UBSan reports it).
  if (n > 0) std::memcpy(v.data(), in.data() + pos, v.size() * sizeof(T));
  pos += v.size() * sizeof(T);
}

}  // namespace

TetgenMesh run_tetgen(const TetgenPlc& plc, const std::string& switches) {
  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(plc.points.size() / 3);
  in.pointlist = copy_array(plc.points);
  if (!plc.point_metric.empty()) {
    in.numberofpointmtrs = 1;
    in.pointmtrlist = copy_array(plc.point_metric);
  }
  const int nf = static_cast<int>(plc.triangles.size() / 3);
  in.numberoffacets = nf;
  in.facetlist = new tetgenio::facet[nf];
  in.facetmarkerlist = copy_array(plc.markers);
  for (int f = 0; f < nf; ++f) {
    tetgenio::facet& fa = in.facetlist[f];
    tetgenio::init(&fa);
    fa.numberofpolygons = 1;
    fa.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&fa.polygonlist[0]);
    fa.polygonlist[0].numberofvertices = 3;
    fa.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) fa.polygonlist[0].vertexlist[k] = plc.triangles[3 * f + k];
  }
  in.numberofholes = static_cast<int>(plc.holes.size() / 3);
  in.holelist = copy_array(plc.holes);

  tetgenio out;
  std::vector<char> sw(switches.begin(), switches.end());
  sw.push_back('\0');
  tetrahedralize(sw.data(), &in, &out);

  TetgenMesh m;
  m.points.assign(out.pointlist, out.pointlist + 3 * static_cast<std::size_t>(out.numberofpoints));
  if (out.tetrahedronlist != nullptr) {
    // With o2 a tet would carry 10 nodes; only the 4 corners are kept.
    const int nc = out.numberofcorners;
    m.tets.reserve(4 * static_cast<std::size_t>(out.numberoftetrahedra));
    for (int t = 0; t < out.numberoftetrahedra; ++t)
      for (int k = 0; k < 4; ++k) m.tets.push_back(out.tetrahedronlist[nc * t + k]);
  }
  if (out.trifacelist != nullptr) {
    m.faces.assign(out.trifacelist,
                   out.trifacelist + 3 * static_cast<std::size_t>(out.numberoftrifaces));
    if (out.trifacemarkerlist != nullptr)
      m.face_markers.assign(out.trifacemarkerlist, out.trifacemarkerlist + out.numberoftrifaces);
  }
  return m;
}

std::string encode(const TetgenMesh& m) {
  std::string out;
  out.reserve(m.points.size() * 8 + (m.tets.size() + m.faces.size() + m.face_markers.size()) * 4 +
              32);
  put_array(out, m.points);
  put_array(out, m.tets);
  put_array(out, m.faces);
  put_array(out, m.face_markers);
  return out;
}

TetgenMesh decode(const std::string& bytes) {
  TetgenMesh m;
  std::size_t pos = 0;
  get_array(bytes, pos, m.points);
  get_array(bytes, pos, m.tets);
  get_array(bytes, pos, m.faces);
  get_array(bytes, pos, m.face_markers);
  if (pos != bytes.size() || m.points.size() % 3 != 0 || m.tets.size() % 4 != 0 ||
      m.faces.size() % 3 != 0)
    throw std::runtime_error("inconsistent TetGen result");
  return m;
}

std::string describe_tetgen_error(int code) {
  switch (code) {
    case 1:
      return "out of memory (code 1); reduce the farfield size or raise growth";
    case 2:
      return "internal error (code 2); check the envelope for slivers and near-degenerate "
             "triangles";
    case 3:
      return "self-intersection detected (code 3); the envelope or farfield intersects itself or "
             "each other";
    case 4:
      return "very small input feature size (code 4); the envelope has points or triangles closer "
             "than TetGen's tolerance";
    case 5:
      return "two very close input facets (code 5); the envelope nearly touches itself or the "
             "farfield";
    case 10:
      return "input error (code 10); the PLC handed to TetGen is invalid";
    default:
      return "unknown error code " + std::to_string(code);
  }
}

}  // namespace blayer::fill_detail

// VTK files: the volume mesh as .vtu, surfaces as .vtp, and reading any volume .vtu /
// legacy .vtk unstructured grid for `blayer check`.
//
// What the writers produce: VTK XML whose DataArrays hold their values inline, as
// base64 text of compressed blocks (VTK's "binary" data mode), with 64-bit block
// headers so that arrays over 4 GiB stay readable. Every file is well-formed XML, so
// strict parsers (expat, as in ParaView and Python's xml.etree; xmllint) and meshio
// read it. The appended raw layout (bytes after <AppendedData encoding="raw">) is not
// used: it is not XML, and ParaView 5.11 with Debian 12's expat 2.5 opens such a file
// with no cells. libxml2 refuses text nodes over 10 MB unless asked (xmllint --huge,
// lxml's huge_tree): a large mesh's arrays exceed that, while expat has no such limit.
//
// The compressor trades write time for size and for who can read the file. Measured
// with bench/io/vtk_write_bench (CPU seconds of the VTK writer alone, fastest of 3 runs
// on a real mesh, of 5 on a generated one):
//                                  ONERA M6, 5.71M cells   generated, 5M prisms
//   inline zlib level 1 (default)  9.6 s, 544 MB           4.7 s, 270 MB   VTK, ParaView, meshio
//   inline LZ4                     2.6 s, 667 MB           1.7 s, 411 MB   VTK, ParaView
//   appended raw LZ4 (not XML)     0.9 s, 500 MB           0.7 s, 308 MB
// In `blayer extrude` of the 571k-triangle ONERA M6 wing (143 s in all) zlib cost
// about 7 s more than LZ4 for a file 18 % smaller that meshio also reads, so zlib is the
// default and LZ4 an option (measured before zlib stored the floating-point arrays, see
// below). zlib levels 3 to 6 write 1.2 to 2.8 times slower than
// level 1 for files at most 1.5 % smaller, so the level is fixed at 1. Reading is slower
// too (base64 and zlib): 5.0 s for the ONERA M6 file against 0.6 s before, 3.5 s with LZ4.
//
// .vtu files are written by blayer itself (io/src/vtu_writer.h): the same text as VTK's
// writer with these settings, array for array, but with the blocks of each array
// compressed in parallel, and with zlib the floating-point arrays stored (deflate level
// 0) rather than compressed: on layer meshes zlib shrinks coordinates and quality
// measures only to 80-94 % at about 46 MB/s. On the pyHyp BWB (532k cells) that took
// `blayer extrude` from 2.99 to 2.54 s for a file of 48.5 MB instead of 43.0 MB (717
// wing: 2.10 to 1.80 s, 38.8 to 44.1 MB; ONERA M6 16k: 0.97 to 0.79 s, 15.4 to
// 17.1 MB). Generated grids, whose coordinates repeat, lose more: bench/io/
// vtk_write_bench 200 10 (800k prisms, 2 threads) writes 74 MB in 0.30 s instead of
// 44 MB in 0.57 s (with the base64 text also encoded in parallel: 0.22-0.24 s; LZ4
// 0.13-0.15 s and 65 MB, smaller than zlib's there). The table above, from VTK's
// writer, gives the encodings' costs on one thread. .vtp surfaces, far smaller, are
// written by VTK.
//
// Every writer goes through AtomicOutputs: the target appears complete or not at all.
#pragma once

#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

enum class VtkCompressor {
  kZlib,  // smaller layer-mesh files that every VTK XML reader, meshio included, understands
  kLz4,   // about 1.7 times faster to write and 1.13 to 1.19 times larger on layer meshes
          // (zlib stores their floating-point arrays); meshio cannot read it
};

struct VtkWriteOptions {
  VtkCompressor compressor = VtkCompressor::kZlib;
};

// Writes mesh (cells in VTK node order) with all its point and cell arrays.
// Throws IoError when the file cannot be written.
void write_vtu(const VolumeMesh& mesh, const std::string& path, const VtkWriteOptions& options = {});

// Writes the triangles of s as PolyData with the given point and cell arrays
// (each array's tuple count must match the points or triangles).
void write_vtp(const TriSurface& s, const std::vector<DataArray>& point_data, const std::vector<DataArray>& cell_data,
               const std::string& path, const VtkWriteOptions& options = {});

struct VolumeMeshFile {
  VolumeMesh mesh;
  int n_skipped_lower_dimension = 0;  // vertices, lines, triangles, quads in the file (boundary markers)
};

// Reads a .vtu or legacy .vtk unstructured grid. Linear tets, pyramids, wedges and hexes
// are kept with their point and cell arrays (as doubles); cells of lower dimension are
// skipped and counted; any other 3D cell type is an InputError naming the cell. Any
// encoding VTK reads is accepted, including the appended raw LZ4 files blayer wrote
// before its output became inline base64.
VolumeMeshFile read_volume_mesh(const std::string& path);

}  // namespace blayer

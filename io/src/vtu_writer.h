// The .vtu writer: a VolumeMesh as VTK XML UnstructuredGrid in the layout VTK's own
// writer gives in its "binary" data mode (vtk_io.h): every DataArray inline, as the
// base64 text of a block header followed by the base64 text of its compressed blocks
// (32 KiB of values each, 64-bit header words: block count, block size, last block
// size, then each compressed size). Blocks are compressed as VTK's own zlib and LZ4
// compressors do it, by zlib and liblz4 called directly (no VTK library is loaded to
// write a .vtu), except that with zlib the floating-point arrays' blocks are stored by
// zlib at level 0 (below).
//
// Why not vtkXMLUnstructuredGridWriter: it compresses one block after the other, which
// made the write the largest single step after the extrusion (9.6 s of a 143 s run on
// the 571k-triangle ONERA M6). Here the blocks of a run of 64 are converted and
// compressed in parallel, then encoded and written in order; memory stays one run of
// blocks per thread above the mesh. The header's sizes are known only after the last
// block, so a placeholder of the same length is written first and overwritten at the
// end (base64 of a fixed byte count has a fixed length).
//
// The file is the same as VTK's up to attributes that readers do not need (no
// RangeMin / RangeMax, no information keys) and one choice VTK's writer cannot make:
// with zlib, floating-point arrays are stored (deflate level 0) and integer arrays
// compressed at level 1. A stored block is an ordinary zlib stream, so VTK, ParaView
// and meshio read the file as before; it is well-formed XML. Internal to blayer_io.
#pragma once

#include <string>

#include "blayer/core/volume_mesh.h"
#include "blayer/io/vtk_io.h"

namespace blayer {
namespace detail {

// The compression settings of every VTK XML file blayer writes: zlib level 1 (higher
// levels cost up to 2.8 times the time for at most 1.5 % smaller files, vtk_io.h), with
// the floating-point arrays of .vtu files stored instead; LZ4 at VTK's default
// acceleration 5.
constexpr int kZlibLevel = 1;
constexpr int kLz4Level = 5;

// Writes mesh to `path` (directly: the caller stages the file under a temporary name;
// errors name `target`, the file the user asked for). Throws IoError when the file
// cannot be written or closed. Precondition: mesh.offsets has n_cells + 1 entries
// ending at the connectivity's size (write_vtu checks it).
void write_vtu_blocks(const VolumeMesh& mesh, const std::string& path, const std::string& target,
                      VtkCompressor compressor);

}  // namespace detail
}  // namespace blayer

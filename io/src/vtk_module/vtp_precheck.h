// Checks of a .vtp on VTK's parse of its XML, before VTK reads the data: what the
// binary-data headers claim against what the file can hold, and the points' layout.
//
// VTK's XML reader trusts the header in front of each compressed data array: the
// number of blocks (it allocates a table of that many sizes), the size of a block
// decompressed and each block's compressed size (it allocates a buffer of each). A
// corrupt header claims exabytes. The release build survives that (the reader's child
// process has a bounded address space and VTK's bad_alloc becomes an InputError), but
// under AddressSanitizer operator new reports a huge request instead of throwing. This
// check parses the XML with VTK's own parser (element positions, appended-data position,
// header type, compressor), before the reader does (which reads some arrays, time
// values, while it gathers the file's information), reads each header where VTK would
// and refuses a claim the file cannot back, naming the array, in every build.
//
// A Points array whose component count is not 3, or element counts whose arrays cannot
// be allocated, make VTK 9.1 fail after it has taken objects it never frees; refused
// here, they are named plainly and nothing leaks.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace blayer::detail {

// The most bytes one block of a .vtp file may decompress to, and the address space
// the reader's process may add: 64 times the file's size (real data compresses by a
// few times, not 64) plus 2 GiB.
double vtp_decoded_bytes_allowed(std::size_t file_bytes);

// "" when the element counts fit the allowance (the points and the point- and cell-data
// arrays they size), the points' arrays have 3 components and every compressed-data
// header of the file claims what the file can hold; "" also when the XML does not parse
// (VTK's parser reports that through its output window, which the caller captures);
// else the first problem, naming its array or count. A header that cannot be decoded (not
// base64, or cut short) is reported too: VTK could not read its array either.
// Uncompressed arrays' headers are not checked: they only bound a copy into an array
// VTK sized from the element counts.
std::string vtp_precheck_problem(std::string_view bytes);

}  // namespace blayer::detail

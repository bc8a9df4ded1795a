// The CGNS library, loaded when the first .cgns file is written instead of linked.
// Debian's libcgns is built on HDF5, which brings libcurl and with it GnuTLS, OpenSSL,
// Kerberos, LDAP and SSH: 30 libraries and about 6 MB resident in every run (a tenth
// of a small run's peak memory), of which most never write CGNS. Internal to blayer_io.
#pragma once

#include <cgnslib.h>

#include <string>

namespace blayer::detail {

// The CGNS functions the writer calls, with the library's own signatures.
struct CgnsLibrary {
  decltype(&::cg_open) open;
  decltype(&::cg_close) close;
  decltype(&::cg_get_error) get_error;
  decltype(&::cg_goto) go_to;
  decltype(&::cg_base_write) base_write;
  decltype(&::cg_zone_write) zone_write;
  decltype(&::cg_coord_write) coord_write;
  decltype(&::cg_exponents_write) exponents_write;
  decltype(&::cg_dataclass_write) dataclass_write;
  decltype(&::cg_section_write) section_write;
  decltype(&::cg_family_write) family_write;
  decltype(&::cg_fambc_write) fambc_write;
  decltype(&::cg_famname_write) famname_write;
  decltype(&::cg_boco_write) boco_write;
  decltype(&::cg_boco_gridlocation_write) boco_gridlocation_write;
};

// Loads the library at `path` (by its file name where the path does not exist: the
// library installed elsewhere on the machine that runs blayer) and keeps it loaded for
// the process. Throws IoError naming the library and why when it cannot be loaded or
// lacks one of the functions.
CgnsLibrary load_cgns_library(const std::string& path);

// The library the build found (BLAYER_CGNS_LIBRARY), loaded on first use. Throws
// IoError naming `target` (the file being written) and the reason, every time.
const CgnsLibrary& cgns_library(const std::string& target);

}  // namespace blayer::detail

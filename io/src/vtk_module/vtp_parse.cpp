// VTK XML PolyData (.vtp), through VTK's reader (the format has too many encodings to
// parse by hand: ascii, base64, appended raw, four compressors), run by blayer_io in a
// child process (vtp_reader.cpp, parse_in_child.h): VTK trusts the counts and
// compressed-block headers of the file, and a corrupt one makes it allocate exabytes or
// read out of bounds. The checks of vtp_precheck.h refuse those claims first; the child
// and its address-space limit remain for what they cannot see (a crash inside VTK, the
// connectivity VTK sizes from the offsets it reads, several arrays that together exceed
// the allowance).
//
// VTK reports problems (its XML parser's included) through the global output window,
// which would print them before blayer's own "error:" line and does not always set the
// reader's error code. While reading, a capturing window replaces it: any error text
// means the file cannot be used, and the first one becomes part of the InputError.
#include <vtkCellArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <new>
#include <string>

#include "blayer/core/address_sanitizer.h"
#include "blayer/core/errors.h"
#include "vtk_files.h"
#include "vtp_precheck.h"

namespace blayer::detail {

namespace {

// "name: what", as an InputError (the message surface_parsers.h's fail_at gives without
// a line).
[[noreturn]] void fail(const std::string& name, const std::string& what) { throw InputError(name + ": " + what); }

class CapturingOutputWindow : public vtkOutputWindow {
 public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);

  void DisplayErrorText(const char* text) override { keep(text); }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  void DisplayText(const char*) override {}

  const std::string& first_error() const { return first_; }

 private:
  // VTK's text is "ERROR: In <source file>, line <n>\n<class> (<address>): <message>";
  // only the message says something about the file.
  void keep(const char* text) {
    if (!first_.empty() || !text) return;
    first_ = text;
    if (first_.rfind("ERROR: In ", 0) == 0 && first_.find('\n') != std::string::npos)
      first_ = first_.substr(first_.find('\n') + 1);
    if (first_.rfind("vtk", 0) == 0 && first_.find("): ") != std::string::npos)
      first_ = first_.substr(first_.find("): ") + 3);
    while (!first_.empty() && (first_.back() == '\n' || first_.back() == ' ')) first_.pop_back();
    first_ = first_.substr(0, 300);
  }
  std::string first_;
};
vtkStandardNewMacro(CapturingOutputWindow);

// Installs a capturing window, and silences VTK's logger (which prints errors to stderr
// besides the window), for its lifetime; then puts both back.
class CapturedVtkErrors {
 public:
  CapturedVtkErrors()
      : previous_(vtkOutputWindow::GetInstance()), verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(window_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~CapturedVtkErrors() {
    vtkLogger::SetStderrVerbosity(verbosity_);
    vtkOutputWindow::SetInstance(previous_);
  }
  CapturedVtkErrors(const CapturedVtkErrors&) = delete;
  CapturedVtkErrors& operator=(const CapturedVtkErrors&) = delete;
  const std::string& first() const { return window_->first_error(); }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkLogger::Verbosity verbosity_;
  vtkNew<CapturingOutputWindow> window_;
};

// The reader's process may map at most what it holds now (the first field of
// /proc/self/statm, in pages) plus what vtp_decoded_bytes_allowed grants: what the
// prechecks cannot see (arrays sized from data, several arrays together) then fails at
// once with bad_alloc instead of making the system zero gigabytes of pages. Not under
// AddressSanitizer, whose shadow memory reserves terabytes of address space.
void limit_address_space(std::size_t file_bytes) {
  if (kAddressSanitizer) return;
  unsigned long pages = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  if (pages == 0) return;
  const double now = static_cast<double>(pages) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  const double allowed = now + vtp_decoded_bytes_allowed(file_bytes);
  rlimit r{};
  if (::getrlimit(RLIMIT_AS, &r) != 0) return;
  if (r.rlim_cur != RLIM_INFINITY && static_cast<double>(r.rlim_cur) <= allowed) return;
  r.rlim_cur = static_cast<rlim_t>(allowed);
  ::setrlimit(RLIMIT_AS, &r);
}

PolygonSoup parse_vtp_here(std::string_view bytes, const std::string& name) {
  CapturedVtkErrors messages;
  auto fail_if_vtk_failed = [&](bool failed) {
    if (failed || !messages.first().empty())
      fail(name, "cannot parse the .vtp file" + (messages.first().empty() ? "" : " (VTK: " + messages.first() + ")"));
  };
  // The checks on the XML before the reader reads any data.
  const std::string problem = vtp_precheck_problem(bytes);
  fail_if_vtk_failed(false);
  if (!problem.empty()) fail(name, "cannot parse the .vtp file: " + problem);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(std::string(bytes));
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    // What the prechecks cannot see (above) can still claim more memory than exists.
    fail(name, "cannot parse the .vtp file (it claims more data than memory can hold: a corrupt count or "
               "data block header)");
  }
  vtkPolyData* poly = reader->GetOutput();
  fail_if_vtk_failed(reader->GetErrorCode() != 0 || !poly);
  if (poly->GetNumberOfStrips() > 0) fail(name, "triangle strips are not supported; convert them to triangles");
  PolygonSoup soup;
  const vtkIdType np = poly->GetNumberOfPoints();
  soup.points.resize(static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i) {
    poly->GetPoint(i, soup.points[i].data());
    for (double c : soup.points[i])
      if (!std::isfinite(c)) fail(name, "point " + std::to_string(i) + ": a coordinate is not a finite number");
  }
  vtkCellArray* polys = poly->GetPolys();
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);) {
    std::vector<int> face;
    face.reserve(static_cast<std::size_t>(n));
    for (vtkIdType k = 0; k < n; ++k) {
      if (ids[k] < -2147483648LL || ids[k] > 2147483647LL)
        fail(name, "polygon " + std::to_string(soup.faces.size()) + ": point index " + std::to_string(ids[k]) +
                       " does not fit an int");
      face.push_back(static_cast<int>(ids[k]));
    }
    soup.faces.push_back(std::move(face));
  }
  return soup;
}

}  // namespace

PolygonSoup parse_vtp_with_vtk(std::string_view bytes, const std::string& name, bool limit_memory) {
  if (limit_memory) limit_address_space(bytes.size());
  return parse_vtp_here(bytes, name);
}

}  // namespace blayer::detail

// Atomic output: every file blayer writes (meshes, surfaces, reports) is first written
// under a temporary name in its target's directory and renamed into place only when
// everything a run writes is complete, so a failed or interrupted run never leaves a
// half-written file, or a mesh without its report, under a requested name.
//
// AtomicOutputs is a set of such files:
//   stage(target)  checks that the target's directory exists (IoError otherwise) and
//                  returns a fresh temporary path next to it, ".<stem>-<pid>-<n>.part<ext>"
//                  (same directory: rename() is atomic only within one file system;
//                  same extension: writers that look at it still see it). The caller
//                  writes the complete file there.
//   stage_directory(target)  the same for a directory output (an OpenFOAM polyMesh):
//                  creates the temporary directory, which the caller fills.
//   commit()       renames every staged file onto its target, in staging order. A
//                  directory that already exists at a directory target is first moved
//                  aside, then removed once the new one is in place (put back if the
//                  rename fails).
//   destructor     removes every temporary (with its content) that was not renamed (an exception on the
//                  way, or no commit at all): nothing is left behind on failure.
//
// A rename failing half way: each rename is atomic, a series of them is not. When the
// k-th rename fails, the targets staged before it already hold their new content (what
// they held before is gone), the k-th and later targets keep what they held (or stay
// absent), their temporaries are removed at once, and commit() throws IoError naming the file
// that failed and the files already written. Within one directory this needs a
// failure between two renames (the disk removed, a target replaced by a directory);
// targets in several directories add permission and quota failures.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace blayer {

// A path "<prefix>-<pid>-<counter><suffix>" that does not exist yet.
std::string unique_temp_path(const std::string& prefix, const std::string& suffix);

class AtomicOutputs {
 public:
  AtomicOutputs() = default;
  AtomicOutputs(const AtomicOutputs&) = delete;
  AtomicOutputs& operator=(const AtomicOutputs&) = delete;
  ~AtomicOutputs();

  // Temporary path to write `target` to. Throws IoError when the directory is missing.
  std::string stage(const std::string& target);
  // Temporary directory, created empty, to fill with `target`'s files. Throws IoError.
  std::string stage_directory(const std::string& target);
  // Renames every staged file onto its target (see above). Throws IoError on failure.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // target, temporary
  std::size_t n_committed_ = 0;                              // renamed so far
};

// Writes text to path (normally a staged temporary); throws IoError naming `target`
// when the file cannot be written completely.
void write_text_file(const std::string& path, const std::string& text, const std::string& target);

}  // namespace blayer

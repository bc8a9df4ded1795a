// most_normal_solve_once SET...
// Solves every fan of a set of most_normal_bench's generated fans once with the default
// most-normal solver, and prints per set the fans, their subdivision cells and a digest
// of the answers (status, D, V and direction, bit for bit). A SET is a valence k (the
// 64 fans of ByValence/default/k) or shape/k (the 32 of ByShape/default/shape/k; shape
// ridge, corner, rim or sliver).
// The solves of a set run in solve_set alone, which bench/normals/count_instructions.sh
// has valgrind count the instructions of: a figure the load of a shared machine does
// not move, for comparing two builds, while the digest tells whether their answers
// differ.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench_fans.h"
#include "blayer/normals/most_normal.h"

namespace {

using namespace blayer;

// FNV-1a over the bytes of each answer's status, D, V and direction.
class AnswerDigest {
 public:
  void add(const MostNormalResult& r) {
    const int status = static_cast<int>(r.status);
    bytes(&status, sizeof status);
    bytes(&r.normality, sizeof r.normality);
    bytes(&r.visibility, sizeof r.visibility);
    bytes(r.normal.data(), sizeof(double) * 3);
  }
  std::uint64_t value() const { return h_; }

 private:
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ c[i]) * 1099511628211ull;
  }
  std::uint64_t h_ = 14695981039346656037ull;
};

// Out of line and named for the instruction counter's toggle: everything it counts is
// the solves.
[[gnu::noinline]] void solve_set(const std::vector<FanGeometry>& fans, std::vector<MostNormalResult>* out) {
  for (const FanGeometry& g : fans) out->push_back(most_normal_normal(g));
}

bool shape_named(const std::string& name, testing_fans::CadShape* shape) {
  for (testing_fans::CadShape s : testing_fans::kCadShapes)
    if (name == testing_fans::cad_shape_name(s)) {
      *shape = s;
      return true;
    }
  return false;
}

// The fans of SET, or false when it names none.
bool fans_of_set(const std::string& set, std::vector<FanGeometry>* fans) {
  const std::size_t slash = set.find('/');
  const std::string valence = slash == std::string::npos ? set : set.substr(slash + 1);
  char* end = nullptr;
  const long k = std::strtol(valence.c_str(), &end, 10);
  if (valence.empty() || *end != '\0' || k < 3 || k > 200) return false;
  if (slash == std::string::npos) {
    *fans = bench::fans_of_valence(static_cast<int>(k));
    return true;
  }
  testing_fans::CadShape shape;
  if (!shape_named(set.substr(0, slash), &shape)) return false;
  *fans = bench::fans_of_shape(shape, static_cast<int>(k));
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: most_normal_solve_once SET... (SET: a valence k, or shape/k)\n");
    return 1;
  }
  for (int a = 1; a < argc; ++a) {
    std::vector<FanGeometry> fans;
    if (!fans_of_set(argv[a], &fans)) {
      std::fprintf(stderr, "error: no fan set '%s' (a valence k from 3 to 200, or ridge/k, corner/k, rim/k, sliver/k)\n",
                   argv[a]);
      return 1;
    }
    std::vector<MostNormalResult> answers;
    answers.reserve(fans.size());
    solve_set(fans, &answers);
    AnswerDigest digest;
    long cells = 0;
    for (const MostNormalResult& r : answers) {
      digest.add(r);
      cells += r.n_cells;
    }
    std::printf("set %s: %zu fans, %ld cells, answers %016llx\n", argv[a], fans.size(), cells,
                static_cast<unsigned long long>(digest.value()));
  }
  return 0;
}

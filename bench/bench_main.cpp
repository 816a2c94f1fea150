// pagor_bench: the benchmark suite. Medians over repeated runs; comparisons are ratios measured in
// the same run. Never asserts anything about time: the tests do the correctness.
//
//   build/bench/pagor_bench [--kitti-root DIR] [--semreg-root DIR] [--gedi-root DIR] [--reps N]
//       [--write-problems DIR]
//       [--only graph|clique|gnc|verification|e2e|studio|association|cascade|front|dense]

#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_sections.hpp"

using namespace pagor::bench;

int main(int argc, char** argv) {
  Options o;
  o.kitti_root = PAGOR_DEFAULT_KITTI_DIR;
  o.semreg_root = PAGOR_DEFAULT_SEMREG_DIR;
  o.gedi_root = PAGOR_DEFAULT_GEDI_DIR;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--kitti-root")
      o.kitti_root = argv[i + 1];
    else if (a == "--semreg-root")
      o.semreg_root = argv[i + 1];
    else if (a == "--gedi-root")
      o.gedi_root = argv[i + 1];
    else if (a == "--reps")
      o.reps = std::max(1, std::atoi(argv[i + 1]));
    else if (a == "--only")
      only = argv[i + 1];
    else if (a == "--write-problems")
      o.write_dir = argv[i + 1];
    else {
      std::fprintf(
          stderr,
          "usage: pagor_bench [--kitti-root DIR] [--semreg-root DIR] [--gedi-root DIR] [--reps N] "
          "[--only SECTION] [--write-problems DIR]\n");
      return 2;
    }
  }
  std::printf("# pagor_bench (medians of %d runs unless noted)\n", o.reps);
  const struct {
    const char* name;
    void (*run)(const Options&);
  } sections[] = {{"graph", bench_graph},
                  {"clique", bench_clique},
                  {"gnc", bench_gnc},
                  {"verification", bench_verification},
                  {"e2e", bench_end_to_end},
                  {"studio", bench_studio},
                  {"association", bench_association},
                  {"cascade", bench_cascade_kitti},
                  {"front", bench_front},
                  {"dense", bench_dense}};
  for (const auto& s : sections)
    if (only.empty() || only == s.name) s.run(o);
  return 0;
}

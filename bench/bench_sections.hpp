#pragma once
// The sections of pagor_bench, one function each; main() picks them with --only.

#include <string>

namespace pagor::bench {

/// Command-line options shared by the sections.
struct Options {
  std::string kitti_root;   ///< KITTI root holding sequences/00
  std::string semreg_root;  ///< semreg-dev: NN/source.pcd and NN/target.pcd
  std::string gedi_root;    ///< gedi-dev: NN.txt (correspondences) and NN.T.txt
  std::string write_dir;    ///< association problems are written here when set
  int reps = 15;            ///< measured runs per figure (medians)
};

void bench_graph(const Options& o);          ///< 1. pyramid graph construction
void bench_clique(const Options& o);         ///< 2. densest clique, all-to-all scene
void bench_gnc(const Options& o);            ///< 3. GNC-TLS
void bench_verification(const Options& o);   ///< 4. verification on full KITTI scans
void bench_end_to_end(const Options& o);     ///< 5. end to end per KITTI pair, by stage
void bench_studio(const Options& o);         ///< 6. studio re-run latency
void bench_association(const Options& o);    ///< 7. issue 11's association problems
void bench_cascade_kitti(const Options& o);  ///< 8. cascade on the KITTI pairs' graphs
void bench_front(const Options& o);          ///< 9. landmarks and correspondences per class
void bench_dense(const Options& o);          ///< 10. dense real and generated problems

}  // namespace pagor::bench

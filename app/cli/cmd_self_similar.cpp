// pagor self-similar: writes the generated self-similar scenes (corridors, streets of repeated
// facades, a street that slides along itself, a symmetric hall; each with and without distinct
// objects, labelled and not; eval/self_similar.hpp) as a pairs set that `pagor bench` scores
// beside the real sets: where a wrong pose can look as aligned as the right one.

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "command.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/eval/self_similar.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/clouds.hpp"

namespace pagor::cli {

namespace fs = std::filesystem;

std::vector<Option> self_similar_options() {
  return {{"out", 1, "DIR", "directory to write the set into (created if needed)"},
          {"seeds", 1, "N", "scenes of seeds 1..N, 16 a seed (default 2)"}};
}

int run_self_similar(const Args& args) {
  if (!args.has("out")) throw UsageError("self-similar needs --out DIR");
  const int seeds = args.get_int("seeds", 2);
  if (seeds < 1 || seeds > 1000) throw UsageError("--seeds must be in [1, 1000]");
  const fs::path dir = args.get("out");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the directory (" + ec.message() + ")");
  // The manifest goes first and comes back last: an interrupted run leaves none that names
  // scenes not written.
  const fs::path manifest = dir / "pairs.txt";
  fs::remove(manifest, ec);
  if (ec)
    throw InputError(manifest.string() + ": cannot remove the old manifest (" + ec.message() + ")");

  const std::vector<SelfSimilarParams> set = self_similar_set(seeds);
  std::string pairs =
      "# Self-similar scenes (pagor self-similar --seeds " + std::to_string(seeds) +
      "): each the source, the target and their relative pose T_target_source.\n"
      "# Run: pagor bench --manifest " + manifest.string() + "\n";
  std::size_t done = 0;
  const bool progress = isatty(STDERR_FILENO);  // in a log it would run into one line
  for (const SelfSimilarParams& p : set) {
    const SelfSimilarScene s = make_self_similar_scene(p);
    const fs::path sub = dir / s.name;
    fs::create_directories(sub, ec);
    if (ec) throw InputError(sub.string() + ": cannot create the directory (" + ec.message() + ")");
    save_cloud(s.source, (sub / "source.pcd").string());
    save_cloud(s.target, (sub / "target.pcd").string());
    write_file_atomic((sub / "T_target_source.txt").string(),
                      transform_file_text(s.T_target_source));
    // The labels' numbering is said, not left to detection (kSelfSimilarLabelScheme).
    pairs += s.name + "/source.pcd " + s.name + "/target.pcd gt=" + s.name +
             "/T_target_source.txt" + (p.labelled ? " scheme=" + kSelfSimilarLabelScheme : "") +
             " name=" + s.name + "\n";
    ++done;
    if (progress) std::fprintf(stderr, "\rwriting scenes: %zu/%zu", done, set.size());
  }
  if (progress) std::fprintf(stderr, "\n");
  write_file_atomic(manifest.string(), pairs);
  std::printf("wrote %zu scenes to %s\nrun: pagor bench --manifest %s\n", set.size(),
              dir.string().c_str(), manifest.string().c_str());
  return 0;
}

}  // namespace pagor::cli

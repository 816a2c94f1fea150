// Registers two clouds with pagor as a library: register_clouds SOURCE TARGET [SOURCE_LABELS
// TARGET_LABELS] (.bin, .pcd, .ply; .label files), or the generated scene without arguments.
// Prints the selected T_target_source and the verdict. Exit status 1 on bad input.

// README: "Use it as a library" (C++)
#include <cstdio>
#include <pagor/eval/synthetic.hpp>  // the generated scene (pagor::eval)
#include <pagor/pagor.hpp>

/// Registers `source` to `target` (clouds from pagor::load_cloud(path, labels_path).cloud, or
/// filled by you: points [m], optional labels) and prints the transform and the verdict.
void register_and_print(pagor::PointCloud source, pagor::PointCloud target) {
  const pagor::Config config = pagor::default_config();  // or pagor::load_config("my.json")
  // Throws pagor::ConfigError, pagor::InputError.
  const pagor::Registration r =
      pagor::register_clouds(std::move(source), std::move(target), config);
  if (r.T_target_source) {
    const pagor::Transform& T = *r.T_target_source;
    std::printf("T_target_source (level %d):\n", r.selected_level);
    for (int row = 0; row < 4; ++row)
      std::printf("  %10.4f %10.4f %10.4f %10.4f\n", T(row, 0), T(row, 1), T(row, 2), T(row, 3));
  }
  if (r.accepted())
    std::printf("accepted: %.0f %% of the source aligned\n", 100.0 * r.acceptance.overlap);
  else
    std::printf("rejected: %s\n", r.acceptance.reason.c_str());
  // pagor::to_json(r) is what `pagor register --json` writes.
}
// end of snippet

int main(int argc, char** argv) {
  if (argc != 1 && argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: register_clouds [SOURCE TARGET [SOURCE_LABELS TARGET_LABELS]]\n");
    return 2;
  }
  try {
    if (argc == 1) {
      pagor::SyntheticScene scene = pagor::make_synthetic_scene();
      register_and_print(std::move(scene.source), std::move(scene.target));
    } else {
      register_and_print(pagor::load_cloud(argv[1], argc == 5 ? argv[3] : "").cloud,
                      pagor::load_cloud(argv[2], argc == 5 ? argv[4] : "").cloud);
    }
  } catch (const pagor::Error& e) {  // unreadable files, invalid parameters
    std::fprintf(stderr, "register_clouds: %s\n", e.what());
    return 1;
  }
  return 0;
}

// libFuzzer target: the KITTI text files (pairs file, poses.txt, calib.txt) and the binary scan
// and label files. The first byte chooses which file the rest becomes; the readers take paths,
// so the bytes are written to a per-process scratch directory.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "pagor/errors.hpp"
#include "scratch.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/kitti.hpp"

using pagor::fuzz::write_bytes;

namespace {

const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    const auto d = pagor::fuzz::make_scratch_directory("kitti");
    std::filesystem::create_directories(d / "sequences" / "00");
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size < 1) return 0;
  const char* data = reinterpret_cast<const char*>(bytes + 1);
  const std::size_t n = size - 1;
  const auto seq = scratch() / "sequences" / "00";
  const char* identity = "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  try {
    switch (bytes[0] % 5) {
      case 0:
        write_bytes(scratch() / "pairs.txt", data, n);
        pagor::read_pairs_file((scratch() / "pairs.txt").string());
        break;
      case 1:
        write_bytes(seq / "poses.txt", data, n);
        write_bytes(seq / "calib.txt", identity, std::char_traits<char>::length(identity));
        pagor::KittiSequence(scratch().string(), "00").ground_truth(0, 0);
        break;
      case 2:
        write_bytes(seq / "poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n", 24);
        write_bytes(seq / "calib.txt", data, n);
        pagor::KittiSequence(scratch().string(), "00").ground_truth(0, 0);
        break;
      case 3:
        write_bytes(scratch() / "scan.bin", data, n);
        pagor::load_cloud((scratch() / "scan.bin").string());
        break;
      default:
        write_bytes(scratch() / "scan.label", data, n);
        pagor::read_kitti_labels((scratch() / "scan.label").string());
        break;
    }
  } catch (const pagor::Error&) {
  }
  return 0;
}

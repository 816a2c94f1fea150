// libFuzzer target: the pairs manifest (quoted paths, keys, duplicate names and pairs), the
// results lines of `pagor bench --out` and the ground-truth transform file. The first byte
// chooses which the rest becomes; the manifest and transform readers take paths, so the bytes go
// to a per-process scratch directory that also holds files a manifest line may name.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/pair_set.hpp"
#include "scratch.hpp"

using pagor::fuzz::write_bytes;

namespace {

const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    const auto d = pagor::fuzz::make_scratch_directory("manifest");
    std::filesystem::create_directories(d / "sub dir");
    for (const char* f : {"a.pcd", "b.pcd", "sub dir/c.ply", "a.label"})
      std::ofstream(d / f) << "x";
    std::ofstream(d / "gt.txt") << "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
    std::error_code ec;
    std::filesystem::create_symlink(d / "a.pcd", d / "link.pcd", ec);
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size < 1) return 0;
  const char* data = reinterpret_cast<const char*>(bytes + 1);
  const std::size_t n = size - 1;
  try {
    switch (bytes[0] % 3) {
      case 0: {
        write_bytes(scratch() / "m.txt", data, n);
        const pagor::PairSet set = pagor::read_pair_manifest((scratch() / "m.txt").string());
        for (const pagor::PairEntry& e : set.pairs) pagor::pair_fingerprint(e);
        break;
      }
      case 1:
        pagor::outcome_from_json_line(std::string(data, n), "fuzz.jsonl:1");
        break;
      default:
        write_bytes(scratch() / "T.txt", data, n);
        pagor::read_transform_file((scratch() / "T.txt").string());
        break;
    }
  } catch (const pagor::Error&) {
  }
  return 0;
}

// libFuzzer target: correspondences files from any matcher (io/correspondence_file.hpp): decimal
// numbers only, finite and bounded coordinates, one column count per file, weights and flags
// checked. A file that parses must hold what the header promises of it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/io/correspondence_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const pagor::CorrespondenceFile f = pagor::parse_correspondence_file(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.txt");
    const std::size_t n = f.items.size();
    if (n == 0 || n > pagor::kMaxFileCorrespondences || f.lines.size() != n) std::abort();
    if (!f.weights.empty() && f.weights.size() != n) std::abort();
    if (!f.inlier.empty() && f.inlier.size() != n) std::abort();
    for (const pagor::Correspondence& c : f.items)
      if (!c.p.allFinite() || !c.q.allFinite() ||
          c.p.cwiseAbs().maxCoeff() > pagor::kMaxMatchCoordinate ||
          c.q.cwiseAbs().maxCoeff() > pagor::kMaxMatchCoordinate || !(c.score >= 0.0))
        std::abort();
    for (const double w : f.weights)
      if (!(w >= 0.0) || w > 1e308) std::abort();
  } catch (const pagor::Error&) {
  }
  return 0;
}

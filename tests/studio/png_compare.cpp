// png_compare: compares a rendered PNG with a reference, tolerating tiny rasterisation differences.
//
//   png_compare REFERENCE ACTUAL [--diff OUT.png] [--pixel-threshold N] [--max-fraction F]
//               [--ignore x,y,w,h]...
//
// A pixel differs when one of its channels differs by more than N (default 24 of 255). The images
// match when the fraction of differing pixels is at most F (default 0.001) and the sizes agree.
// Prints the fraction and the largest channel difference; on a mismatch writes a diff image
// (differing pixels red over a dimmed reference). Exit 0 on a match, 1 on a mismatch, 2 on errors.

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Rect {
  int x, y, w, h;
  bool contains(int px, int py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

struct Image {
  int w = 0, h = 0;
  std::vector<unsigned char> rgba;
};

bool load(const std::string& path, Image& img) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &img.w, &img.h, &channels, 4);
  if (!data) return false;
  img.rgba.assign(data, data + static_cast<std::size_t>(img.w) * img.h * 4);
  stbi_image_free(data);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: png_compare REFERENCE ACTUAL [--diff OUT.png] [--pixel-threshold N] "
                 "[--max-fraction F] [--ignore x,y,w,h]...\n");
    return 2;
  }
  std::string diff_path;
  int threshold = 24;
  double max_fraction = 0.001;
  std::vector<Rect> ignore;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string opt = argv[i];
    if (opt == "--diff")
      diff_path = argv[i + 1];
    else if (opt == "--pixel-threshold")
      threshold = std::atoi(argv[i + 1]);
    else if (opt == "--max-fraction")
      max_fraction = std::atof(argv[i + 1]);
    else if (opt == "--ignore") {
      Rect r{};
      if (std::sscanf(argv[i + 1], "%d,%d,%d,%d", &r.x, &r.y, &r.w, &r.h) != 4) {
        std::fprintf(stderr, "png_compare: --ignore expects x,y,w,h\n");
        return 2;
      }
      ignore.push_back(r);
    } else {
      std::fprintf(stderr, "png_compare: unknown option %s\n", opt.c_str());
      return 2;
    }
  }
  Image ref, act;
  if (!load(argv[1], ref)) {
    std::fprintf(stderr, "png_compare: cannot read reference %s\n", argv[1]);
    return 2;
  }
  if (!load(argv[2], act)) {
    std::fprintf(stderr, "png_compare: cannot read %s\n", argv[2]);
    return 2;
  }
  if (ref.w != act.w || ref.h != act.h) {
    std::printf("size differs: reference %dx%d, actual %dx%d\n", ref.w, ref.h, act.w, act.h);
    return 1;
  }
  std::size_t differing = 0, compared = 0;
  int largest = 0;
  std::vector<unsigned char> diff(ref.rgba.size());
  for (int y = 0; y < ref.h; ++y)
    for (int x = 0; x < ref.w; ++x) {
      const std::size_t k = (static_cast<std::size_t>(y) * ref.w + x) * 4;
      bool skip = false;
      for (const Rect& r : ignore) skip = skip || r.contains(x, y);
      int d = 0;
      for (int c = 0; c < 3; ++c)
        d = std::max(d, std::abs(int(ref.rgba[k + c]) - int(act.rgba[k + c])));
      const bool differs = !skip && d > threshold;
      if (!skip) {
        ++compared;
        largest = std::max(largest, d);
      }
      differing += differs;
      for (int c = 0; c < 3; ++c) diff[k + c] = static_cast<unsigned char>(ref.rgba[k + c] / 4);
      if (differs) {
        diff[k] = 255;
        diff[k + 1] = diff[k + 2] = 0;
      }
      diff[k + 3] = 255;
    }
  const double fraction = compared ? static_cast<double>(differing) / compared : 0.0;
  std::printf(
      "%zu of %zu pixels differ (%.4f %%, limit %.4f %%), largest channel difference %d "
      "(pixel threshold %d)\n",
      differing, compared, 100 * fraction, 100 * max_fraction, largest, threshold);
  if (fraction <= max_fraction) return 0;
  if (!diff_path.empty() &&
      stbi_write_png(diff_path.c_str(), ref.w, ref.h, 4, diff.data(), ref.w * 4))
    std::printf("wrote diff image %s\n", diff_path.c_str());
  return 1;
}

#include "runtime/ImageDifference.h"

#include <algorithm>
#include <cmath>

namespace mxc::rt {

ImageDifference compareImages(const RgbaImage& image, const RgbaImage& reference, double threshold) {
  ImageDifference out;
  double sum = 0.0;
  const size_t size = std::min(image.pixels.size(), reference.pixels.size());
  for (size_t p = 0; p + 3 < size; p += 4) {
    const float* a = &image.pixels[p];
    const float* b = &reference.pixels[p];
    if (!(a[3] > 0.0f) && !(b[3] > 0.0f)) continue;  // background in both
    double d = std::abs(double(a[3]) - double(b[3]));
    bool finite = std::isfinite(d);
    for (size_t k = 0; k < 3; ++k) {
      const double term = std::abs(double(a[k]) - double(b[k])) / std::max(std::abs(double(b[k])), 0.05);  // 0.05 > 0
      finite = finite && std::isfinite(term);  // tested apart: std::max would drop a NaN
      d = std::max(d, term);
    }
    if (!finite) d = 1.0;
    ++out.covered;
    out.over += d > threshold ? 1 : 0;
    out.worst = std::max(out.worst, d);
    sum += d;
  }
  out.mean = out.covered ? sum / double(out.covered) : 0.0;  // covered > 0 to divide
  return out;
}

}  // namespace mxc::rt

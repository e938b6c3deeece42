#include "render/antialias.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "math/lane_array.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace raycast {

namespace {

/// Refinement samples use their own stream per pixel, apart from the first pass's.
constexpr unsigned kRefineSalt = 0x5bd1e995u;

struct Counters {
  std::uint64_t rays = 0, samples = 0;
};

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

/// The displayed value of a linear colour: its 8-bit sRGB codes (io/image.h), as the bytes of one
/// word (red lowest) so that a first pass keeps 4 bytes per pixel.
std::uint32_t display_codes(const Color& c) {
  return std::uint32_t(linear_to_srgb8(float(c.x))) |
         std::uint32_t(linear_to_srgb8(float(c.y))) << 8 |
         std::uint32_t(linear_to_srgb8(float(c.z))) << 16;
}

/// The distance of two displayed values in codes: the sum over channels of |code difference|
/// (0 to 765). The tests compare it with an integer limit, so no division per comparison.
int code_distance(std::uint32_t a, std::uint32_t b) {
#if defined(__SSE2__)
  // One sum of absolute byte differences (psadbw; the fourth bytes are zero).
  return _mm_cvtsi128_si32(_mm_sad_epu8(_mm_cvtsi32_si128(int(a)), _mm_cvtsi32_si128(int(b))));
#else
  const auto channel = [&](int shift) {
    return std::abs(int((a >> shift) & 0xff) - int((b >> shift) & 0xff));
  };
  return channel(0) + channel(8) + channel(16);
#endif
}

/// The least code distance s with s / 255 > threshold (766: none), so that
/// `code_distance >= limit` is exactly `colour distance > threshold`.
int code_limit(double threshold) {
  int s = 0;
  while (s <= 765 && !(double(s) / 255.0 > threshold)) ++s;
  return s;
}

/// Runs body(y, counters) for every row y in [0, rows) in parallel, then calls row_done.
template <class Body>
void for_rows(int rows, tbb::enumerable_thread_specific<Counters>& counters,
              const std::function<void()>& row_done, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& range) {
    Counters& c = counters.local();
    for (int y = range.begin(); y != range.end(); ++y) {
      body(y, c);
      if (row_done) row_done();
    }
  });
}

/// The displayed first-pass values over the pixels [x0, x1) x [y0, y1) of a full_width x
/// full_height picture (a window and the one-pixel ring around it that neighbour tests read),
/// indexed by full-image pixel coordinates. The values themselves go straight into the image:
/// fresh memory is costly to touch (a page fault per 4 KiB), so the pass keeps 4 bytes per pixel
/// beside the image rather than 48.
struct FirstPass {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0, full_width = 0, full_height = 0;
  std::vector<std::uint32_t> shown;
  std::size_t index(int x, int y) const {
    return std::size_t(y - y0) * std::size_t(x1 - x0) + std::size_t(x - x0);
  }
};

/// Whether pixel (x, y) of the first-pass values differs from one of its four neighbours by more
/// than the threshold, `limit` = code_limit(threshold) (POV-Ray's method 1 compares each pixel with
/// its left and upper neighbours and refines both: the same set of pixels). Forced inline: GCC
/// kept it a call, once per pixel of the refinement pass.
inline __attribute__((always_inline)) bool differs(const FirstPass& first, int x, int y,
                                                   int limit) {
  const std::size_t i = first.index(x, y);
  const std::uint32_t* shown = first.shown.data();
  const std::uint32_t c = shown[i];
  const std::size_t row = std::size_t(first.x1 - first.x0);
  // Left, right, up, down (in that order, as before), each inside the full picture.
  if (x > 0 && code_distance(c, shown[i - 1]) >= limit) return true;
  if (x + 1 < first.full_width && code_distance(c, shown[i + 1]) >= limit) return true;
  if (y > 0 && code_distance(c, shown[i - row]) >= limit) return true;
  return y + 1 < first.full_height && code_distance(c, shown[i + row]) >= limit;
}

/// The first pass of methods 1 and variance: one sample through every pixel's centre, over the
/// window (wx0, wy0, w x h) grown by one pixel inside the full picture; the window's values go
/// into `image` (pixel (wx0, wy0) at (0, 0)); row_done for the window's rows only.
FirstPass centre_pass(int wx0, int wy0, int w, int h, int full_width, int full_height,
                      unsigned seed, const RasterBatchSampler& trace, Image& image,
                      tbb::enumerable_thread_specific<Counters>& counters,
                      const std::function<void()>& row_done) {
  FirstPass first;
  first.full_width = full_width;
  first.full_height = full_height;
  first.x0 = std::max(0, wx0 - 1);
  first.y0 = std::max(0, wy0 - 1);
  first.x1 = std::min(full_width, wx0 + w + 1);
  first.y1 = std::min(full_height, wy0 + h + 1);
  first.shown.resize(std::size_t(first.x1 - first.x0) * std::size_t(first.y1 - first.y0));
  // The displayed values are computed in the same parallel rows (not in a serial pass after).
  for_rows(first.y1 - first.y0, counters, nullptr, [&](int row, Counters& c) {
    const int y = first.y0 + row;
    const bool in_rows = y >= wy0 && y < wy0 + h;
    std::uint32_t* const shown = first.shown.data() + first.index(first.x0, y);
    std::uint64_t rays = 0;  // summed here, added to the thread's counters once per row
    // Batches of neighbouring pixels of the row (coherent camera rays).
    LaneArray<SampleState, kMaxRasterBatch> state;  // each written before it is read
    RasterSample at[kMaxRasterBatch];
    Color value[kMaxRasterBatch];
    for (int xb = first.x0; xb < first.x1; xb += kMaxRasterBatch) {
      const int count = std::min(kMaxRasterBatch, first.x1 - xb);
      for (int i = 0; i < count; ++i) {
        state[i] = SampleState{Rng::for_pixel(xb + i, y, seed), 0};
        at[i] = RasterSample{xb + i + 0.5, y + 0.5, &state[i]};
      }
      trace(at, count, value);
      for (int i = 0; i < count; ++i) {
        const int x = xb + i;
        shown[x - first.x0] = display_codes(value[i]);
        if (in_rows && x >= wx0 && x < wx0 + w) image.set(x - wx0, y - wy0, Vec3f(value[i]));
        rays += state[i].rays;
      }
    }
    c.rays += rays;
    c.samples += std::uint64_t(first.x1 - first.x0);
    if (row_done && in_rows) row_done();
  });
  return first;
}

/// Method 1's refinement of the pixels xs[0..count) of row y (count <= kMaxRasterBatch, each
/// differing from a neighbour): depth x depth stratified, jittered samples in place of each
/// centre sample; with depth odd the middle stratum keeps the centre sample (it lies in that
/// stratum), so depth^2 - 1 new samples. Stratum k of every pixel is one batch; each pixel
/// draws its jitter and traces in stratum order with its own generator, so its value is the
/// same whatever pixels share its batches.
void refine_pixels(const int* xs, int count, int y, int x0, int y0, int n, unsigned seed,
                   const RasterBatchSampler& trace, Image& image, Counters& c) {
  LaneArray<SampleState, kMaxRasterBatch> state;  // each written before it is read
  RasterSample at[kMaxRasterBatch];
  Color value[kMaxRasterBatch], centre[kMaxRasterBatch], sum[kMaxRasterBatch];
  for (int p = 0; p < count; ++p) {
    state[p] = SampleState{Rng::for_pixel(xs[p], y, seed + kRefineSalt), 0};
    // The centre sample as the first pass stored it (in float, as every pixel is kept).
    centre[p] = Color(image.at(xs[p] - x0, y - y0));
    sum[p] = Color{0, 0, 0};
  }
  const int middle = n % 2 ? n * n / 2 : -1;
  // Stratum k = j n + i (row j, column i), in that order: no division per sample.
  for (int j = 0, k = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i, ++k) {
      for (int p = 0; p < count; ++p) {
        const double jx = state[p].rng.uniform(), jy = state[p].rng.uniform();
        at[p] = RasterSample{xs[p] + (i + jx) / n, y + (j + jy) / n, &state[p]};
      }
      if (k == middle) {
        for (int p = 0; p < count; ++p) sum[p] += centre[p];
        continue;
      }
      trace(at, count, value);
      for (int p = 0; p < count; ++p) sum[p] += value[p];
    }
  }
  for (int p = 0; p < count; ++p) {
    image.set(xs[p] - x0, y - y0, Vec3f(sum[p] / double(n * n)));
    c.rays += state[p].rays;
  }
  c.samples += std::uint64_t(count) * (std::uint64_t(n) * n - (middle >= 0));
}

/// Method 2's recursion over the square [x0, x0 + size] x [y0, y0 + size] with corner values
/// c[0..3] (top-left, top-right, bottom-left, bottom-right); `limit` = code_limit(aa.threshold).
Color subdivide(double x0, double y0, double size, const Color c[4], int level,
                const AntialiasSettings& aa, int limit, const RasterSampler& sample,
                SampleState& state, std::uint64_t& samples) {
  const std::uint32_t shown[4] = {display_codes(c[0]), display_codes(c[1]), display_codes(c[2]),
                                  display_codes(c[3])};
  int spread = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) spread = std::max(spread, code_distance(shown[i], shown[j]));
  if (level >= aa.depth || spread < limit) return 0.25 * (c[0] + c[1] + c[2] + c[3]);
  const double h = 0.5 * size;
  // The five new points: the edges' midpoints (top, left, right, bottom) and the centre.
  const Color top = sample(x0 + h, y0, state), left = sample(x0, y0 + h, state);
  const Color mid = sample(x0 + h, y0 + h, state), right = sample(x0 + size, y0 + h, state);
  const Color bottom = sample(x0 + h, y0 + size, state);
  samples += 5;
  const Color q0[4] = {c[0], top, left, mid}, q1[4] = {top, c[1], mid, right};
  const Color q2[4] = {left, mid, c[2], bottom}, q3[4] = {mid, right, bottom, c[3]};
  return 0.25 * (subdivide(x0, y0, h, q0, level + 1, aa, limit, sample, state, samples) +
                 subdivide(x0 + h, y0, h, q1, level + 1, aa, limit, sample, state, samples) +
                 subdivide(x0, y0 + h, h, q2, level + 1, aa, limit, sample, state, samples) +
                 subdivide(x0 + h, y0 + h, h, q3, level + 1, aa, limit, sample, state, samples));
}

// The variance sampler's pixel (x, y): rounds of four samples (2 x 2 strata, jittered) until the
// standard error of the mean of the clamped values is at most `target` in every channel (after
// at least two rounds) or `most` samples are taken. Returns the mean; counts into c.
Color refine_by_variance(int x, int y, unsigned seed, int most, double target,
                         const RasterSampler& sample, Counters& c) {
  SampleState state{Rng::for_pixel(x, y, seed + kRefineSalt), 0};
  Color sum{0, 0, 0}, sum1{0, 0, 0}, sum2{0, 0, 0};  // values; clamped; squared
  int n = 0;
  while (n < most) {
    for (int k = 0; k < 4; ++k) {
      const double jx = state.rng.uniform(), jy = state.rng.uniform();
      const Color v = sample(x + ((k % 2) + jx) / 2, y + ((k / 2) + jy) / 2, state);
      sum += v;
      const Color w{clamp01(v.x), clamp01(v.y), clamp01(v.z)};
      sum1 += w;
      sum2 += mul(w, w);
    }
    n += 4;
    if (n < 8) continue;
    // Unbiased variance of the clamped values per channel; the mean's standard error.
    double worst = 0;
    for (int i = 0; i < 3; ++i) {
      const double mean = sum1[i] / n;
      const double var = std::max(0.0, (sum2[i] - n * mean * mean) / (n - 1));
      worst = std::max(worst, var / n);
    }
    if (worst <= target * target) break;
  }
  c.rays += state.rays;
  c.samples += std::uint64_t(n);
  return sum / double(n);
}

}  // namespace

double colour_distance(const Color& a, const Color& b) {
  return code_distance(display_codes(a), display_codes(b)) / 255.0;
}

void render_adaptive(const AntialiasSettings& aa, unsigned seed, const RasterSampler& sample,
                     Image& image, AdaptiveStats& stats, const std::function<void()>& row_done,
                     const RasterWindow& window, const RasterBatchSampler& batch) {
  if (!(aa.threshold >= 0) || !std::isfinite(aa.threshold))
    throw std::invalid_argument("antialias threshold must be finite and >= 0");
  if (aa.depth < 1 || aa.depth > 16)
    throw std::invalid_argument("antialias depth must be in [1, 16]");
  // (x0, y0): the image's place in the full picture; every sample and seed uses full-picture
  // pixel coordinates, so a window's pixels are those of the whole render.
  const int width = image.width, height = image.height, x0 = window.x0, y0 = window.y0;
  const int full_width = window.full_width > 0 ? window.full_width : width;
  const int full_height = window.full_height > 0 ? window.full_height : height;
  if (x0 < 0 || y0 < 0 || x0 + width > full_width || y0 + height > full_height)
    throw std::invalid_argument("render_adaptive: the window does not fit in the picture");
  tbb::enumerable_thread_specific<Counters> counters;
  const int limit = code_limit(aa.threshold);
  // The batches of the passes that take them: `batch`, else `sample` one by one.
  const RasterBatchSampler one_by_one = [&](const RasterSample* at, int count, Color* values) {
    for (int i = 0; i < count; ++i) values[i] = sample(at[i].x, at[i].y, *at[i].state);
  };
  const RasterBatchSampler& trace = batch ? batch : one_by_one;

  switch (aa.method) {
    case AntialiasMethod::kNone:
      throw std::invalid_argument("render_adaptive: no adaptive method");

    case AntialiasMethod::kNeighbour: {
      // Method 1: a pixel that differs from a neighbour is refined (refine_pixels), up to
      // kMaxRasterBatch pixels of a row at once.
      const FirstPass first = centre_pass(x0, y0, width, height, full_width, full_height, seed,
                                          trace, image, counters, row_done);
      const int n = aa.depth;
      for_rows(height, counters, row_done, [&](int row, Counters& c) {
        if (n <= 1) return;
        const int y = y0 + row;
        int xs[kMaxRasterBatch], count = 0;
        for (int x = x0; x < x0 + width; ++x) {
          if (!differs(first, x, y, limit)) continue;
          xs[count++] = x;
          if (count == kMaxRasterBatch) {
            refine_pixels(xs, count, y, x0, y0, n, seed, trace, image, c);
            count = 0;
          }
        }
        if (count > 0) refine_pixels(xs, count, y, x0, y0, n, seed, trace, image, c);
      });
      break;
    }

    case AntialiasMethod::kSubdivide: {
      // Method 2: values at the pixel corners (shared by neighbouring pixels), each pixel
      // subdivided into four while its corners differ, up to depth levels.
      const int cw = width + 1;
      std::vector<Color> corners(std::size_t(cw) * (height + 1));
      for_rows(height + 1, counters, nullptr, [&](int row, Counters& c) {
        for (int i = 0; i < cw; ++i) {
          SampleState state{Rng::for_pixel(x0 + i, y0 + row, seed), 0};
          corners[std::size_t(row) * cw + i] = sample(x0 + i, y0 + row, state);
          c.rays += state.rays;
          ++c.samples;
        }
        if (row_done && row < height) row_done();
      });
      for_rows(height, counters, row_done, [&](int row, Counters& c) {
        for (int i = 0; i < width; ++i) {
          const Color corner[4] = {
              corners[std::size_t(row) * cw + i], corners[std::size_t(row) * cw + i + 1],
              corners[std::size_t(row + 1) * cw + i], corners[std::size_t(row + 1) * cw + i + 1]};
          const int x = x0 + i, y = y0 + row;
          SampleState state{Rng::for_pixel(x, y, seed + kRefineSalt), 0};
          std::uint64_t samples = 0;
          image.set(i, row,
                    Vec3f(subdivide(x, y, 1, corner, 0, aa, limit, sample, state, samples)));
          c.rays += state.rays;
          c.samples += samples;
        }
      });
      break;
    }

    case AntialiasMethod::kVariance: {
      // A pixel that differs from a neighbour takes rounds of four samples (2 x 2 strata,
      // jittered) until the standard error of its mean is at most threshold / 4 in every
      // channel (after at least two rounds) or it has depth x depth samples (rounded up to 4).
      const FirstPass first = centre_pass(x0, y0, width, height, full_width, full_height, seed,
                                          trace, image, counters, row_done);
      const int most = std::max(8, (aa.depth * aa.depth + 3) / 4 * 4);
      const double target = aa.threshold / 4;
      for_rows(height, counters, row_done, [&](int row, Counters& c) {
        const int y = y0 + row;
        for (int x = x0; x < x0 + width; ++x) {
          if (differs(first, x, y, limit))
            image.set(x - x0, row, Vec3f(refine_by_variance(x, y, seed, most, target, sample, c)));
        }
      });
      break;
    }
  }
  for (const Counters& c : counters) {
    stats.rays += c.rays;
    stats.samples += c.samples;
  }
}

}  // namespace raycast

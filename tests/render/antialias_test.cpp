#include "render/antialias.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_error.h"
#include "load/demo_scene.h"
#include "load/loader.h"
#include "render/renderer.h"

namespace raycast {
namespace {

RenderOptions small(AntialiasMethod method, double threshold, int depth, int threads) {
  RenderOptions options;
  options.width = 40;
  options.height = 30;
  options.progress = false;
  options.threads = threads;
  options.antialias = AntialiasSettings{method, threshold, depth};
  return options;
}

double rmse(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double d =
        std::clamp(double(a.rgb[i]), 0.0, 1.0) - std::clamp(double(b.rgb[i]), 0.0, 1.0);
    sum += d * d;
  }
  return std::sqrt(sum / double(a.rgb.size()));
}

TEST(ColourDistance, SumOfClampedChannelDifferences) {
  EXPECT_EQ(colour_distance({0, 0, 0}, {0, 0, 0}), 0);
  EXPECT_EQ(colour_distance({1, 0, 0}, {0, 0.5, 0.25}),
            (255 + linear_to_srgb8(0.5f) + linear_to_srgb8(0.25f)) / 255.0);
  EXPECT_EQ(colour_distance({0.2, 0.2, 0.2}, {0.2, 0.2, 0.2}), 0);
  EXPECT_EQ(colour_distance({3, -1, 0.5}, {1, 0, 0.5}), 0);  // clamped to [0, 1] first
  EXPECT_EQ(colour_distance({0, 0, 0}, {2, 2, 2}), 3);
}

TEST(ColourDistance, EqualsTheDisplayedCodesDividedBy255) {
  // The sum of the channels' 8-bit sRGB code differences, divided by 255 once, bit for bit.
  std::uint64_t h = 1;
  auto next = [&] {
    h = h * 6364136223846793005ull + 1442695040888963407ull;
    return double(h >> 11) * 0x1p-53 * 1.2 - 0.1;  // in [-0.1, 1.1): both clamps too
  };
  for (int i = 0; i < 2000; ++i) {
    const Color a{next(), next(), next()}, b{next(), next(), next()};
    int codes = 0;
    for (int c = 0; c < 3; ++c)
      codes += std::abs(int(linear_to_srgb8(float(a[c]))) - int(linear_to_srgb8(float(b[c]))));
    ASSERT_EQ(colour_distance(a, b), codes / 255.0) << i;
  }
}

TEST(Antialias, Method1_RefinesExactlyThePixelsThatDifferFromANeighbour) {
  // A 9 x 7 picture of blocks of different grey levels (and a window of it): the refined pixels
  // are those whose centre value differs from one of its four neighbours' (inside the picture)
  // by more than the threshold, found here by brute force; each takes its 3 x 3 strata in order,
  // one jittered sample per stratum (the middle one is the centre sample).
  auto grey = [](double x, double y) {
    const int cell = int(std::floor(x / 3)) + 2 * int(std::floor(y / 2));
    const double g = (cell % 4) * 0.25;
    return Color{g, g, g};
  };
  const int w = 9, h = 7;
  const double threshold = 0.3;
  std::vector<bool> want(w * h, false);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Color c = grey(x + 0.5, y + 0.5);
      const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
      for (int k = 0; k < 4; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx >= 0 && ny >= 0 && nx < w && ny < h &&
            colour_distance(c, grey(nx + 0.5, ny + 0.5)) > threshold)
          want[y * w + x] = true;
      }
    }
  for (const RasterWindow window : {RasterWindow{}, RasterWindow{2, 1, w, h}}) {
    const int iw = window.full_width ? 5 : w, ih = window.full_height ? 4 : h;
    std::vector<std::vector<std::pair<double, double>>> calls(w * h);
    const RasterSampler sample = [&](double x, double y, SampleState& state) {
      ++state.rays;
      calls[int(y) * w + int(x)].emplace_back(x, y);
      return grey(x, y);
    };
    Image image(iw, ih);
    AdaptiveStats stats;
    render_adaptive({AntialiasMethod::kNeighbour, threshold, 3}, 1, sample, image, stats, nullptr,
                    window);
    int refined = 0;
    for (int y = window.y0; y < window.y0 + ih; ++y)
      for (int x = window.x0; x < window.x0 + iw; ++x) {
        const auto& c = calls[y * w + x];
        EXPECT_EQ(c.size(), want[y * w + x] ? 9u : 1u) << x << "," << y;
        refined += want[y * w + x];
        if (c.size() != 9) continue;
        for (int k = 1; k < 9; ++k) {  // c[0] is the centre; then the strata, the middle skipped
          const int s = k <= 4 ? k - 1 : k;
          EXPECT_EQ(int(std::floor((c[k].first - x) * 3)), s % 3) << x << "," << y << "," << k;
          EXPECT_EQ(int(std::floor((c[k].second - y) * 3)), s / 3) << x << "," << y << "," << k;
        }
      }
    EXPECT_GT(refined, 0);
    std::uint64_t ring = 0;  // the first pass also samples the one-pixel ring around a window
    for (const auto& c : calls) ring += !c.empty();
    EXPECT_EQ(stats.samples, ring + 8u * std::uint64_t(refined));
  }
}

TEST(Antialias, EveryMethod_OneAndTwoThreadsGiveIdenticalImages) {
  const Scene scene = load_demo_scene();
  for (auto method :
       {AntialiasMethod::kNeighbour, AntialiasMethod::kSubdivide, AntialiasMethod::kVariance}) {
    RenderStats one, two;
    const Image a = render(scene, small(method, 0.1, 3, 1), &one);
    const Image b = render(scene, small(method, 0.1, 3, 2), &two);
    EXPECT_EQ(a.rgb, b.rgb) << int(method);
    EXPECT_EQ(one.rays, two.rays) << int(method);
    EXPECT_EQ(one.samples, two.samples) << int(method);
    EXPECT_EQ(one.antialias, method);
  }
}

TEST(Antialias, ThresholdAboveEveryDistance_NoRefinement) {
  // Distances are at most 3, so nothing is refined: method 1 and variance trace the centre
  // samples only and equal a 1-sample render; method 2 traces the (w+1) x (h+1) corners.
  const Scene scene = load_demo_scene();
  RenderOptions fixed = small(AntialiasMethod::kNone, 0, 1, 1);
  fixed.antialias.reset();
  fixed.spp = 1;
  const Image one_spp = render(scene, fixed);
  for (auto method : {AntialiasMethod::kNeighbour, AntialiasMethod::kVariance}) {
    RenderStats stats;
    const Image image = render(scene, small(method, 3.5, 4, 1), &stats);
    EXPECT_EQ(image.rgb, one_spp.rgb) << int(method);
    EXPECT_EQ(stats.samples, 40u * 30u) << int(method);
  }
  RenderStats stats;
  render(scene, small(AntialiasMethod::kSubdivide, 3.5, 4, 1), &stats);
  EXPECT_EQ(stats.samples, 41u * 31u);
}

TEST(Antialias, ThresholdEqualToTheDistance_NoRefinementJustBelowIt_Refinement) {
  // Two halves of a 2 x 1 picture whose colours lie exactly `d` apart: a pixel is refined when
  // the distance exceeds the threshold, so threshold d refines nothing and the next double
  // below d refines both pixels (method 1: 8 new samples each; method 2: the pixels' squares).
  const Color a{0.1, 0.6, 0.3}, b{0.7, 0.2, 0.35};
  const double d = colour_distance(a, b);
  const RasterSampler sample = [&](double x, double, SampleState& state) {
    ++state.rays;
    return x < 1 ? a : b;
  };
  for (const auto method : {AntialiasMethod::kNeighbour, AntialiasMethod::kSubdivide}) {
    const std::uint64_t first = method == AntialiasMethod::kNeighbour ? 2 : 6;
    for (const double threshold : {d, std::nextafter(d, 0.0)}) {
      Image image(2, 1);
      AdaptiveStats stats;
      render_adaptive({method, threshold, 3}, 1, sample, image, stats, nullptr);
      if (threshold == d)
        EXPECT_EQ(stats.samples, first) << int(method);
      else
        EXPECT_GT(stats.samples, first) << int(method);
    }
  }
}

TEST(Antialias, FlatImage_ExactBackgroundEverywhere) {
  const Scene scene = load_scene_text(R"(
render: {background: [0.25, 0.5, 0.75]}
objects:
  - sphere: {center: [0, 0, -1000], radius: 1}
camera: {position: [0, 0, 0], look_at: [0, 0, 1]}
)");
  for (auto method :
       {AntialiasMethod::kNeighbour, AntialiasMethod::kSubdivide, AntialiasMethod::kVariance}) {
    const Image image = render(scene, small(method, 0, 3, 2));
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
      ASSERT_EQ(image.rgb[i], 0.25f);
      ASSERT_EQ(image.rgb[i + 1], 0.5f);
      ASSERT_EQ(image.rgb[i + 2], 0.75f);
    }
  }
}

TEST(Antialias, EdgesRefined_CloserToTheReferenceThanOneSample) {
  // The demo's edges: every adaptive method lands nearer a 64-sample render than 1 sample does,
  // refining only some pixels (fewer samples than refining every one).
  const Scene scene = load_demo_scene();
  RenderOptions fixed = small(AntialiasMethod::kNone, 0, 1, 2);
  fixed.antialias.reset();
  fixed.spp = 64;
  const Image reference = render(scene, fixed);
  fixed.spp = 1;
  const double one_spp = rmse(render(scene, fixed), reference);
  for (auto method :
       {AntialiasMethod::kNeighbour, AntialiasMethod::kSubdivide, AntialiasMethod::kVariance}) {
    RenderStats stats;
    const double error = rmse(render(scene, small(method, 0.1, 3, 2), &stats), reference);
    EXPECT_LT(error, 0.8 * one_spp) << int(method);
    // Method 2 at depth 3 may trace up to 105 points in a pixel (duplicates on shared edges).
    const unsigned most = method == AntialiasMethod::kSubdivide ? 105u : 9u;
    EXPECT_LT(stats.samples, 40u * 30u * most) << int(method);
    EXPECT_GT(stats.samples, 41u * 31u) << int(method);
  }
}

TEST(Antialias, Method1_OddDepthReusesTheCentreSampleForTheMiddleStratum) {
  // A 4 x 1 image with an edge at x = 2: pixels 1 and 2 differ from a neighbour and are
  // refined. Depth 3: 8 new samples each, none at a pixel centre again, the centre value
  // counted once in the mean of 9; depth 2: 4 new samples each.
  for (int depth : {2, 3}) {
    std::vector<std::pair<double, double>> calls;
    const RasterSampler sample = [&](double x, double y, SampleState& state) {
      calls.emplace_back(x, y);
      ++state.rays;
      return x < 2 ? Color{1, 1, 1} : Color{0, 0, 0};
    };
    Image image(4, 1);
    AdaptiveStats stats;
    render_adaptive({AntialiasMethod::kNeighbour, 0.3, depth}, 1, sample, image, stats, nullptr);
    const std::uint64_t refined = depth == 3 ? 8 : 4;
    EXPECT_EQ(stats.samples, 4 + 2 * refined);
    EXPECT_EQ(calls.size(), 4 + 2 * refined);
    int centres = 0;
    for (const auto& [x, y] : calls) centres += x - std::floor(x) == 0.5 && y == 0.5;
    EXPECT_EQ(centres, 4) << depth;  // the first pass only
    // Pixel 1 ([1, 2]) lies left of the edge: all 1; pixel 2 all 0; the others untouched.
    for (int x = 0; x < 4; ++x) EXPECT_EQ(image.at(x, 0)[0], x < 2 ? 1.0f : 0.0f) << x;
  }
}

TEST(Antialias, Loader_ReadsSettingsAndRejectsBadOnes) {
  const Scene scene = load_scene_text(R"(
render: {antialias: {method: 2, threshold: 0.1, depth: 4}}
objects: [{sphere: {radius: 1}}]
)");
  EXPECT_EQ(scene.render.antialias.method, AntialiasMethod::kSubdivide);
  EXPECT_EQ(scene.render.antialias.threshold, 0.1);
  EXPECT_EQ(scene.render.antialias.depth, 4);
  const Scene named = load_scene_text(
      "render: {antialias: {method: variance}}\nobjects: [{sphere: {radius: 1}}]\n");
  EXPECT_EQ(named.render.antialias.method, AntialiasMethod::kVariance);
  EXPECT_EQ(named.render.antialias.threshold, 0.3);  // defaults as POV-Ray's +A0.3 +R3
  EXPECT_EQ(named.render.antialias.depth, 3);
  for (const std::string bad :
       {"{method: 3}", "{method: 1, threshold: -1}", "{method: 1, depth: 0}",
        "{method: 1, depth: 17}", "{threshold: 0.3}", "{method: 1, extra: 2}",
        "{method: 1, threshold: .nan}"}) {
    EXPECT_THROW(load_scene_text("render: {antialias: " + bad + "}\nobjects: []\n"), SceneError)
        << bad;
  }
}

TEST(Antialias, SppOverride_TurnsTheScenesAdaptiveSamplingOff) {
  Scene scene = load_demo_scene();
  scene.render.antialias = {AntialiasMethod::kNeighbour, 0.0, 3};
  RenderOptions options;
  options.width = 20;
  options.height = 15;
  options.progress = false;
  RenderStats adaptive, fixed;
  render(scene, options, &adaptive);
  EXPECT_EQ(adaptive.antialias, AntialiasMethod::kNeighbour);
  options.spp = 2;
  render(scene, options, &fixed);
  EXPECT_EQ(fixed.antialias, AntialiasMethod::kNone);
  EXPECT_EQ(fixed.samples, 20u * 15u * 2u);
}

TEST(Antialias, BadSettings_Throw) {
  const Scene scene = load_demo_scene();
  EXPECT_THROW(render(scene, small(AntialiasMethod::kNeighbour, -1, 3, 1)), std::invalid_argument);
  EXPECT_THROW(render(scene, small(AntialiasMethod::kNeighbour, NAN, 3, 1)), std::invalid_argument);
  EXPECT_THROW(render(scene, small(AntialiasMethod::kSubdivide, 0.3, 0, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace raycast

// Rng::for_pixel seeds on the first draw: the numbers must be those of the generator seeded at
// once from the pixel's key (its definition), for copies made before and after the first draw too.
#include "render/rng.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace raycast {
namespace {

Rng seeded_at_once(int x, int y, unsigned seed) {
  const std::uint64_t key = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
  return Rng(mix64(key) ^ mix64(0x9e3779b97f4a7c15ull + seed));
}

TEST(Rng, ForPixel_DrawsWhatTheSeedItDefinesGives) {
  const int xs[] = {0, 1, 639, -1, 2147483647};
  const int ys[] = {0, 7, 479, -5};
  const unsigned seeds[] = {0u, 1u, 12345u, 0xffffffffu};
  for (int x : xs)
    for (int y : ys)
      for (unsigned seed : seeds) {
        Rng lazy = Rng::for_pixel(x, y, seed), eager = seeded_at_once(x, y, seed);
        for (int k = 0; k < 8; ++k) ASSERT_EQ(lazy.next(), eager.next()) << x << " " << y;
        EXPECT_EQ(lazy.uniform(), eager.uniform());
      }
}

TEST(Rng, ForPixel_CopiesBeforeAndAfterTheFirstDrawFollowTheSameSequence) {
  const Rng fresh = Rng::for_pixel(12, 34, 5);
  Rng a = fresh, b = fresh, eager = seeded_at_once(12, 34, 5);
  const std::uint32_t first = eager.next();
  EXPECT_EQ(a.next(), first);
  EXPECT_EQ(b.next(), first);
  Rng c = a;  // copied after its first draw
  const std::uint32_t second = eager.next();
  EXPECT_EQ(a.next(), second);
  EXPECT_EQ(c.next(), second);
  // Different pixels and seeds give different streams.
  EXPECT_NE(Rng::for_pixel(12, 34, 5).next(), Rng::for_pixel(34, 12, 5).next());
  EXPECT_NE(Rng::for_pixel(12, 34, 5).next(), Rng::for_pixel(12, 34, 6).next());
}

}  // namespace
}  // namespace raycast

// The generic traversal's stack: it grows instead of dropping children.
#include <gtest/gtest.h>

#include "accel/bvh_traverse.h"

namespace raycast {
namespace {

TEST(BvhStack, PushesBeyondTheLocalCapacity_PopsEveryEntryInLifoOrder) {
  BvhStack stack;
  for (std::uint32_t i = 0; i < 1000; ++i) stack.push(i, 0.5 * i);
  for (std::uint32_t i = 1000; i-- > 0;) {
    ASSERT_FALSE(stack.empty());
    const BvhStack::Entry e = stack.pop();
    EXPECT_EQ(e.node, i);
    EXPECT_EQ(e.t_enter, 0.5 * i);
  }
  EXPECT_TRUE(stack.empty());
}

}  // namespace
}  // namespace raycast

#include "load/did_you_mean.h"

#include <gtest/gtest.h>

namespace raycast {
namespace {

TEST(EditDistance, HandComputedCases_Match) {
  EXPECT_EQ(edit_distance("", ""), 0);
  EXPECT_EQ(edit_distance("abc", ""), 3);
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(edit_distance("radius", "radius"), 0);
  EXPECT_EQ(edit_distance("radus", "radius"), 1);     // deletion
  EXPECT_EQ(edit_distance("objectz", "objects"), 1);  // substitution
  EXPECT_EQ(edit_distance("widht", "width"), 1);      // swap of neighbours
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(edit_distance("ab", "ba"), 1);
  EXPECT_EQ(edit_distance("ca", "abc"), 3);  // optimal string alignment, not full Damerau
}

TEST(NearestName, CloseCandidate_IsSuggested) {
  const std::vector<std::string> keys = {"camera", "image", "render", "objects"};
  EXPECT_EQ(nearest_name("camra", keys), "camera");
  EXPECT_EQ(nearest_name("objectz", keys), "objects");
  EXPECT_EQ(did_you_mean("imgae", keys), " (did you mean 'image'?)");
}

TEST(NearestName, FarOrTinyWords_AreNotSuggested) {
  const std::vector<std::string> keys = {"camera", "image", "u", "v"};
  EXPECT_EQ(nearest_name("lights", keys), "");
  EXPECT_EQ(nearest_name("w", keys), "");  // one edit from 'u' but the word is one letter
  EXPECT_EQ(did_you_mean("zzzz", keys), "");
  EXPECT_EQ(nearest_name("camera", {"camera"}), "");  // the word itself is not a suggestion
}

}  // namespace
}  // namespace raycast

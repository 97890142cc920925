// base/vec3.h: the small vector and box every floor uses.
#include "base/vec3.h"

#include <gtest/gtest.h>

namespace scallop {
namespace {

TEST(Box3, DefaultIsEmptyAndExtendingMakesTheBoundingBox) {
  Box3 b;
  EXPECT_TRUE(b.empty());
  b.extend(Vec3{1, -2, 3});
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.min, (Vec3{1, -2, 3}));
  EXPECT_EQ(b.max, (Vec3{1, -2, 3}));
  b.extend(Box3(Vec3{-1, 0, 0}, Vec3{0, 5, 4}));
  EXPECT_EQ(b.min, (Vec3{-1, -2, 0}));
  EXPECT_EQ(b.max, (Vec3{1, 5, 4}));
}

TEST(Box3, MinMaxConstructorKeepsBothCornersAndAnInvertedOneIsEmpty) {
  const Box3 stock(Vec3{0, 0, -5}, Vec3{20, 20, 0});
  EXPECT_FALSE(stock.empty());
  EXPECT_EQ(stock.min, (Vec3{0, 0, -5}));
  EXPECT_EQ(stock.max, (Vec3{20, 20, 0}));
  EXPECT_TRUE(Box3(Vec3{0, 0, 1}, Vec3{1, 1, 0}).empty());
}

TEST(Vec3, CrossDotAndLengthFollowTheRightHandRule) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  EXPECT_EQ(cross(x, y), (Vec3{0, 0, 1}));
  EXPECT_EQ(dot(x, y), 0);
  EXPECT_DOUBLE_EQ(length(Vec3{3, 4, 12}), 13);
  EXPECT_DOUBLE_EQ(length(normalize(Vec3{3, 4, 12})), 1);
  EXPECT_FALSE(isFinite(Vec3{0, HUGE_VAL, 0}));
}

}  // namespace
}  // namespace scallop

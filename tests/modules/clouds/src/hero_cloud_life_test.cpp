// A hero cloud's life on its timeline (clouds/hero_cloud_life.h): the growth and dissipation it
// gives at each phase, continuous through every ramp and across repeats, and its fields
// checked by name.
#include <gtest/gtest.h>

#include <cmath>

#include "clouds/hero_cloud_life.h"

namespace {

clouds::HeroCloudLifecycle shortLife() {
  clouds::HeroCloudLifecycle l;
  l.startSeconds = 100.0;
  l.growSeconds = 60.0f;
  l.matureSeconds = 120.0f;
  l.dissipateSeconds = 40.0f;
  l.restSeconds = 30.0f;
  return l;
}

TEST(HeroCloudLife, EachPhaseGivesItsLife) {
  const clouds::HeroCloudLifecycle l = shortLife();
  const auto at = [&](double s) { return clouds::heroCloudLife(l, s); };
  EXPECT_EQ(at(0.0).growth, 0.0f);    // before it starts: not there
  EXPECT_EQ(at(100.0).growth, 0.0f);  // starts from nothing
  EXPECT_FLOAT_EQ(at(130.0).growth, 0.5f);
  EXPECT_EQ(at(130.0).dissipation, 0.0f);
  EXPECT_EQ(at(200.0).growth, 1.0f);  // mature
  EXPECT_EQ(at(200.0).dissipation, 0.0f);
  EXPECT_FLOAT_EQ(at(300.0).dissipation, 0.5f);
  EXPECT_EQ(at(300.0).growth, 1.0f);
  EXPECT_EQ(at(330.0).dissipation, 1.0f);  // resting: gone
  // One period (250 s) on, it grows again.
  EXPECT_FLOAT_EQ(at(130.0 + 250.0).growth, 0.5f);
  EXPECT_FLOAT_EQ(at(130.0 + 250.0 * 1000.0).growth, 0.5f);

  clouds::HeroCloudLifecycle once = l;
  once.repeat = false;
  EXPECT_EQ(clouds::heroCloudLife(once, 130.0 + 250.0).dissipation, 1.0f);
}

// No jumps: through a whole period and into the next, the life moves by no more than its
// fastest ramp allows (a step of 0.01 s on the 40 s dissipation: 1/4000), even after hours.
TEST(HeroCloudLife, IsContinuousThroughEveryPhaseAndRepeat) {
  const clouds::HeroCloudLifecycle l = shortLife();
  for (const double hours : {0.0, 10.0}) {
    const double from = 90.0 + 3600.0 * hours;
    clouds::HeroCloudLife previous = clouds::heroCloudLife(l, from);
    float largest = 0.0f;
    for (int k = 1; k <= 60000; ++k) {
      const clouds::HeroCloudLife now = clouds::heroCloudLife(l, from + k * 0.01);
      // Resting (dissipated) to newborn (not grown) is the same nothing.
      const bool rebirth = previous.dissipation == 1.0f && now.dissipation == 0.0f;
      if (!rebirth) {
        largest = std::max({largest, std::abs(now.growth - previous.growth),
                            std::abs(now.dissipation - previous.dissipation)});
      } else {
        EXPECT_LE(now.growth, 0.01f / 60.0f + 1e-4f);
      }
      previous = now;
    }
    EXPECT_LE(largest, 0.01f / 40.0f + 1e-4f) << hours << " h";
    EXPECT_GT(largest, 0.0f);
  }
}

TEST(HeroCloudLife, FieldsAreCheckedByName) {
  EXPECT_EQ(clouds::validateHeroCloudLifecycle(shortLife()), "");
  const auto problem = [](auto change) {
    clouds::HeroCloudLifecycle l = shortLife();
    change(l);
    return clouds::validateHeroCloudLifecycle(l);
  };
  EXPECT_NE(problem([](auto& l) { l.startSeconds = NAN; }).find("startSeconds"), std::string::npos);
  EXPECT_NE(problem([](auto& l) { l.growSeconds = 0.0f; }).find("growSeconds = 0"),
            std::string::npos);
  EXPECT_NE(problem([](auto& l) { l.matureSeconds = -1.0f; }).find("matureSeconds"),
            std::string::npos);
  EXPECT_NE(problem([](auto& l) { l.dissipateSeconds = INFINITY; }).find("dissipateSeconds"),
            std::string::npos);
  EXPECT_NE(problem([](auto& l) { l.restSeconds = NAN; }).find("restSeconds"), std::string::npos);
}

}  // namespace

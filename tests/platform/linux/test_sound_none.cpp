// A build without libasound (platform/linux/alsa_none.cpp): asking for sound is one sentence
// that says so and names the fix, and no sound.
#include <gtest/gtest.h>

#include "app/platform.hpp"

TEST(SoundNone, SaysThisBuildHasNoSound) {
    std::string error;
    EXPECT_EQ(noneuclid::platform::open_sound({}, error), nullptr);
    EXPECT_EQ(error, "this build has no sound (libasound was not found when it was built): install libasound2-dev and "
                     "rebuild; the run goes on silent.");
}

// The GPIO backend of a build without libgpiod (platform/linux/gpio_none.cpp), compiled on its
// own so that every build checks its sentence, whichever backend noneuclid_input has.
#include <gtest/gtest.h>

#include "linux/input.hpp"

namespace p = noneuclid::platform;

TEST(OpenGpioWithoutLibgpiod, OneSentence) {
    p::GpioConfig c;
    c.chips = {"pinctrl-bcm2711"};
    c.buttons = {{noneuclid::world::Action::thrust, 17, 11}};
    std::string error;
    EXPECT_EQ(p::open_gpio(c, error), nullptr);
    EXPECT_EQ(error, "this build has no GPIO support: install libgpiod-dev and rebuild");
    EXPECT_STREQ(p::gpiod_version(), "none");
}

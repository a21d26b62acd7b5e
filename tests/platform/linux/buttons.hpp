// The input tests' configuration: two buttons (thrust on line 17, header pin 11; left on line 27,
// pin 13) on the Raspberry Pi's two GPIO chip labels.
#pragma once

#include "linux/gpio_common.hpp"
#include "world/action.hpp"

namespace noneuclid::test {

inline platform::GpioConfig two_buttons() {
    platform::GpioConfig c;
    c.chips = {"pinctrl-bcm2711", "pinctrl-rp1"};
    c.buttons = {{world::Action::thrust, 17, 11}, {world::Action::left, 27, 13}};
    return c;
}

}  // namespace noneuclid::test

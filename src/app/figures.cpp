#include "app/figures.hpp"

namespace noneuclid::app {

const Figure kFigures[] = {
    {"kiosk", "kiosk", 60, 0, true, true, 800, 480, "the kiosk's picture"},
    {"fig1", "fig1", 120, 0, false, false, 600, 600, "figure 1's bodies"},
    {"fig14", "fig14", 600, 40, false, false, 600, 600, "figure 14's time-lapse"},
    {"fig15", "fig15", 600, 40, false, false, 600, 600, "figure 15's time-lapse"},
    {"fig16", "fig16", 120, 15, false, false, 600, 600, "figure 16's time-lapse"},
    {"fig17", "fig17", 250, 25, false, true, 600, 600, "figure 17's time-lapse through a change of K"},
};
const int kFigureCount = static_cast<int>(sizeof kFigures / sizeof kFigures[0]);

}  // namespace noneuclid::app

// GPIO buttons through libgpiod 1.6 (the v1 API: Debian 12, Raspberry Pi OS Bookworm).
// One event request per line (pull-up, active-low, both edges), each with its own fd; the v1
// API has no kernel debounce, so ButtonTracker debounces in software on CLOCK_MONOTONIC and
// deadline_ns() tells the frame loop when a debounce window closes.
#include <fcntl.h>
#include <gpiod.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "linux/gpio_common.hpp"
#include "linux/input.hpp"

namespace noneuclid::platform {

namespace {

using gpio_detail::ButtonTracker;

int probe_chip(const std::string& path, gpio_detail::ChipInfo& info) {
    gpiod_chip* chip = gpiod_chip_open(path.c_str());
    if (!chip) return errno ? errno : ENODEV;
    const char* label = gpiod_chip_label(chip);
    info.label = label ? label : "";
    info.num_lines = gpiod_chip_num_lines(chip);
    gpiod_chip_close(chip);
    return 0;
}

class GpioV1 final : public InputSource {
public:
    ~GpioV1() override {
        if (chip_) gpiod_chip_close(chip_);  // releases every requested line
    }

    bool open(const GpioConfig& config, std::string& error) {
        error = gpio_detail::check_config(config);
        if (!error.empty()) return false;
        gpio_detail::ChipInfo info;
        if (!gpio_detail::find_chip(config, probe_chip, path_, info, error)) return false;
        chip_ = gpiod_chip_open(path_.c_str());
        if (!chip_) {
            int err = errno;
            error = (err == EACCES || err == EPERM) ? gpio_detail::permission_error(path_)
                                                    : "cannot open " + path_ + ": " + std::strerror(err);
            return false;
        }
        label_ = info.label;
        const std::string chip_name = label_ + " (" + path_ + ")";

        const int flags = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP | GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW;
        for (const auto& b : config.buttons) {
            if (b.line >= info.num_lines) {
                error = gpio_detail::line_range_error(b, chip_name, info.num_lines);
                return false;
            }
            gpiod_line* line = gpiod_chip_get_line(chip_, b.line);
            if (!line) {
                error = "cannot get " + gpio_detail::describe_line(b) + " on " + chip_name + ": " +
                        std::strerror(errno);
                return false;
            }
            if (gpiod_line_request_both_edges_events_flags(line, config.consumer.c_str(), flags) != 0) {
                int err = errno;
                std::string consumer;
                if (gpiod_line_update(line) == 0 && gpiod_line_consumer(line)) consumer = gpiod_line_consumer(line);
                error = gpio_detail::request_error(b, chip_name, err, consumer);
                return false;
            }
            int fd = gpiod_line_event_get_fd(line);
            if (fd < 0 || fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK) != 0) {
                error = "cannot set up events for " + gpio_detail::describe_line(b) + " on " + chip_name + ": " +
                        std::strerror(errno);
                return false;
            }
            lines_.push_back(line);
            fds_.push_back(fd);
        }

        debounce_ms_ = config.debounce_ms;
        tracker_.init(config, static_cast<int64_t>(config.debounce_ms) * 1000000);
        for (size_t i = 0; i < lines_.size(); ++i) {
            int v = gpiod_line_get_value(lines_[i]);  // logical: 1 = pressed (active-low)
            tracker_.set_initial(static_cast<int>(i), v == 1);
        }
        describe_ = "gpio: " + label_ + " (" + path_ + "), " + std::to_string(lines_.size()) + " button" +
                    (lines_.size() == 1 ? "" : "s") + ", libgpiod " + gpiod_version() + ", " +
                    (debounce_ms_ ? "software debounce " + std::to_string(debounce_ms_) + " ms" : "no debounce");
        return true;
    }

    std::string describe() const override { return describe_; }

    int fds(pollfd* out, int max) override {
        int n = 0;
        for (; n < max && n < static_cast<int>(fds_.size()); ++n) out[n] = pollfd{fds_[n], POLLIN, 0};
        return n;
    }

    int read(world::InputEvent* out, int max, int64_t now_ns) override {
        // Leave room for every button's debounce window closing in this call.
        int budget = tracker_.space() - tracker_.count();
        for (size_t i = 0; i < lines_.size() && budget > 0; ++i) {
            while (budget > 0) {
                const int want = std::min(budget, kBatch);
                int n = gpiod_line_event_read_fd_multiple(fds_[i], events_, static_cast<unsigned>(want));
                if (n <= 0) break;  // EAGAIN: nothing pending
                for (int k = 0; k < n; ++k)
                    tracker_.edge(static_cast<int>(i), events_[k].event_type == GPIOD_LINE_EVENT_RISING_EDGE, now_ns);
                budget -= n;
                if (n < want) break;
            }
        }
        tracker_.expire(now_ns, [this](int i) { return gpiod_line_get_value(lines_[i]); });
        return tracker_.pop(out, max);
    }

    int64_t deadline_ns() const override { return tracker_.deadline(); }

private:
    static constexpr int kBatch = 16;
    gpiod_chip* chip_ = nullptr;
    std::string path_, label_, describe_;
    unsigned debounce_ms_ = 0;
    std::vector<gpiod_line*> lines_;
    std::vector<int> fds_;
    ButtonTracker tracker_;
    gpiod_line_event events_[kBatch];
};

}  // namespace

std::unique_ptr<InputSource> open_gpio(const GpioConfig& config, std::string& error) {
    auto src = std::make_unique<GpioV1>();
    if (!src->open(config, error)) return nullptr;
    error.clear();
    return src;
}

const char* gpiod_version() {
    static const std::string v = std::string(gpiod_version_string()) + " (v1 API)";
    return v.c_str();
}

}  // namespace noneuclid::platform

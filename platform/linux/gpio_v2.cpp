// GPIO buttons through libgpiod 2.x (the v2 API: Debian 13, or bookworm-backports through
// platform/debian/gpiod2-prefix.sh). One request for all lines (pull-up, active-low, both
// edges, the kernel's debounce), one fd; edge events are read into a buffer allocated at open.
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
    int err = 0;
    if (gpiod_chip_info* ci = gpiod_chip_get_info(chip)) {
        const char* label = gpiod_chip_info_get_label(ci);
        info.label = label ? label : "";
        info.num_lines = static_cast<unsigned>(gpiod_chip_info_get_num_lines(ci));
        gpiod_chip_info_free(ci);
    } else {
        err = errno ? errno : EIO;
    }
    gpiod_chip_close(chip);
    return err;
}

class GpioV2 final : public InputSource {
public:
    ~GpioV2() override {
        if (buffer_) gpiod_edge_event_buffer_free(buffer_);
        if (request_) gpiod_line_request_release(request_);
        if (chip_) gpiod_chip_close(chip_);
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
        const std::string chip_name = info.label + " (" + path_ + ")";
        for (const auto& b : config.buttons) {
            if (b.line >= info.num_lines) {
                error = gpio_detail::line_range_error(b, chip_name, info.num_lines);
                return false;
            }
            offsets_.push_back(b.line);
        }

        if (!request(config, error, chip_name)) return false;

        request_fd_ = gpiod_line_request_get_fd(request_);
        if (request_fd_ < 0 || fcntl(request_fd_, F_SETFL, fcntl(request_fd_, F_GETFL) | O_NONBLOCK) != 0) {
            error = "cannot set up GPIO events on " + chip_name + ": " + std::strerror(errno);
            return false;
        }
        buffer_ = gpiod_edge_event_buffer_new(kBatch);
        if (!buffer_) {
            error = "cannot set up GPIO events on " + chip_name + ": out of memory";
            return false;
        }

        tracker_.init(config, 0);  // the kernel debounces
        values_.resize(offsets_.size());
        if (gpiod_line_request_get_values_subset(request_, offsets_.size(), offsets_.data(), values_.data()) == 0)
            for (size_t i = 0; i < values_.size(); ++i)
                tracker_.set_initial(static_cast<int>(i), values_[i] == GPIOD_LINE_VALUE_ACTIVE);

        const size_t n = offsets_.size();
        describe_ = "gpio: " + info.label + " (" + path_ + "), " + std::to_string(n) + " button" +
                    (n == 1 ? "" : "s") + ", libgpiod " + gpiod_version() + ", " +
                    (config.debounce_ms ? "kernel debounce " + std::to_string(config.debounce_ms) + " ms"
                                        : "no debounce");
        return true;
    }

    std::string describe() const override { return describe_; }

    int fds(pollfd* out, int max) override {
        if (max < 1) return 0;
        out[0] = pollfd{request_fd_, POLLIN, 0};
        return 1;
    }

    int read(world::InputEvent* out, int max, int64_t now_ns) override {
        int budget = std::min(tracker_.space() - tracker_.count(), kBatch);
        while (budget > 0) {
            int n = gpiod_line_request_read_edge_events(request_, buffer_, static_cast<size_t>(budget));
            if (n <= 0) break;  // EAGAIN: nothing pending
            for (int k = 0; k < n; ++k) {
                gpiod_edge_event* ev = gpiod_edge_event_buffer_get_event(buffer_, static_cast<unsigned long>(k));
                const unsigned offset = gpiod_edge_event_get_line_offset(ev);
                const auto it = std::find(offsets_.begin(), offsets_.end(), offset);
                if (it == offsets_.end()) continue;
                tracker_.edge(static_cast<int>(it - offsets_.begin()),
                              gpiod_edge_event_get_event_type(ev) == GPIOD_EDGE_EVENT_RISING_EDGE, now_ns);
            }
            if (n < budget) break;
            budget = std::min(tracker_.space() - tracker_.count(), kBatch);
        }
        return tracker_.pop(out, max);
    }

private:
    bool request(const GpioConfig& config, std::string& error, const std::string& chip_name) {
        gpiod_line_settings* settings = gpiod_line_settings_new();
        gpiod_line_config* line_cfg = gpiod_line_config_new();
        gpiod_request_config* req_cfg = gpiod_request_config_new();
        int err = ENOMEM;
        if (settings && line_cfg && req_cfg &&
            gpiod_line_settings_set_direction(settings, GPIOD_LINE_DIRECTION_INPUT) == 0 &&
            gpiod_line_settings_set_edge_detection(settings, GPIOD_LINE_EDGE_BOTH) == 0 &&
            gpiod_line_settings_set_bias(settings, GPIOD_LINE_BIAS_PULL_UP) == 0) {
            gpiod_line_settings_set_active_low(settings, true);
            gpiod_line_settings_set_debounce_period_us(settings, static_cast<unsigned long>(config.debounce_ms) * 1000);
            gpiod_request_config_set_consumer(req_cfg, config.consumer.c_str());
            if (gpiod_line_config_add_line_settings(line_cfg, offsets_.data(), offsets_.size(), settings) == 0) {
                request_ = gpiod_chip_request_lines(chip_, req_cfg, line_cfg);
                err = request_ ? 0 : errno;
            } else {
                err = errno;
            }
        }
        if (req_cfg) gpiod_request_config_free(req_cfg);
        if (line_cfg) gpiod_line_config_free(line_cfg);
        if (settings) gpiod_line_settings_free(settings);
        if (err == 0) return true;

        // The request is all or nothing: name the first line someone else holds.
        size_t culprit = 0;
        std::string consumer;
        if (err == EBUSY)
            for (size_t i = 0; i < config.buttons.size(); ++i) {
                gpiod_line_info* li = gpiod_chip_get_line_info(chip_, config.buttons[i].line);
                if (!li) continue;
                const bool used = gpiod_line_info_is_used(li);
                const char* c = gpiod_line_info_get_consumer(li);
                if (used) {
                    culprit = i;
                    consumer = c ? c : "";
                }
                gpiod_line_info_free(li);
                if (used) break;
            }
        error = gpio_detail::request_error(config.buttons[culprit], chip_name, err, consumer);
        return false;
    }

    static constexpr int kBatch = 16;
    gpiod_chip* chip_ = nullptr;
    gpiod_line_request* request_ = nullptr;
    gpiod_edge_event_buffer* buffer_ = nullptr;
    int request_fd_ = -1;
    std::string path_, describe_;
    std::vector<unsigned> offsets_;
    std::vector<gpiod_line_value> values_;
    ButtonTracker tracker_;
};

}  // namespace

std::unique_ptr<InputSource> open_gpio(const GpioConfig& config, std::string& error) {
    auto src = std::make_unique<GpioV2>();
    if (!src->open(config, error)) return nullptr;
    error.clear();
    return src;
}

const char* gpiod_version() {
    static const std::string v = std::string(gpiod_api_version()) + " (v2 API)";
    return v.c_str();
}

}  // namespace noneuclid::platform

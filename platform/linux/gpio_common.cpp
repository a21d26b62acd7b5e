#include "linux/gpio_common.hpp"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace noneuclid::platform::gpio_detail {

namespace {

constexpr int kMaxButtons = 32;             // a 40-pin header has 28 GPIO lines
constexpr unsigned kMaxDebounceMs = 1000;

const char* kChipHint = "run `gpiodetect` and set chip in the board file's [gpio] table to one of the labels it lists";

// "/dev/gpiochip12" -> 12; -1 if not of that form.
long chip_number(const std::string& name) {
    const std::string prefix = "gpiochip";
    if (name.compare(0, prefix.size(), prefix) != 0 || name.size() == prefix.size()) return -1;
    char* end = nullptr;
    long n = std::strtol(name.c_str() + prefix.size(), &end, 10);
    return (*end == '\0' && n >= 0) ? n : -1;
}

bool is_path(const std::string& s) { return !s.empty() && s[0] == '/'; }

}  // namespace

std::string describe_line(const GpioButton& button) {
    std::string s = "GPIO line " + std::to_string(button.line) + " (" + world::action_name(button.control);
    if (button.header_pin > 0) s += ", header pin " + std::to_string(button.header_pin);
    return s + ")";
}

std::string check_config(const GpioConfig& config) {
    if (config.buttons.empty())
        return "no GPIO buttons are configured: give each [[button]] in the board file a gpio line";
    if (config.buttons.size() > static_cast<size_t>(kMaxButtons))
        return std::to_string(config.buttons.size()) + " GPIO buttons are configured, more than the " +
               std::to_string(kMaxButtons) + " supported: remove some [[button]] gpio entries from the board file";
    if (config.chips.empty())
        return "no GPIO chip is configured: set chip in the board file's [gpio] table "
               "(`gpiodetect` lists the labels, e.g. pinctrl-bcm2711)";
    for (const auto& c : config.chips)
        if (c.empty()) return "an empty GPIO chip name is configured: remove it from chip in the board file's [gpio] table";
    for (size_t i = 0; i < config.buttons.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (config.buttons[i].line == config.buttons[j].line)
                return "GPIO line " + std::to_string(config.buttons[i].line) + " is given to both " +
                       world::action_name(config.buttons[j].control) + " and " +
                       world::action_name(config.buttons[i].control) +
                       ": give each [[button]] in the board file its own gpio line";
    if (config.debounce_ms > kMaxDebounceMs)
        return "a GPIO debounce of " + std::to_string(config.debounce_ms) + " ms is too long: set debounce_ms in the "
               "board file's [gpio] table between 0 and " + std::to_string(kMaxDebounceMs) + " (10 suits most buttons)";
    return {};
}

std::vector<std::string> list_chips(const std::string& dev_dir) {
    std::vector<std::pair<long, std::string>> found;
    if (DIR* d = opendir(dev_dir.c_str())) {
        while (const dirent* e = readdir(d)) {
            long n = chip_number(e->d_name);
            if (n >= 0) found.emplace_back(n, dev_dir + "/" + e->d_name);
        }
        closedir(d);
    }
    std::sort(found.begin(), found.end());
    std::vector<std::string> out;
    for (auto& f : found) out.push_back(std::move(f.second));
    return out;
}

std::string permission_error(const std::string& what) {
    return "no permission to open " + what + ": add the user to the gpio group "
           "(`sudo usermod -aG gpio $USER`) and log in again";
}

bool find_chip(const GpioConfig& config, ChipProbe probe, std::string& path, ChipInfo& info, std::string& error,
               const std::string& dev_dir) {
    // Probe every chip once, lazily (only if a label is asked for).
    struct Probed {
        std::string path;
        ChipInfo info;
        int err;
    };
    std::vector<Probed> chips;
    bool scanned = false;
    auto scan = [&] {
        if (scanned) return;
        scanned = true;
        for (auto& p : list_chips(dev_dir)) {
            Probed pr{p, {}, 0};
            pr.err = probe(p, pr.info);
            chips.push_back(std::move(pr));
        }
    };

    std::string first_path_error;
    for (const auto& entry : config.chips) {
        if (is_path(entry)) {
            struct stat st {};
            if (stat(entry.c_str(), &st) != 0) {
                if (first_path_error.empty()) first_path_error = entry + " does not exist";
                continue;
            }
            int err = probe(entry, info);
            if (err == 0) {
                path = entry;
                return true;
            }
            if (err == EACCES || err == EPERM) {
                error = permission_error(entry);
                return false;
            }
            if (first_path_error.empty())
                first_path_error = entry + " is not a GPIO chip (" + std::strerror(err) + ")";
            continue;
        }
        scan();
        for (const auto& c : chips)
            if (c.err == 0 && c.info.label == entry) {
                path = c.path;
                info = c.info;
                return true;
            }
    }

    // Nothing matched: say what was tried and what there is.
    std::string tried;
    for (size_t i = 0; i < config.chips.size(); ++i) tried += (i ? ", " : "") + config.chips[i];
    scan();
    std::string present, denied;
    for (const auto& c : chips) {
        if (c.err == 0)
            present += (present.empty() ? "" : ", ") + c.path + " \"" + c.info.label + "\"";
        else if ((c.err == EACCES || c.err == EPERM) && denied.empty())
            denied = c.path;
    }
    const bool any_label = std::any_of(config.chips.begin(), config.chips.end(), [](const std::string& c) { return !is_path(c); });
    if (any_label && !denied.empty()) {
        // Some chips could not be opened: the wanted one is probably among them.
        error = "no permission to open " + denied + " (looking for the GPIO chip " + tried +
                "): add the user to the gpio group (`sudo usermod -aG gpio $USER`) and log in again";
        return false;
    }
    if (!any_label && config.chips.size() == 1 && !first_path_error.empty()) {
        error = first_path_error + ": " + kChipHint + " (or its /dev/gpiochipN path)";
        return false;
    }
    error = "no GPIO chip matches " + tried + " (" +
            (present.empty() ? std::string("this system has no /dev/gpiochip* devices")
                             : "the chips here are " + present) +
            "): " + kChipHint;
    return false;
}

std::string request_error(const GpioButton& button, const std::string& chip, int err, const std::string& consumer) {
    const std::string what = describe_line(button) + " on " + chip;
    if (err == EBUSY) {
        if (!consumer.empty())
            return what + " is in use by \"" + consumer + "\": stop that program, or remove the dtoverlay=gpio-key "
                   "line for it from /boot/firmware/config.txt and reboot";
        return what + " is in use by another process or a gpio-key overlay: stop that program, or remove the "
               "dtoverlay=gpio-key line for it from /boot/firmware/config.txt and reboot";
    }
    if (err == EACCES || err == EPERM) return permission_error(chip) + " (needed for " + describe_line(button) + ")";
    if (err == EINVAL)
        return "the kernel refused " + what + " as a pulled-up, active-low input with edge events (" +
               std::strerror(err) + "): a Linux kernel of 5.10 or later is needed";
    return "cannot request " + what + ": " + std::strerror(err);
}

std::string line_range_error(const GpioButton& button, const std::string& chip, unsigned num_lines) {
    return describe_line(button) + " does not exist on " + chip + ", which has " + std::to_string(num_lines) +
           " lines (0 to " + std::to_string(num_lines == 0 ? 0 : num_lines - 1) +
           "): fix gpio in that [[button]] of the board file";
}

void ButtonTracker::init(const GpioConfig& config, int64_t debounce_ns) {
    count_ = static_cast<int>(config.buttons.size());
    debounce_ns_ = debounce_ns;
    control_.clear();
    for (const auto& b : config.buttons) control_.push_back(b.control);
    reported_.assign(count_, false);
    until_.assign(count_, -1);
    queue_.clear();
}

void ButtonTracker::push(int index, bool pressed) {
    queue_.push({control_[index], pressed});  // never full: backends read at most space() - count() edges
}

void ButtonTracker::change(int index, bool pressed, int64_t now_ns) {
    reported_[index] = pressed;
    push(index, pressed);
    if (debounce_ns_ > 0) until_[index] = now_ns + debounce_ns_;
}

void ButtonTracker::set_initial(int index, bool pressed) {
    reported_[index] = pressed;
    if (pressed) push(index, true);
}

void ButtonTracker::edge(int index, bool pressed, int64_t now_ns) {
    if (index < 0 || index >= count_) return;
    if (until_[index] >= 0) {
        if (now_ns < until_[index]) return;  // bouncing: the window's end reads the level
        until_[index] = -1;
    }
    if (pressed != reported_[index]) change(index, pressed, now_ns);
}

int64_t ButtonTracker::deadline() const {
    int64_t d = -1;
    for (int i = 0; i < count_; ++i)
        if (until_[i] >= 0 && (d < 0 || until_[i] < d)) d = until_[i];
    return d;
}

}  // namespace noneuclid::platform::gpio_detail

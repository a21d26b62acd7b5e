// Key devices through evdev: a gpio-key overlay (the kernel debounces), a USB keyboard or an
// arcade encoder. Opens the configured device, or every /dev/input/event* that reports EV_KEY
// and at least one wanted code; grabs them (EVIOCGRAB) so the keys do not reach the console;
// reads the keys held at open (EVIOCGKEY) and after a dropped-events overflow (SYN_DROPPED).
#include <dirent.h>
#include <fcntl.h>
#include <linux/input.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "linux/event_queue.hpp"
#include "linux/input.hpp"

namespace noneuclid::platform {

namespace {

constexpr size_t kKeyBytes = KEY_MAX / 8 + 1;

bool test_bit(const unsigned char* bits, unsigned bit) { return (bits[bit / 8] >> (bit % 8)) & 1u; }

std::string group_hint(const std::string& what) {
    return "no permission to open " + what + ": add the user to the input group "
           "(`sudo usermod -aG input $USER`) and log in again";
}

// "/dev/input/event12" -> 12; -1 if not an event device name.
long event_number(const char* name) {
    if (std::strncmp(name, "event", 5) != 0 || name[5] == '\0') return -1;
    char* end = nullptr;
    long n = std::strtol(name + 5, &end, 10);
    return (*end == '\0' && n >= 0) ? n : -1;
}

class Evdev final : public InputSource {
public:
    ~Evdev() override {
        for (auto& d : devices_)
            if (d.fd >= 0) {
                if (grab_) ioctl(d.fd, EVIOCGRAB, 0);
                close(d.fd);
            }
    }

    // The keys checked and mapped, then the device named or every device with one of them.
    bool open(const EvdevConfig& config, std::string& error) {
        if (!map_keys(config, error)) return false;
        grab_ = config.grab;
        std::string codes;
        for (size_t i = 0; i < codes_.size(); ++i) codes += (i ? ", " : "") + std::to_string(codes_[i]);
        if (!(config.device.empty() ? open_every(codes, error) : open_named(config.device, codes, error))) return false;
        describe_ = "evdev: ";
        for (size_t i = 0; i < devices_.size(); ++i)
            describe_ += (i ? ", " : "") + devices_[i].path + " \"" + devices_[i].name + "\"";
        describe_ += ", " + std::to_string(codes_.size()) + " key" + (codes_.size() == 1 ? "" : "s") +
                     (grab_ ? ", grabbed" : ", not grabbed");
        return true;
    }

    std::string describe() const override { return describe_; }

    int fds(pollfd* out, int max) override {
        int n = 0;
        for (; n < max && n < static_cast<int>(devices_.size()); ++n) out[n] = pollfd{devices_[n].fd, POLLIN, 0};
        return n;
    }

    int read(world::InputEvent* out, int max, int64_t) override {
        for (auto& d : devices_) {
            while (d.fd >= 0) {
                // Room for this batch plus a full resync after SYN_DROPPED.
                const int budget = queue_.space() - static_cast<int>(codes_.size());
                if (budget <= 0) break;
                const int want = std::min(budget, kBatch);
                ssize_t got = ::read(d.fd, events_, sizeof(input_event) * static_cast<size_t>(want));
                if (got < 0) {
                    if (errno == ENODEV) unplugged(d);  // device gone: release its keys, stop polling it
                    break;                              // EAGAIN: nothing pending
                }
                const int n = static_cast<int>(got / static_cast<ssize_t>(sizeof(input_event)));
                for (int k = 0; k < n; ++k) {
                    const input_event& e = events_[k];
                    if (e.type == EV_SYN && e.code == SYN_DROPPED) {
                        d.dropped = true;  // the kernel lost events: ignore until the next SYN_REPORT
                    } else if (e.type == EV_SYN && e.code == SYN_REPORT && d.dropped) {
                        d.dropped = false;
                        resync(d);
                    } else if (e.type == EV_KEY && !d.dropped && e.code <= KEY_MAX && control_[e.code] >= 0 &&
                               (e.value == 0 || e.value == 1)) {  // 2 is autorepeat
                        set(d, e.code, e.value == 1);
                    }
                }
                if (n < want) break;
            }
        }
        return queue_.pop(out, max);
    }

private:
    // Every configured key code checked and mapped to its control (codes_ sorted).
    bool map_keys(const EvdevConfig& config, std::string& error) {
        if (config.keys.empty()) {
            error = "no evdev keys are configured: give the [[button]] tables in the board file key codes";
            return false;
        }
        control_.assign(KEY_MAX + 1, -1);
        for (const auto& k : config.keys) {
            if (k.code == 0 || k.code > KEY_MAX) {
                error = "key code " + std::to_string(k.code) + " (" + world::action_name(k.control) +
                        ") is not an evdev key: use a code from 1 to " + std::to_string(KEY_MAX) +
                        " from /usr/include/linux/input-event-codes.h";
                return false;
            }
            if (control_[k.code] >= 0 && control_[k.code] != static_cast<int>(k.control)) {
                error = "key code " + std::to_string(k.code) + " is given to both " +
                        world::action_name(static_cast<world::Action>(control_[k.code])) + " and " +
                        world::action_name(k.control) + ": give each [[button]] in the board file its own key";
                return false;
            }
            control_[k.code] = static_cast<int>(k.control);
            if (std::find(codes_.begin(), codes_.end(), k.code) == codes_.end()) codes_.push_back(k.code);
        }
        if (codes_.size() > kMaxCodes) {
            error = std::to_string(codes_.size()) + " evdev key codes are configured, more than the " +
                    std::to_string(kMaxCodes) + " supported: remove some key entries from the board file";
            return false;
        }
        std::sort(codes_.begin(), codes_.end());
        return true;
    }
    // The device the board file names; it must have one of the key codes.
    bool open_named(const std::string& device, const std::string& codes, std::string& error) {
        std::string name;
        int fd = ::open(device.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) {
            int err = errno;
            if (err == EACCES || err == EPERM)
                error = group_hint(device);
            else if (err == ENOENT)
                error = device + " does not exist: set device in the board file's [evdev] table to "
                        "one of /dev/input/by-id/* (or leave it empty to use every device with the keys)";
            else
                error = "cannot open " + device + ": " + std::strerror(err);
            return false;
        }
        if (!has_keys(fd, name)) {
            close(fd);
            error = device + (name.empty() ? "" : " (" + name + ")") + " has none of the key codes " + codes +
                    ": set key in the board file's [[button]] tables to codes it has (`evtest " + device +
                    "` lists them), or pick another device";
            return false;
        }
        return add(fd, device, name, error);
    }
    // Every /dev/input/event* that has one of the key codes, in number order.
    bool open_every(const std::string& codes, std::string& error) {
        std::vector<std::pair<long, std::string>> paths;
        if (DIR* d = opendir("/dev/input")) {
            while (const dirent* e = readdir(d)) {
                long n = event_number(e->d_name);
                if (n >= 0) paths.emplace_back(n, std::string("/dev/input/") + e->d_name);
            }
            closedir(d);
        }
        std::sort(paths.begin(), paths.end());
        std::string denied, seen;
        for (const auto& p : paths) {
            int fd = ::open(p.second.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
            if (fd < 0) {
                if ((errno == EACCES || errno == EPERM) && denied.empty()) denied = p.second;
                continue;
            }
            std::string name;
            if (!has_keys(fd, name)) {
                seen += (seen.empty() ? "" : ", ") + p.second + " \"" + name + "\"";
                close(fd);
                continue;
            }
            if (!add(fd, p.second, name, error)) return false;
        }
        if (devices_.empty()) {
            if (!denied.empty())
                error = group_hint(denied + " (looking for a device with the key codes " + codes + ")");
            else
                error = "no input device has any of the key codes " + codes + " (" +
                        (paths.empty() ? std::string("this system has no /dev/input/event* devices")
                                       : "looked at " + seen) +
                        "): connect the keyboard or arcade encoder, add the dtoverlay=gpio-key lines to "
                        "/boot/firmware/config.txt, or set key codes the device has in the board file";
            return false;
        }
        return true;
    }
    struct Device {
        int fd = -1;
        std::string path, name;
        std::vector<unsigned char> down;  // per wanted key (index in codes_): held
        bool dropped = false;
    };

    // EV_KEY and at least one wanted code; also fetches the device name.
    bool has_keys(int fd, std::string& name) const {
        char buf[256] = {};
        if (ioctl(fd, EVIOCGNAME(sizeof(buf) - 1), buf) >= 0) name = buf;
        unsigned char types[EV_MAX / 8 + 1] = {};
        unsigned char keys[kKeyBytes] = {};
        if (ioctl(fd, EVIOCGBIT(0, sizeof(types)), types) < 0 || !test_bit(types, EV_KEY)) return false;
        if (ioctl(fd, EVIOCGBIT(EV_KEY, sizeof(keys)), keys) < 0) return false;
        for (unsigned c : codes_)
            if (test_bit(keys, c)) return true;
        return false;
    }

    bool add(int fd, const std::string& path, const std::string& name, std::string& error) {
        if (grab_ && ioctl(fd, EVIOCGRAB, 1) != 0) {
            int err = errno;
            close(fd);
            error = err == EBUSY ? path + " (" + name + ") is grabbed by another program: stop it, or set grab = false "
                                   "in the board file's [evdev] table"
                                 : "cannot grab " + path + " (" + name + "): " + std::strerror(err);
            return false;
        }
        Device d;
        d.fd = fd;
        d.path = path;
        d.name = name;
        d.down.assign(codes_.size(), 0);
        devices_.push_back(std::move(d));
        resync(devices_.back());  // keys already held give presses on the first read()
        return true;
    }

    void push(unsigned code, bool pressed) {
        queue_.push({static_cast<world::Action>(control_[code]), pressed});  // never full: read() keeps room for a resync
    }

    void set(Device& d, unsigned code, bool pressed) {
        const size_t i = static_cast<size_t>(std::lower_bound(codes_.begin(), codes_.end(), code) - codes_.begin());
        if (d.down[i] == static_cast<unsigned char>(pressed)) return;
        d.down[i] = pressed;
        push(code, pressed);
    }

    // The kernel's idea of which keys are down, reported as differences from ours.
    void resync(Device& d) {
        unsigned char state[kKeyBytes] = {};
        if (ioctl(d.fd, EVIOCGKEY(sizeof(state)), state) < 0) return;
        for (unsigned c : codes_) set(d, c, test_bit(state, c));
    }

    void unplugged(Device& d) {
        for (unsigned c : codes_) set(d, c, false);
        close(d.fd);
        d.fd = -1;  // poll() ignores negative fds
    }

    static constexpr size_t kMaxCodes = 64;
    static constexpr int kQueue = 128;  // a batch plus a resync of every code always fits
    static constexpr int kBatch = 32;
    bool grab_ = true;
    std::vector<int> control_;     // key code -> control, -1: not wanted
    std::vector<unsigned> codes_;  // wanted codes, sorted
    std::vector<Device> devices_;
    std::string describe_;
    input_event events_[kBatch];
    EventQueue<kQueue> queue_;
};

}  // namespace

std::unique_ptr<InputSource> open_evdev(const EvdevConfig& config, std::string& error) {
    auto src = std::make_unique<Evdev>();
    if (!src->open(config, error)) return nullptr;
    error.clear();
    return src;
}

}  // namespace noneuclid::platform

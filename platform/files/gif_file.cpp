// open_gif and read_gif (app/platform.hpp) with giflib.
#include "app/platform.hpp"

#include <gif_lib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace noneuclid::platform {

namespace {

int write_to_file(GifFileType* gif, const GifByteType* bytes, int n) {
    auto* f = static_cast<std::FILE*>(gif->UserData);
    return static_cast<int>(std::fwrite(bytes, 1, static_cast<std::size_t>(n), f));
}

// A frame's colours and each pixel's index into them: the colours themselves when there are at
// most 256 (a small open-addressing table of 24-bit colours), else giflib's quantisation.
class Palette {
public:
    explicit Palette(std::size_t pixels) : r_(pixels), g_(pixels), b_(pixels), index_(pixels) {}
    // False when giflib could not quantise the frame.
    bool take(const render::Canvas& c) {
        std::fill(std::begin(slot_), std::end(slot_), kEmpty);
        count_ = 0;
        bool exact = true;
        std::size_t i = 0;
        for (int y = 0; y < c.height(); ++y)
            for (int x = 0; x < c.width(); ++x, ++i) {
                const render::Rgb p = c.get(x, y);
                r_[i] = p.r, g_[i] = p.g, b_[i] = p.b;
                if (exact) exact = lookup(static_cast<uint32_t>(p.r) << 16 | p.g << 8 | p.b, index_[i]);
            }
        if (exact) return true;
        int size = 256;
        count_ = 256;
        return GifQuantizeBuffer(static_cast<unsigned>(c.width()), static_cast<unsigned>(c.height()), &size, r_.data(),
                                 g_.data(), b_.data(), index_.data(), colours_) == GIF_OK;
    }
    const GifByteType* row(int y, int width) const { return index_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width); }
    GifColorType* colours() { return colours_; }

private:
    static constexpr uint32_t kEmpty = 0xFFFFFFFF;
    // The index of colour c, entered if new; false once a 257th colour comes.
    bool lookup(uint32_t c, GifByteType& index) {
        uint32_t h = (c * 2654435761u) >> 23;  // 9 bits: 512 slots for at most 256 colours
        while (slot_[h] != kEmpty && slot_[h] >> 8 != c) h = (h + 1) & 511;
        if (slot_[h] == kEmpty) {
            if (count_ == 256) return false;
            slot_[h] = c << 8 | static_cast<uint32_t>(count_);
            colours_[count_] = {static_cast<GifByteType>(c >> 16), static_cast<GifByteType>(c >> 8), static_cast<GifByteType>(c)};
            ++count_;
        }
        index = static_cast<GifByteType>(slot_[h] & 0xFF);
        return true;
    }
    std::vector<GifByteType> r_, g_, b_, index_;
    uint32_t slot_[512];
    GifColorType colours_[256] = {};
    int count_ = 0;
};

class GifFile final : public GifWriter {
public:
    GifFile(const std::string& path, int width, int height) : path_(path), w_(width), h_(height),
          palette_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}
    ~GifFile() override { drop(); }

    bool open(std::string& error) {
        if (!out_.open(path_, error)) return false;
        int err = 0;
        gif_ = EGifOpen(out_.file(), write_to_file, &err);
        if (!gif_) return failed(err, error);
        EGifSetGifVersion(gif_, true);
        static const GifByteType netscape[] = "NETSCAPE2.0";
        static const GifByteType forever[] = {1, 0, 0};  // loop count 0: for ever
        if (EGifPutScreenDesc(gif_, w_, h_, 8, 0, nullptr) == GIF_ERROR ||
            EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
            EGifPutExtensionBlock(gif_, 11, netscape) == GIF_ERROR || EGifPutExtensionBlock(gif_, 3, forever) == GIF_ERROR ||
            EGifPutExtensionTrailer(gif_) == GIF_ERROR)
            return failed(gif_->Error, error);
        return true;
    }

    bool frame(const render::Canvas& c, int centiseconds, std::string& error) override {
        if (!gif_ || c.width() != w_ || c.height() != h_) {
            error = "cannot write " + path_ + ": a frame is not the animation's size; it is left as it was.";
            return false;
        }
        if (centiseconds < 0 || centiseconds > 65535) {  // a GIF frame's delay is 16 bits
            error = "cannot write " + path_ + ": a frame's delay of " + std::to_string(centiseconds) +
                    " centiseconds is past the 655.35 s a GIF frame can be shown; it is left as it was.";
            drop();
            return false;
        }
        if (stop_signal()) return stopped(error);
        if (!palette_.take(c)) return failed(E_GIF_ERR_NOT_ENOUGH_MEM, error);
        GraphicsControlBlock gcb{};
        gcb.DisposalMode = DISPOSE_DO_NOT, gcb.DelayTime = centiseconds, gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        GifByteType ext[4];
        const std::size_t n = EGifGCBToExtension(&gcb, ext);
        ColorMapObject* map = GifMakeMapObject(256, palette_.colours());
        if (!map) return failed(E_GIF_ERR_NOT_ENOUGH_MEM, error);
        const bool ok = EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(n), ext) != GIF_ERROR &&
                        EGifPutImageDesc(gif_, 0, 0, w_, h_, false, map) != GIF_ERROR;
        GifFreeMapObject(map);
        if (!ok) return failed(gif_->Error, error);
        for (int y = 0; y < h_; ++y)
            if (EGifPutLine(gif_, const_cast<GifByteType*>(palette_.row(y, w_)), w_) == GIF_ERROR) return failed(gif_->Error, error);
        return true;
    }

    bool finish(std::string& error) override {
        if (!gif_) {
            error = "cannot write " + path_ + ": it was not opened.";
            return false;
        }
        if (stop_signal()) return stopped(error);
        int err = 0;
        const int closed = EGifCloseFile(gif_, &err);
        gif_ = nullptr;
        if (closed == GIF_ERROR) return failed(err, error);
        return out_.commit(error);
    }

private:
    // Ends the writer, its temporary file removed (giflib's own end first: it writes through it).
    void drop() {
        if (gif_) EGifCloseFile(gif_, nullptr);
        gif_ = nullptr;
        out_.abort();
    }
    bool failed(int gif_error, std::string& error) {
        const int e = errno;
        const bool disk = out_.file() && std::ferror(out_.file());
        error = "cannot write " + path_ + ": " +
                (disk ? std::string(std::strerror(e)) + " (check the disk has room)"
                      : std::string("giflib: ") + (GifErrorString(gif_error) ? GifErrorString(gif_error) : "failed")) +
                "; it is left as it was.";
        drop();
        return false;
    }
    bool stopped(std::string& error) {
        error = "stopped by signal " + std::to_string(stop_signal()) + " while writing " + path_ + "; it is left as it was.";
        drop();
        return false;
    }

    std::string path_;
    int w_, h_;
    AtomicFile out_;
    GifFileType* gif_ = nullptr;
    Palette palette_;
};

}  // namespace

std::unique_ptr<GifWriter> open_gif(const std::string& path, int width, int height, std::string& error) {
    if (width <= 0 || height <= 0 || width > 65535 || height > 65535) {
        error = "cannot write " + path + ": a GIF is at most 65535 pixels a side; choose a smaller --size.";
        return nullptr;
    }
    auto gif = std::make_unique<GifFile>(path, width, height);
    if (!gif->open(error)) return nullptr;
    return gif;
}

bool read_gif(const std::string& path, int& width, int& height, std::vector<GifFrame>& frames, std::string& error) {
    int err = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &err);
    if (!gif) {
        error = "cannot read " + path + ": " + (GifErrorString(err) ? GifErrorString(err) : "not a GIF");
        return false;
    }
    if (DGifSlurp(gif) == GIF_ERROR) {
        error = "cannot read " + path + ": " + (GifErrorString(gif->Error) ? GifErrorString(gif->Error) : "not a GIF");
        DGifCloseFile(gif, nullptr);
        return false;
    }
    width = gif->SWidth, height = gif->SHeight;
    frames.clear();
    std::string canvas(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, '\0');
    for (int i = 0; i < gif->ImageCount; ++i) {
        const SavedImage& im = gif->SavedImages[i];
        const ColorMapObject* map = im.ImageDesc.ColorMap ? im.ImageDesc.ColorMap : gif->SColorMap;
        for (int y = 0; y < im.ImageDesc.Height && map; ++y)
            for (int x = 0; x < im.ImageDesc.Width; ++x) {
                const int cx = im.ImageDesc.Left + x, cy = im.ImageDesc.Top + y;
                if (cx >= width || cy >= height) continue;
                const int k = im.RasterBits[static_cast<std::size_t>(y) * static_cast<std::size_t>(im.ImageDesc.Width) + static_cast<std::size_t>(x)];
                if (k >= map->ColorCount) continue;
                const GifColorType c = map->Colors[k];
                const std::size_t at = (static_cast<std::size_t>(cy) * static_cast<std::size_t>(width) + static_cast<std::size_t>(cx)) * 3;
                canvas[at] = static_cast<char>(c.Red), canvas[at + 1] = static_cast<char>(c.Green), canvas[at + 2] = static_cast<char>(c.Blue);
            }
        GraphicsControlBlock gcb{};
        DGifSavedExtensionToGCB(gif, i, &gcb);
        frames.push_back({canvas, gcb.DelayTime});
    }
    DGifCloseFile(gif, nullptr);
    return true;
}

}  // namespace noneuclid::platform

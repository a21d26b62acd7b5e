// A lesson's worksheet and its key (app/worksheet.hpp).
#include "app/worksheet.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/lesson.hpp"
#include "app/picture.hpp"
#include "app/platform.hpp"
#include "app/setup.hpp"
#include "render/font.hpp"
#include "render/hud.hpp"
#include "render/measure_panel.hpp"

namespace noneuclid::app {

namespace {

// 150 dots an inch; the built-in font's 8-pixel cell at three times is 24 pixels, 11.5 points.
constexpr int kMargin = 60, kScale = 3, kTitleScale = 5, kGap = 30, kPictureW = 440, kPictureH = 330;
constexpr int kLine = (8 + 3) * kScale;  // a line of text, with its leading
const render::Rgb kInk{20, 20, 20}, kGrey{90, 90, 90}, kRule{160, 160, 160}, kKeyInk{170, 20, 20};

struct PaperSize {
    int width, height;
    double width_pt, height_pt;
};
PaperSize paper_size(Paper p) {
    // A4: 210 x 297 mm; Letter: 8.5 x 11 inches.
    return p == Paper::a4 ? PaperSize{1240, 1754, 595.276, 841.890} : PaperSize{1275, 1650, 612, 792};
}

// The pages as they are written, a step at a time; text is drawn, or with a null page only
// measured (the height a step needs, to know whether it fits).
class SheetWriter {
public:
    SheetWriter(Worksheet& w, const render::Font& font) : w_(w), font_(font) {}

    render::Canvas canvas() const { return measuring_ ? render::Canvas(dummy_, 1, 1, 4, fmt()) : w_.page(w_.pages.size() - 1); }
    void new_page() {
        w_.pages.emplace_back(static_cast<std::size_t>(w_.width) * w_.height * 4, 0xFF);  // white paper
        y = kMargin;
    }
    void measure(bool on) { measuring_ = on; }
    bool measuring() const { return measuring_; }
    // Text at (x, y) wrapped to `width`; returns the y below it.
    int text(int x, int top, int width, const std::string& s, render::Rgb color, int scale = kScale) const {
        const int line = (font_.height + 3) * scale;
        return top + line * render::draw_wrapped(canvas(), font_, s.c_str(), " ", color, scale, x, width, line, top, true);
    }
    void rule(int x0, int x1, int at) const {
        if (measuring_) return;
        const render::Canvas c = canvas();
        for (int x = x0; x < x1; ++x) c.set(x, at, kRule), c.set(x, at + 1, kRule);
    }
    int page() const { return static_cast<int>(w_.pages.size()) - 1; }
    const render::Font& font() const { return font_; }

    int y = kMargin;

private:
    static render::PixelFormat fmt() { return render::PixelFormat::xrgb8888(); }
    Worksheet& w_;
    const render::Font& font_;
    bool measuring_ = false;
    mutable uint8_t dummy_[4] = {};
};

// What a step prints, once its picture is taken.
struct StepText {
    std::string heading, caption, question, readings_title;
    std::vector<render::PanelReading> readings;
};

// The step's text column and blanks at the writer's y; returns its height (with the picture's).
int step_block(SheetWriter& sw, Worksheet& w, int index, const StepText& t, bool answers, const Picture* picture) {
    const int top = sw.y, tx = kMargin + kPictureW + kGap, tw = w.width - tx - kMargin;
    if (picture && !sw.measuring()) {
        const render::Canvas c = sw.canvas();
        for (int y = 0; y < kPictureH; ++y)
            for (int x = 0; x < kPictureW; ++x) c.set(kMargin + x, top + y, picture->canvas.get(x, y));
        for (int x = -1; x <= kPictureW; ++x) c.set(kMargin + x, top - 1, kRule), c.set(kMargin + x, top + kPictureH, kRule);
        for (int y = -1; y <= kPictureH; ++y) c.set(kMargin - 1, top + y, kRule), c.set(kMargin + kPictureW, top + y, kRule);
    }
    int y = sw.text(tx, top, tw, t.heading, kGrey) + 6;
    y = sw.text(tx, y, tw, t.caption, kInk) + 10;
    if (!t.question.empty()) y = sw.text(tx, y, tw, t.question, kInk) + 10;
    if (!t.readings.empty()) {
        y = sw.text(tx, y, tw, t.readings_title, kInk) + 4;
        // Two readings a row: "A ______°", the value above the line on the key.
        const int cell = tw / 2, char_w = sw.font().width * kScale;
        for (std::size_t i = 0; i < t.readings.size(); ++i) {
            const render::PanelReading& r = t.readings[i];
            const int cx = tx + static_cast<int>(i % 2) * cell, cy = y + static_cast<int>(i / 2) * (kLine + 14);
            const int label_end = cx + 5 * char_w;  // labels are at most four characters ("sum", "C/C0": five)
            sw.text(cx, cy, 5 * char_w, r.label, kInk);
            const int unit_w = render::text_width(sw.font(), r.unit, kScale);
            const int box_x = label_end + 6, box_w = cell - (box_x - cx) - unit_w - 24;
            sw.rule(box_x, box_x + box_w, cy + kLine - 6);
            sw.text(box_x + box_w + 4, cy, unit_w + 8, r.unit, kInk);
            if (answers) sw.text(box_x + 6, cy, box_w - 6, r.value, kKeyInk);
            if (!sw.measuring())
                w.values.push_back({index, sw.page(), box_x, cy, box_w, kLine - 6, r.label, r.value, r.unit});
        }
        y += static_cast<int>((t.readings.size() + 1) / 2) * (kLine + 14) + 8;
    }
    if (!t.question.empty())  // room to write the answer in words
        for (int k = 0; k < (t.readings.empty() ? 2 : 1); ++k, y += kLine + 16) sw.rule(tx, tx + tw, y + kLine + 8);
    return std::max(y, top + kPictureH) - top;
}

// The title block at the top of the first page: the title, what the lesson is about, and
// "Name: ____" on the pupil's pages or "Key" on the teacher's.
void title_block(SheetWriter& sw, Worksheet& w, const files::Lesson& lesson, lang::Language language,
                 bool answers) {
    const int width = w.width - 2 * kMargin;
    sw.y = sw.text(kMargin, sw.y, width, lesson.title, kInk, kTitleScale) + 8;
    sw.y = sw.text(kMargin, sw.y, width, lesson.about, kGrey) + 16;
    const std::string mark = lang::text(answers ? lang::Text::worksheet_key : lang::Text::worksheet_name, language);
    const int mark_w = render::text_width(sw.font(), mark, kScale);
    const int mark_x = w.width - kMargin - 520;
    sw.text(mark_x, sw.y, mark_w + 8, mark, answers ? kKeyInk : kInk);
    if (!answers) sw.rule(mark_x + mark_w + 12, w.width - kMargin, sw.y + kLine - 6);
    w.mark = {-1, 0, mark_x, sw.y, w.width - kMargin - mark_x, kLine, mark, "", ""};
    sw.y += kLine + 30;
}

}  // namespace

bool parse_paper(const std::string& name, Paper& out) {
    if (name == "a4") return out = Paper::a4, true;
    if (name == "letter") return out = Paper::letter, true;
    return false;
}

render::Canvas Worksheet::page(std::size_t i) const {
    auto* px = const_cast<uint8_t*>(pages[i].data());  // (a canvas is a view; the pages are the sheet's)
    return render::Canvas(px, width, height, std::ptrdiff_t{width} * 4, render::PixelFormat::xrgb8888());
}

bool names_pdf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& ch : ext) ch = static_cast<char>(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
    return ext == ".pdf";
}

double asked_curvature(const files::LessonStep& step, double start_K) {
    return step.has_question_curvature ? step.question_curvature : start_K;
}

bool make_worksheet(const files::Lesson& lesson, const Options& base, bool answers, Paper paper, Worksheet& w,
                    std::string& error) {
    const PaperSize size = paper_size(paper);
    w = Worksheet{};
    w.width = size.width, w.height = size.height, w.width_pt = size.width_pt, w.height_pt = size.height_pt;
    const render::Font& font = render::builtin_font();
    const lang::Language language = resolve_language(base);
    using lang::Text;
    SheetWriter sw(w, font);
    sw.new_page();
    title_block(sw, w, lesson, language, answers);
    for (int i = 0; i < static_cast<int>(lesson.steps.size()); ++i) {
        const files::LessonStep& s = lesson.steps[i];
        Options o = step_options(lesson, base, i);
        const double start = s.has_curvature ? s.curvature : load_scene(o).curvature;
        o.has_curvature = true, o.curvature = asked_curvature(s, start);
        const world::Scene scene = load_scene(o);  // (at that K)
        o.width = kPictureW, o.height = kPictureH, o.frames = 60, o.hud = false, o.panels = false;
        o.format = render::PixelFormat::xrgb8888();
        if (base.palette == render::Palette::scene) o.palette = render::Palette::print;
        Picture picture;
        const PictureResult r = render_picture(o, scene, nullptr, font, picture);
        if (r.stopped) return error = "stopped by a signal: the worksheet was not written.", false;
        StepText t;
        char line[160];
        std::snprintf(line, sizeof line, lang::text(Text::worksheet_step, language), i + 1, r.K,
                      render::projection_words(o.projection, language));
        t.heading = line;
        t.caption = s.caption;
        if (!s.question.empty()) {
            std::vector<char> q(s.question.size() + 64);
            std::snprintf(q.data(), q.size(), lang::text(Text::question, language), s.question.c_str());
            t.question = q.data();
            for (int g = 0; g < r.readings; ++g) {
                const render::PanelReadings rows = render::panel_readings(r.reading[g], language);
                t.readings.insert(t.readings.end(), rows.row, rows.row + rows.count);
            }
            std::snprintf(line, sizeof line, lang::text(Text::worksheet_readings, language), r.K);
            t.readings_title = line;
        }
        sw.measure(true);
        const int need = step_block(sw, w, i, t, answers, nullptr);
        sw.measure(false);
        if (sw.y + need > w.height - kMargin - kLine && sw.y > kMargin) sw.new_page();  // a step is never split
        w.steps.push_back({r.K, sw.page(), t.heading});
        sw.y += step_block(sw, w, i, t, answers, &picture) + 40;
    }
    // Each page's number, bottom right.
    const int pages = static_cast<int>(w.pages.size());
    for (int p = 0; p < pages; ++p) {
        char footer[64];
        std::snprintf(footer, sizeof footer, lang::text(Text::worksheet_page, language), p + 1, pages);
        const int fw = render::text_width(font, footer, kScale);
        render::draw_text(w.page(p), font, w.width - kMargin - fw, w.height - kMargin / 2 - kLine, footer, kGrey, kScale);
    }
    return true;
}

bool write_worksheet(const files::Lesson& lesson, const Options& base, const std::string& path, bool answers,
                     Paper paper, std::string& error) {
    Worksheet w;
    if (!make_worksheet(lesson, base, answers, paper, w, error)) return false;
    std::vector<render::Canvas> pages;
    for (std::size_t i = 0; i < w.pages.size(); ++i) pages.push_back(w.page(i));
    if (names_pdf(path)) return platform::write_pdf(path, pages, w.width_pt, w.height_pt, error);
    // A PNG: the pages one below the other.
    std::vector<uint8_t> all;
    for (const std::vector<uint8_t>& p : w.pages) all.insert(all.end(), p.begin(), p.end());
    const render::Canvas sheet(all.data(), w.width, w.height * static_cast<int>(w.pages.size()),
                               std::ptrdiff_t{w.width} * 4, render::PixelFormat::xrgb8888());
    return platform::write_png(path, sheet, error);
}

}  // namespace noneuclid::app

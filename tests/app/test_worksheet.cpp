// The worksheets and their keys (app/worksheet.hpp), for every built-in lesson in every language:
// each step printed at the K its question asks about (the lesson's own data, and the K its
// question's words name), the pupil's pages carrying none of the key's values (the two differ
// only inside the value boxes, blank on the pupil's), the key's values those `measure` gives at
// that K (files/measure_table.hpp's rows, the `--format table` command's), text at 9 points or
// more on A4, and the PDF read back by poppler (pdfinfo, pdftoppm: package poppler-utils).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include "app/lesson.hpp"
#include "app/platform.hpp"
#include "app/setup.hpp"
#include "app/worksheet.hpp"
#include "files/measure_table.hpp"
#include "geometry/measure.hpp"
#include "world/scene.hpp"

namespace {
namespace worksheet_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;

app::Options options_in(lang::Language l) {
    app::Options o = app::defaults(app::Command::run);
    o.language = lang::language_code(l);
    return o;
}

// The K step i should be printed at, from the lesson's data alone: the question's K, else the
// step's, else its scene's.
double expected_K(const files::Lesson& lesson, int i, const app::Options& base) {
    const files::LessonStep& s = lesson.steps[i];
    if (s.has_question_curvature) return s.question_curvature;
    if (s.has_curvature) return s.curvature;
    world::Scene scene;
    EXPECT_TRUE(world::builtin_scene(app::step_options(lesson, base, i).scene, {}, scene));
    return scene.curvature;
}

bool inside(const app::SheetValue& v, int page, int x, int y) {
    return v.page == page && x >= v.x && x < v.x + v.w && y >= v.y && y < v.y + v.h;
}

TEST(Worksheet, EveryStepIsAtItsQuestionsKAndThePupilsPagesCarryNoValue) {
    for (int li = 0; li < lang::kLanguages; ++li) {
        const auto language = static_cast<lang::Language>(li);
        const app::Options base = options_in(language);
        for (const std::string& name : files::builtin_lesson_names()) {
            SCOPED_TRACE(name + " in " + lang::language_code(language));
            files::Lesson lesson;
            ASSERT_TRUE(files::builtin_lesson(name, lesson, language));
            app::Worksheet pupil, key;
            std::string error;
            ASSERT_TRUE(app::make_worksheet(lesson, base, false, app::Paper::a4, pupil, error)) << error;
            ASSERT_TRUE(app::make_worksheet(lesson, base, true, app::Paper::a4, key, error)) << error;
            ASSERT_EQ(pupil.steps.size(), lesson.steps.size());
            for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
                const double K = expected_K(lesson, static_cast<int>(i), base);
                EXPECT_NEAR(pupil.steps[i].K, K, 1e-6) << "step " << i + 1;
                char printed[32];
                std::snprintf(printed, sizeof printed, "K = %+.2f", K);
                EXPECT_NE(pupil.steps[i].heading.find(printed), std::string::npos) << pupil.steps[i].heading;
                // A question that names a K in its words names this one.
                std::smatch m;
                const std::string& q = lesson.steps[i].question;
                if (std::regex_search(q, m, std::regex("K = ([-+]?[0-9.]+)"))) {
                    EXPECT_NEAR(std::stod(m[1]), K, 1e-9) << "step " << i + 1 << ": " << q;
                }
            }
            // The same pages but for the values: white in their boxes on the pupil's, inked on the key's.
            ASSERT_EQ(pupil.pages.size(), key.pages.size());
            ASSERT_EQ(pupil.values.size(), key.values.size());
            if (name == "triangles") {
                EXPECT_EQ(key.values.size(), 4u * 7u) << "every step's question: the triangle's seven readings";
            }
            long differing_outside = 0;
            for (std::size_t p = 0; p < key.pages.size(); ++p) {
                const render::Canvas a = pupil.page(p), b = key.page(p);
                for (int y = 0; y < a.height(); ++y)
                    for (int x = 0; x < a.width(); ++x) {
                        if (a.get(x, y) == b.get(x, y)) continue;
                        bool in_box = inside(key.mark, static_cast<int>(p), x, y);  // "Key" for "Name: ___"
                        for (const app::SheetValue& v : key.values) in_box = in_box || inside(v, static_cast<int>(p), x, y);
                        differing_outside += !in_box;
                    }
            }
            EXPECT_EQ(differing_outside, 0);
            EXPECT_EQ(key.mark.label, lang::text(lang::Text::worksheet_key, language));
            EXPECT_EQ(pupil.mark.label, lang::text(lang::Text::worksheet_name, language));
            for (const app::SheetValue& v : key.values) {
                long ink_key = 0, ink_pupil = 0;
                for (int y = v.y; y < v.y + v.h; ++y)
                    for (int x = v.x; x < v.x + v.w; ++x) {
                        ink_key += !(key.page(v.page).get(x, y) == render::Rgb{255, 255, 255});
                        ink_pupil += !(pupil.page(v.page).get(x, y) == render::Rgb{255, 255, 255});
                    }
                EXPECT_GT(ink_key, 20) << v.label << " " << v.value;
                EXPECT_EQ(ink_pupil, 0) << v.label;
            }
        }
    }
}

// The key's values against the measure command's table at the step's K, for the measure scene's
// triangle (its marks read from the scene): each to the panel's rounding.
TEST(Worksheet, TheKeysValuesAreWhatMeasureGivesAtThatK) {
    files::Lesson lesson;
    ASSERT_TRUE(files::builtin_lesson("triangles", lesson));
    app::Worksheet key;
    std::string error;
    ASSERT_TRUE(app::make_worksheet(lesson, app::defaults(app::Command::run), true, app::Paper::a4, key, error)) << error;
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene("measure", {}, scene));
    ASSERT_EQ(scene.measures.size(), 1u);
    const std::map<std::string, std::string> row_of = {{"A", "angle A"}, {"B", "angle B"}, {"C", "angle C"},
                                                       {"sum", "angle sum"}, {"exc", "excess"}, {"area", "area"},
                                                       {"K*A", "K × area"}};
    int checked = 0;
    for (const app::SheetValue& v : key.values) {
        const double K = key.steps[v.step].K;
        geo::Polar<double> marks[3];
        for (int i = 0; i < 3; ++i)
            marks[i] = {scene.measures[0].marks[i].r, geo::wrap_pi(scene.measures[0].marks[i].theta_deg * 3.14159265358979323846 / 180)};
        geo::TriangleReading t;
        ASSERT_EQ(geo::measure_triangle(K, marks, scene.limit_radius, t), geo::MeasureError::none);
        std::string table;
        files::append_triangle_table(table, K, t);
        ASSERT_TRUE(row_of.count(v.label)) << v.label;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(table, m, std::regex(row_of.at(v.label) + " +(-?[0-9.]+)"))) << table;
        const double measured = std::stod(m[1]), written = std::stod(v.value);
        const std::size_t dot = v.value.find('.');
        const int decimals = dot == std::string::npos ? 0 : static_cast<int>(v.value.size() - dot - 1);
        EXPECT_LE(std::fabs(measured - written), 0.5 * std::pow(10, -decimals) + 0.5e-3 + 1e-9)
            << v.label << " at K = " << K << ": the key " << v.value << ", measure " << m[1];
        ++checked;
    }
    EXPECT_EQ(checked, 28);
    // (and at K = +1 the angle sum is over 180, at -1 under it: the picture really is there)
    for (const app::SheetValue& v : key.values)
        if (v.label == "sum") {
            EXPECT_EQ(std::stod(v.value) > 180.05, key.steps[v.step].K > 0) << v.value;
        }
}

// Text at 9 points or more on A4: each line of the text column's ink at least 0.7 em of 9 points
// tall (a capital's height; the built-in font's capitals are 7 of its 8 rows) at 150 dots an inch,
// the page A4's 210 mm wide.
TEST(Worksheet, TextIsNinePointsOrMoreOnA4) {
    files::Lesson lesson;
    ASSERT_TRUE(files::builtin_lesson("triangles", lesson));
    app::Worksheet key;
    std::string error;
    ASSERT_TRUE(app::make_worksheet(lesson, app::defaults(app::Command::run), true, app::Paper::a4, key, error)) << error;
    const double dpi = key.width / (210 / 25.4);
    EXPECT_NEAR(dpi, 150, 0.1);
    EXPECT_NEAR(key.width_pt, 595.276, 0.01);
    const render::Canvas c = key.page(0);
    const int x0 = 60 + 440 + 30;
    int run = 0, shortest = 1 << 30, lines = 0;
    for (int y = 0; y < c.height(); ++y) {
        bool ink = false;
        for (int x = x0; x < c.width() - 60 && !ink; ++x) {
            const render::Rgb p = c.get(x, y);
            ink = p.r + p.g + p.b < 330 && !(p == render::Rgb{160, 160, 160});  // text, not a rule
        }
        if (ink) ++run;
        else if (run > 0) shortest = std::min(shortest, run), ++lines, run = 0;
    }
    EXPECT_GT(lines, 10);
    EXPECT_GE(shortest / dpi * 72, 0.7 * 9) << shortest << " px";
}

std::string shell(const std::string& command) {
    std::string out;
    if (std::FILE* p = popen(command.c_str(), "r")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
        pclose(p);
    }
    return out;
}

// A PDF poppler reads: its pages and paper size (pdfinfo), and its first page rasterised at 150
// dots an inch (pdftoppm) the page's own pixels, on A4 and on Letter.
TEST(Worksheet, ThePdfIsWhatPopplerReads) {
    ASSERT_NE(shell("command -v pdfinfo && command -v pdftoppm"), "")
        << "pdfinfo and pdftoppm are not installed: install poppler-utils (platform/debian/packages.sh's test group)";
    files::Lesson lesson;
    ASSERT_TRUE(files::builtin_lesson("triangles", lesson));
    for (const app::Paper paper : {app::Paper::a4, app::Paper::letter}) {
        const bool a4 = paper == app::Paper::a4;
        const std::string path = ::testing::TempDir() + (a4 ? "sheet-a4.pdf" : "sheet-letter.pdf");
        const app::Options base = app::defaults(app::Command::run);
        std::string error;
        ASSERT_TRUE(app::write_worksheet(lesson, base, path, true, paper, error)) << error;
        app::Worksheet w;
        ASSERT_TRUE(app::make_worksheet(lesson, base, true, paper, w, error)) << error;
        const std::string info = shell("pdfinfo '" + path + "' 2>&1");
        EXPECT_TRUE(std::regex_search(info, std::regex("Pages: +" + std::to_string(w.pages.size()) + "\n"))) << info;
        EXPECT_TRUE(std::regex_search(info, std::regex(a4 ? "Page size: +595.276 x 841.89 pts \\(A4\\)"
                                                           : "Page size: +612 x 792 pts \\(letter\\)")))
            << info;
        const std::string ppm = ::testing::TempDir() + "sheet-page";
        shell("pdftoppm -scale-to-x " + std::to_string(w.width) + " -scale-to-y " + std::to_string(w.height) + " -f 1 -l 1 -singlefile '" + path + "' '" + ppm + "'");
        std::ifstream in(ppm + ".ppm", std::ios::binary);
        std::string magic;
        int width = 0, height = 0, max = 0;
        in >> magic >> width >> height >> max;
        in.get();
        ASSERT_EQ(magic, "P6");
        ASSERT_EQ(width, w.width);
        ASSERT_EQ(height, w.height);
        std::string rgb(static_cast<std::size_t>(width) * height * 3, '\0');
        in.read(rgb.data(), static_cast<std::streamsize>(rgb.size()));
        // 8x8 blocks' means (the rasteriser's resampling blurs an edge by a pixel; a block keeps its ink).
        const render::Canvas page = w.page(0);
        double diff = 0, worst = 0;
        long blocks = 0;
        for (int by = 0; by + 8 <= height; by += 8)
            for (int bx = 0; bx + 8 <= width; bx += 8, ++blocks) {
                double mine = 0, theirs = 0;
                for (int y = by; y < by + 8; ++y)
                    for (int x = bx; x < bx + 8; ++x) {
                        const render::Rgb p = page.get(x, y);
                        const auto* q = reinterpret_cast<const unsigned char*>(&rgb[(static_cast<std::size_t>(y) * width + x) * 3]);
                        mine += p.r + p.g + p.b, theirs += q[0] + q[1] + q[2];
                    }
                const double d = std::fabs(mine - theirs) / (3 * 64);
                diff += d, worst = std::max(worst, d);
            }
        EXPECT_LT(diff / blocks, 1.0) << "mean difference of an 8x8 block, per channel";
        EXPECT_LT(worst, 40.0) << "the worst block's";
    }
}

// A name ending .pdf in any case is a PDF (the command line checks it as one, and so it is written).
TEST(Worksheet, APdfIsNamedInAnyCase) {
    files::Lesson lesson;
    ASSERT_TRUE(files::builtin_lesson("game", lesson));
    const std::string path = ::testing::TempDir() + "sheet.Pdf";
    std::string error;
    ASSERT_TRUE(app::write_worksheet(lesson, app::defaults(app::Command::run), path, false, app::Paper::a4, error)) << error;
    std::ifstream in(path, std::ios::binary);
    std::string head(5, '\0');
    in.read(head.data(), 5);
    EXPECT_EQ(head, "%PDF-");
    EXPECT_TRUE(app::names_pdf("x.PDF"));
    EXPECT_FALSE(app::names_pdf("x.png"));
    EXPECT_FALSE(app::names_pdf("pdf"));
}

// The PNG is the pages one below the other; a folder that is not there is made.
TEST(Worksheet, ThePngIsThePagesOneBelowTheOther) {
    files::Lesson lesson;
    ASSERT_TRUE(files::builtin_lesson("curvature", lesson));
    const app::Options base = app::defaults(app::Command::run);
    app::Worksheet w;
    std::string error;
    ASSERT_TRUE(app::make_worksheet(lesson, base, false, app::Paper::letter, w, error)) << error;
    const std::string path = ::testing::TempDir() + "sheet.png";
    ASSERT_TRUE(app::write_worksheet(lesson, base, path, false, app::Paper::letter, error)) << error;
    int width = 0, height = 0;
    std::string rgb;
    ASSERT_TRUE(platform::read_png(path, width, height, rgb, error)) << error;
    EXPECT_EQ(width, 1275);
    EXPECT_EQ(height, 1650 * static_cast<int>(w.pages.size()));
    long same = 0;
    const render::Canvas last = w.page(w.pages.size() - 1);
    const int y0 = 1650 * static_cast<int>(w.pages.size() - 1);
    for (int y = 0; y < last.height(); y += 7)
        for (int x = 0; x < last.width(); x += 7) {
            const render::Rgb p = last.get(x, y);
            const auto* q = reinterpret_cast<const unsigned char*>(&rgb[(static_cast<std::size_t>(y0 + y) * width + x) * 3]);
            same += p.r == q[0] && p.g == q[1] && p.b == q[2];
        }
    EXPECT_EQ(same, static_cast<long>(((last.height() + 6) / 7) * ((last.width() + 6) / 7)));
}

}  // namespace worksheet_test
}  // namespace

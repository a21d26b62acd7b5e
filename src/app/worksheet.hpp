// A lesson on paper (docs/lessons.md): the pupil's worksheet and the teacher's key. Each step's
// picture shows the situation its question is about: the step's scene at the K the question
// names (files::LessonStep::question_curvature, else the K the step starts at), the shape in
// place, and no readings on it. Beside it the step's K, caption and question, and where the scene
// has instruments a labelled blank for each reading ("A ______°"); the key is the same pages with
// the values written in, rounded as the instruments' panel rounds them (angles to 0.1°, lengths
// and areas to 0.001). Pages are A4 or Letter at 150 dots an inch, text at least 9 points (the
// built-in font at three times: 24-pixel lines), in the print palette unless another is asked
// for. Written as a PNG (the pages one below the other) or, named .pdf, as a PDF of one page per
// sheet.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/options.hpp"
#include "files/lesson_file.hpp"
#include "render/canvas.hpp"

namespace noneuclid::app {

enum class Paper { a4, letter };
bool parse_paper(const std::string& name, Paper& out);  // "a4", "letter"

// Where a reading's value goes: its page and box, the label and unit beside it, and the value
// the key writes there (the pupil's page leaves the box blank above its line).
struct SheetValue {
    int step = 0, page = 0, x = 0, y = 0, w = 0, h = 0;
    std::string label, value, unit;
};

// A step as printed: the K its picture is at and its heading says, and the heading's text.
struct SheetStep {
    double K = 0;
    int page = 0;
    std::string heading;
};

struct Worksheet {
    int width = 0, height = 0;                   // each page's, in pixels
    double width_pt = 0, height_pt = 0;          // the paper's, in points (1/72 inch)
    std::vector<std::vector<uint8_t>> pages;     // xrgb8888, width x height each
    std::vector<SheetStep> steps;
    std::vector<SheetValue> values;
    SheetValue mark;  // "Name: ____" on the pupil's first page, "Key" on the teacher's: where, and which
    render::Canvas page(std::size_t i) const;
};

// The K step `i`'s question is about, given the K its picture would start at.
double asked_curvature(const files::LessonStep& step, double start_K);

// The pages of `lesson`: the pupil's, or with `answers` the teacher's key. `base`: run's options
// (its engine, palette, language). False with one sentence in `error` (a stop signal).
bool make_worksheet(const files::Lesson& lesson, const Options& base, bool answers, Paper paper, Worksheet& out,
                    std::string& error);

// Whether `path` names a PDF: its extension is .pdf in any case ("x.PDF", "x.Pdf").
bool names_pdf(const std::string& path);

// make_worksheet into `path`: a PDF if names_pdf(path), else a PNG. False with one sentence.
bool write_worksheet(const files::Lesson& lesson, const Options& base, const std::string& path, bool answers,
                     Paper paper, std::string& error);

}  // namespace noneuclid::app

// The languages the program speaks, one row each: X(code, its own name). A language's two files
// define its tables, named after its code: lang/<code>.cpp its texts (kTexts_<code>, every name
// of lang/texts.hpp) and lang/lessons_<code>.cpp its built-in lessons (kLessons_<code>, step for
// step the English ones). src/sources.cmake builds every .cpp of lang/, so a language is its row
// here and its two files. English comes first: the texts' index and the lessons' order are its.
#pragma once

#define NONEUCLID_LANGUAGES(X) \
    X(en, "English")           \
    X(de, "Deutsch")           \
    X(fr, "Français")

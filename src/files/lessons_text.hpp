// The built-in lessons' file texts, one table a language (files/lessons*.cpp).
#pragma once

namespace noneuclid::files {

struct BuiltinLesson {
    const char* name;
    const char* text;
};

extern const BuiltinLesson kLessonsGerman[];
extern const int kLessonsGermanCount;
extern const BuiltinLesson kLessonsFrench[];
extern const int kLessonsFrenchCount;

}  // namespace noneuclid::files

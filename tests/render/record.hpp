// A measurement for --gtest_output=xml (RecordProperty), formatted like printf: the perf tests'
// figures, kept beside their pass or fail.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

template <class... A>
void noneuclid_test_record(const char* format, A... args) {
    char text[512];
    std::snprintf(text, sizeof text, format, args...);
    static int n = 0;
    ::testing::Test::RecordProperty("measured_" + std::to_string(++n), text);
}

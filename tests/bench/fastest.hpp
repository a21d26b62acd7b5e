// The fastest of each benchmark's repetitions (--benchmark_repetitions=N), for the summary
// tables the benchmarks print: on a shared machine the others' load only ever adds time.
// FastestReporter prints as the console reporter does and hands every iteration run to a
// callback, which keeps what it wants with keep_fastest.
#pragma once

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

template <class OnRun>
class FastestReporter final : public benchmark::ConsoleReporter {
public:
    explicit FastestReporter(OnRun on_run) : on_run_(std::move(on_run)) {}
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs)
            if (r.run_type == Run::RT_Iteration) on_run_(r.run_name.function_name, r);
    }

private:
    OnRun on_run_;
};

// Keeps the smallest value seen under `name`; true when `value` is the new smallest.
inline bool keep_fastest(std::map<std::string, double>& best, const std::string& name, double value) {
    auto it = best.find(name);
    if (it != best.end() && !(value < it->second)) return false;
    best[name] = value;
    return true;
}

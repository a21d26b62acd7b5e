// Cost of each fixed-point function against std:: double and float, measured side by side in
// one run (Google Benchmark), with a summary table of ns/call and ratios at the end.
//     build/release/bench_fixed                       # everything
//     build/release/bench_fixed --benchmark_filter=sin
// Each call takes its input from a 1024-entry array (see functions.hpp) so nothing folds away;
// the loop costs the same for every implementation.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "fixed/tables.hpp"
#include "functions.hpp"

namespace nb = noneuclid::bench;

namespace {

enum class Impl { fixed, dbl, flt };

// One call per iteration of implementation M of function I, on the shared 1024 inputs.
template <int I, Impl M>
void bm(benchmark::State& st) {
    static nb::Inputs in;
    nb::make_inputs(nb::kFunctions[I], in);
    unsigned i = 0;
    for (auto _ : st) {
        if constexpr (M == Impl::fixed)
            benchmark::DoNotOptimize(nb::kFunctions[I].fixed_fn(in.fixed_raw[i], in.fixed_raw2[i]));
        else if constexpr (M == Impl::dbl)
            benchmark::DoNotOptimize(nb::kFunctions[I].double_fn(in.d[i], in.d2[i]));
        else
            benchmark::DoNotOptimize(nb::kFunctions[I].float_fn(in.f[i], in.f2[i]));
        i = (i + 1) & (nb::kInputs - 1);
    }
}

template <int... I>
void register_all(std::integer_sequence<int, I...>) {
    (benchmark::RegisterBenchmark((std::string(nb::kFunctions[I].name) + "/fixed").c_str(), bm<I, Impl::fixed>), ...);
    (benchmark::RegisterBenchmark((std::string(nb::kFunctions[I].name) + "/double").c_str(), bm<I, Impl::dbl>), ...);
    (benchmark::RegisterBenchmark((std::string(nb::kFunctions[I].name) + "/float").c_str(), bm<I, Impl::flt>), ...);
}

// Prints what the console reporter prints, and remembers ns/call for the summary.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs)
            if (!r.error_occurred && r.run_type == Run::RT_Iteration)
                ns_[r.benchmark_name()] = r.GetAdjustedCPUTime();  // ns (the default unit)
        ConsoleReporter::ReportRuns(runs);
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        std::printf("\nns per call (CPU time), same run; ratio > 1 means fixed is faster\n");
        std::printf("%-8s %10s %10s %10s %14s %14s\n", "function", "fixed", "double", "float",
                    "double/fixed", "float/fixed");
        for (int i = 0; i < nb::kFunctionCount; ++i) {
            const std::string n = nb::kFunctions[i].name;
            const auto f = ns_.find(n + "/fixed"), d = ns_.find(n + "/double"), s = ns_.find(n + "/float");
            if (f == ns_.end() || d == ns_.end() || s == ns_.end()) continue;
            std::printf("%-8s %10.2f %10.2f %10.2f %14.2f %14.2f\n", n.c_str(), f->second, d->second,
                        s->second, d->second / f->second, s->second / f->second);
        }
        std::printf("lookup tables: %zu bytes\n", noneuclid::fx::tables::table_bytes);
    }

private:
    std::map<std::string, double> ns_;
};

}  // namespace

int main(int argc, char** argv) {
    register_all(std::make_integer_sequence<int, nb::kFunctionCount>{});
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}

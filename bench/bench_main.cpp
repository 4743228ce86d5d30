// The one Google Benchmark main of dda_bench.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();

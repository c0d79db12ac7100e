//! pm-bench: speed of the hot path, with Google Benchmark, against ViSP doing the same work in the same process.
//! The benchmarks are in bench_fitness.cpp, bench_hue.cpp and bench_tracker.cpp, by stage.
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "BenchSetup.h"

int main(int argc, char **argv)
{
  // pm-bench [suite] [Google Benchmark flags]; the suite "fitness" runs the fitness and hue benchmarks.
  std::vector<char *> args{argv[0]};
  std::string filter = "--benchmark_filter=.";
  std::string format = "--benchmark_format=json";
  int i = 1;
  if (argc > 1 && argv[1][0] != '-') {
    const std::string suite = argv[1];
    if (suite == "fitness")
      filter = "--benchmark_filter=^(Fitness|Hue)";
    else {
      std::cerr << "pm-bench: usage error: unknown suite '" << suite << "' (known: fitness) (see --help)" << std::endl;
      return 2;
    }
    i = 2;
  }
  for (int k = 1; k < argc; ++k)
    if (!std::strcmp(argv[k], "--help") || !std::strcmp(argv[k], "-h")) {
      std::cout << "usage: pm-bench [fitness] [Google Benchmark flags, e.g. --benchmark_filter=REGEX "
                   "--benchmark_repetitions=N]\n"
                   "Prints JSON (Google Benchmark's format) on stdout: stereo fitness evaluations per second on one core "
                   "for the default C12 model and a 1,000-point model (AVX2 and scalar kernels, and the same fitness "
                   "written with ViSP's types as the peer), hue planes against vpImageConvert::RGBaToHSV, the four "
                   "fitness maps on all cores, the stages of a tracked frame (hue planes as tracked, a generation of "
                   "evaluations exact and coarse, the smooth ascent's gradient, RM-GA's own work; whole, steady, steady on "
                   "the whole images as the peer of the steady frame's hue windows, verifying a lock, and the 1,900 "
                   "evaluations of before issue 18 as the whole frame's peer) and the lab's renderer (a stereo pair).\n";
      return 0;
    }
  args.push_back(filter.data());
  args.push_back(format.data());
  for (; i < argc; ++i)
    args.push_back(argv[i]);
  int n = static_cast<int>(args.size());
  try {
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data()))
      return 2;
    pm::bench::setup(); // build the scene before timing; errors surface here
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception &e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}

#pragma once
// A Google Benchmark reporter that also keeps each run's time, so a benchmark program can
// print ratios against a baseline measured in the same run.

#include <benchmark/benchmark.h>

#include <map>
#include <string>

namespace mxc::bench {

class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration || run.iterations == 0) continue;
      seconds_[run.benchmark_name()] = run.GetAdjustedRealTime() * timeUnitSeconds(run.time_unit);
    }
    ConsoleReporter::ReportRuns(runs);
  }

  /// Real time of one iteration, in seconds (0 when the benchmark did not run). `name` is the
  /// function name; suffixes such as "/min_time:0.500" are ignored.
  double seconds(const std::string& name) const {
    for (const auto& [full, value] : seconds_) {
      if (full == name || full.rfind(name + "/", 0) == 0) return value;
    }
    return 0.0;
  }

 private:
  static double timeUnitSeconds(benchmark::TimeUnit unit) {
    switch (unit) {
      case benchmark::kNanosecond: return 1e-9;
      case benchmark::kMicrosecond: return 1e-6;
      case benchmark::kMillisecond: return 1e-3;
      default: return 1.0;
    }
  }
  std::map<std::string, double> seconds_;
};

}  // namespace mxc::bench

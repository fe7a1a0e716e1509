// Run progress for people: a one-line bar (strain, steps per second, ETA, running eta_r) on a terminal, plain
// periodic log lines otherwise (batch jobs), nothing with --quiet.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace suspend::io {

class Progress {
 public:
  enum class Mode { bar, log, quiet };
  Progress(Mode mode, double target_strain, double start_strain);
  static Mode detect(bool quiet);

  void update(double strain, std::int64_t step, double eta_r);
  void finish();
  void message(const std::string& line);  // a log line that does not break the bar

 private:
  using clock = std::chrono::steady_clock;
  Mode mode_;
  double target_, start_;
  clock::time_point t0_, last_print_;
  std::int64_t step0_ = -1;
  double next_log_fraction_ = 0.1;
  bool bar_drawn_ = false;
};

}  // namespace suspend::io

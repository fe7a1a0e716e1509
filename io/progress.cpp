#include "io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace suspend::io {

Progress::Progress(Mode mode, double target, double start)
    : mode_(mode), target_(target), start_(start), t0_(clock::now()), last_print_(t0_) {}

Progress::Mode Progress::detect(bool quiet) {
  if (quiet) return Mode::quiet;
  return isatty(STDERR_FILENO) ? Mode::bar : Mode::log;
}

namespace {
std::string duration(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "--:--";
  const long t = std::lround(s);
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", t / 60, t % 60);
  return buf;
}
}  // namespace

void Progress::update(double strain, std::int64_t step, double eta_r) {
  if (mode_ == Mode::quiet) return;
  const auto now = clock::now();
  if (step0_ < 0) step0_ = step;
  const double elapsed = std::chrono::duration<double>(now - t0_).count();
  const double since_print = std::chrono::duration<double>(now - last_print_).count();
  const double done = std::clamp((strain - start_) / std::max(1e-300, target_ - start_), 0.0, 1.0);
  const double rate = elapsed > 0 ? (step - step0_) / elapsed : 0.0;
  const double eta = done > 0 ? elapsed * (1.0 - done) / done : NAN;
  if (mode_ == Mode::bar) {
    if (since_print < 0.2 && done < 1.0) return;
    const int width = 30, filled = static_cast<int>(done * width);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r[%s] strain %.3f/%.3g  %.0f steps/s  ETA %s  eta_r %.4g   ", bar.c_str(), strain,
                 target_, rate, duration(eta).c_str(), eta_r);
    std::fflush(stderr);
    bar_drawn_ = true;
  } else {
    if (done < next_log_fraction_ && since_print < 60.0) return;
    while (next_log_fraction_ <= done) next_log_fraction_ += 0.1;
    std::fprintf(stderr, "strain %.4g of %.4g (%3.0f%%), step %lld, %.0f steps/s, elapsed %s, ETA %s, eta_r %.5g\n",
                 strain, target_, 100.0 * done, static_cast<long long>(step), rate, duration(elapsed).c_str(),
                 duration(eta).c_str(), eta_r);
  }
  last_print_ = now;
}

void Progress::message(const std::string& line) {
  if (mode_ == Mode::quiet) return;
  if (bar_drawn_) std::fprintf(stderr, "\n");
  bar_drawn_ = false;
  std::fprintf(stderr, "%s\n", line.c_str());
}

void Progress::finish() {
  if (mode_ == Mode::bar && bar_drawn_) std::fprintf(stderr, "\n");
  bar_drawn_ = false;
}

}  // namespace suspend::io

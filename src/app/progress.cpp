#include "app/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace dda {

namespace {

constexpr auto kMinRedraw = std::chrono::milliseconds(100);  // ~10 redraws per second
constexpr int kBarWidth = 30;

// "mm:ss", or "h:mm:ss" past an hour; "--:--" when unknown.
std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", s / 60, s % 60);
  }
  return buf;
}

}  // namespace

ProgressBar::ProgressBar(double end, std::string label)
    : end_(end),
      label_(std::move(label)),
      enabled_(isatty(fileno(stderr)) != 0),
      start_(Clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  // Leave the last drawn state but end its line, so that whatever is printed next (an error
  // after an exception, say) starts on a fresh line.
  if (drawn_ && !finished_) std::fputc('\n', stderr);
}

void ProgressBar::update(double value) {
  value_ = value;
  if (!enabled_ || finished_) return;
  const auto now = Clock::now();
  if (drawn_ && now - last_draw_ < kMinRedraw) return;
  last_draw_ = now;
  draw();
}

void ProgressBar::finish() {
  if (finished_) return;
  if (enabled_) {
    draw();
    std::fputc('\n', stderr);
  }
  finished_ = true;
}

void ProgressBar::draw() {
  // An end of 0 (nothing to do) counts as done rather than dividing by zero.
  const double fraction = end_ > 0 ? std::clamp(value_ / end_, 0.0, 1.0) : 1.0;
  const int filled = static_cast<int>(fraction * kBarWidth);
  const std::string bar =
      std::string(filled, '#') + std::string(kBarWidth - filled, '.');
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  // Linear extrapolation of the rate so far; unknown until some progress was made.
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
  // \r returns to the start of the line, \033[K clears what a longer previous line left.
  std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.4g/%.4g  elapsed %s  ETA %s\033[K",
               label_.c_str(), bar.c_str(), 100.0 * fraction, value_, end_,
               format_duration(elapsed).c_str(), format_duration(eta).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace dda

#include "renderer/app/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "base/terminal_text.h"

namespace hsb {
namespace {

// Terminal lines at most this often; log lines at most every kLogPeriod.
constexpr double kTerminalPeriod = 0.2;
constexpr double kLogPeriod = 10.0;

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

const char* stage_name(JobStage stage) {
  switch (stage) {
    case JobStage::sharing: return "reading the series' steps for their shared scale and colours";
    case JobStage::waiting: return "waiting for another task reading the series' steps";
    case JobStage::preparing: return "reading data, tracing trajectories";
    case JobStage::rendering: return "rendering";
    case JobStage::writing: return "writing";
  }
  return "";
}

}  // namespace

std::string human_duration(double seconds) {
  char text[48];
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  if (seconds < 60.0) {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  } else if (seconds < 3600.0) {
    std::snprintf(text, sizeof text, "%d min %d s", int(seconds / 60.0), int(std::fmod(seconds, 60.0)));
  } else {
    std::snprintf(text, sizeof text, "%d h %d min", int(seconds / 3600.0), int(std::fmod(seconds, 3600.0) / 60.0));
  }
  return text;
}

BatchProgress::Mode BatchProgress::mode_for(bool quiet) {
  if (quiet) return Mode::quiet;
  return isatty(STDERR_FILENO) ? Mode::terminal : Mode::lines;
}

BatchProgress::BatchProgress(Mode mode, std::size_t items)
    : mode_(mode), items_(items), batch_start_(Clock::now()), item_start_(batch_start_), last_print_(batch_start_) {}

BatchProgress::~BatchProgress() { finish(); }

void BatchProgress::start(std::size_t index, const std::string& name) {
  index_ = index;
  name_ = name;
  stage_ = JobStage::preparing;
  fraction_ = 0.0;
  item_start_ = stage_start_ = last_print_ = Clock::now();
  print(true);
}

void BatchProgress::update(JobStage stage, double fraction) {
  if (stage != stage_ && (stage == JobStage::rendering || stage == JobStage::sharing)) stage_start_ = Clock::now();
  const bool changed = stage != stage_;
  stage_ = stage;
  fraction_ = fraction;
  print(changed && mode_ == Mode::terminal);
}

void BatchProgress::finish() {
  if (line_shown_ && mode_ == Mode::terminal) std::fputs("\r\033[K", stderr);
  line_shown_ = false;
  if (index_ < items_ && !name_.empty()) {
    finished_seconds_ += seconds_between(item_start_, Clock::now());
    ++finished_;
    name_.clear();
  }
}

void BatchProgress::print(bool force) {
  if (mode_ == Mode::quiet) return;
  const Clock::time_point now = Clock::now();
  const double since = seconds_between(last_print_, now);
  if (mode_ == Mode::terminal ? (!force && since < kTerminalPeriod) : since < kLogPeriod) return;
  last_print_ = now;

  const double elapsed = seconds_between(item_start_, now);
  std::string item = "[" + std::to_string(index_ + 1) + "/" + std::to_string(items_) + "] " + name_ + ": " +
                     stage_name(stage_);
  double left = NAN;  // of this image
  if (stage_ == JobStage::rendering || stage_ == JobStage::sharing) {
    char percent[16];
    std::snprintf(percent, sizeof percent, " %.0f%%", 100.0 * fraction_);
    item += percent;
    const double rendering = seconds_between(stage_start_, now);  // in this stage
    if (fraction_ > 0.02) left = rendering / fraction_ * (1.0 - fraction_);
  }
  item += ", " + human_duration(elapsed) + " elapsed";
  if (std::isfinite(left)) item += ", about " + human_duration(left) + " left";
  if (items_ > 1 && finished_ > 0) {
    // The rest of the batch at the mean time of the images done so far.
    const double mean = finished_seconds_ / double(finished_);
    const double batch_left = (std::isfinite(left) ? left : std::max(0.0, mean - elapsed)) +
                              mean * double(items_ - index_ - 1);
    item += "; batch about " + human_duration(batch_left) + " left";
  }
  if (mode_ == Mode::terminal) {
    std::fprintf(stderr, "\r\033[K%s", shown(item).c_str());
    line_shown_ = true;
  } else {
    std::fprintf(stderr, "hsb: %s\n", shown(item).c_str());
  }
  std::fflush(stderr);
}

}  // namespace hsb

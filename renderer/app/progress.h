#pragma once
// What a batch is doing, for the person waiting on it: on a terminal, one
// line rewritten in place (the image's stage and percentage, elapsed and
// estimated time left, and the batch's); into a log (not a terminal), a
// plain line every ten seconds of a long image; nothing when quiet.
// Everything goes to standard error, so standard output keeps one line
// per finished image.

#include <chrono>
#include <cstddef>
#include <string>

namespace hsb {

// `sharing`: reading a time series' steps for the scale, colours and
// camera its images share (renderer/app/series_scale.h); `waiting`: for
// another task doing that (renderer/app/series_settings_file.h).
enum class JobStage { sharing, waiting, preparing, rendering, writing };

class BatchProgress {
 public:
  enum class Mode { terminal, lines, quiet };
  // terminal when standard error is one, else lines; quiet when asked.
  static Mode mode_for(bool quiet);

  BatchProgress(Mode mode, std::size_t items);
  ~BatchProgress();

  void start(std::size_t index, const std::string& name);
  // Cheap to call often: output is throttled.
  void update(JobStage stage, double fraction);
  // Clears the terminal line, so the image's summary line stands alone.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void print(bool force);

  Mode mode_;
  std::size_t items_, index_ = 0, finished_ = 0;
  std::string name_;
  JobStage stage_ = JobStage::preparing;
  double fraction_ = 0.0;
  Clock::time_point batch_start_, item_start_, stage_start_, last_print_;
  double finished_seconds_ = 0.0;  // of the items done
  bool line_shown_ = false;
};

// "4.2 s", "3 min 5 s", "1 h 2 min".
std::string human_duration(double seconds);

}  // namespace hsb

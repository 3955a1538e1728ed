#pragma once
// VTK reports problems by printing them: through its output window, and as
// coloured log lines on stderr. A user given fifteen lines of VTK's log
// before the real message, or VTK's log and no message at all, is lost; so
// while a capture is alive nothing is printed and the last error is kept,
// for the caller to turn into one DataError naming the file. Internal to
// field/.

#include <mutex>
#include <string>

namespace hsb {

class VtkErrorCapture {
 public:
  // VTK's reporting is global: one capture at a time (others wait).
  VtkErrorCapture();
  ~VtkErrorCapture();
  VtkErrorCapture(const VtkErrorCapture&) = delete;
  VtkErrorCapture& operator=(const VtkErrorCapture&) = delete;

  // The last error since the capture began, reduced to the part a user can
  // act on (its last line, without VTK's source file and object address);
  // "" when there was none.
  std::string last_error() const;

 private:
  std::unique_lock<std::mutex> lock_;
};

}  // namespace hsb

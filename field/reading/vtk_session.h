#pragma once
// VTK as this project needs it, for as long as a session object lives:
//  - quiet: VTK reports problems by printing them, through its output
//    window and as coloured log lines on stderr. A user given fifteen lines
//    of VTK's log before the real message, or VTK's log and no message at
//    all, is lost; so nothing is printed and the first error and warning
//    are kept, for the caller to turn into one DataError naming the file;
//  - deterministic: VTK's own threading (vtkSMPTools) builds cell locators
//    and averages cell data in an order that depends on scheduling, which
//    moved trajectories by a few ulps between runs and so changed images.
//    Its backend is set to sequential: the data sets are read once and are
//    small next to the rendering, which keeps its threads.
// Internal to field/.

#include <mutex>
#include <string>

namespace hsb {

class VtkSession {
 public:
  // VTK's reporting is global: one session at a time (others wait). So a
  // thread that holds one must not open another, which would wait for
  // ever: it passes its session down instead.
  VtkSession();
  ~VtkSession();
  VtkSession(const VtkSession&) = delete;
  VtkSession& operator=(const VtkSession&) = delete;

  // The first error (or warning) since the session began, reduced to the
  // part a user can act on (its first line, without VTK's source file and
  // object address); "" when there was none. The first, because VTK's
  // later messages are consequences ("returned failure for request ...").
  std::string first_error() const;
  std::string first_warning() const;

 private:
  std::unique_lock<std::mutex> lock_;
};

}  // namespace hsb

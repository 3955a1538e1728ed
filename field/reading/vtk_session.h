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

class vtkAlgorithm;

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

  // Throws DataError "PATH: cannot read it as AS: ..." for the first
  // error VTK reported in this session, and with `warnings` for its first
  // warning too (where a reader's warning is a file it could not read as
  // declared: a truncated array read as garbage).
  void refuse_complaints(const std::string& path, const std::string& as, bool warnings) const;

 private:
  std::unique_lock<std::mutex> lock_;
};

// The one way a VTK reader is run on a user's file: `reader`'s Update(),
// then everything VTK reported refused (VtkSession::refuse_complaints). A
// file that declares more than memory holds, which some of VTK's readers
// meet with a bare std::bad_alloc, is a DataError naming the file too.
void update_reader(vtkAlgorithm* reader, const VtkSession& vtk, const std::string& path, const std::string& as,
                   bool warnings);

// Throws the DataError update_reader makes of a std::bad_alloc, for one
// met in a reader's own steps after VTK's (merging blocks, copying arrays).
[[noreturn]] void refuse_memory(const std::string& path, const std::string& as);

}  // namespace hsb

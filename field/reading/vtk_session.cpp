#include "field/reading/vtk_session.h"

#include <vtkAlgorithm.h>
#include <vtkLogger.h>
#include <vtkOutputWindow.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <new>

#include "field/reading/data_error.h"

namespace hsb {
namespace {

std::mutex session_mutex;
// Guarded by session_mutex while a session lives.
std::string first_error_text, first_warning_text;

void keep(std::string& first, const char* text) {
  if (first.empty() && text) first = text;
}

class CapturingOutputWindow : public vtkOutputWindow {
 public:
  static CapturingOutputWindow* New() { return new CapturingOutputWindow; }
  void DisplayErrorText(const char* text) override { keep(first_error_text, text); }
  void DisplayWarningText(const char* text) override { keep(first_warning_text, text); }
  void DisplayGenericWarningText(const char* text) override { keep(first_warning_text, text); }
  void DisplayDebugText(const char*) override {}
  void DisplayText(const char*) override {}
};

void on_log(void*, const vtkLogger::Message& message) {
  if (message.verbosity <= vtkLogger::VERBOSITY_ERROR) keep(first_error_text, message.message);
  else if (message.verbosity == vtkLogger::VERBOSITY_WARNING) keep(first_warning_text, message.message);
}

// Once: every VTK message goes to the session, none to the terminal, and
// VTK's own loops run in order.
void install() {
  static const bool installed = [] {
    vtkSMPTools::SetBackend("Sequential");
    vtkOutputWindow::SetInstance(vtkSmartPointer<CapturingOutputWindow>::New());
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    vtkLogger::AddCallback("hsb-capture", on_log, nullptr, vtkLogger::VERBOSITY_WARNING);
    return true;
  }();
  (void)installed;
}

}  // namespace

VtkSession::VtkSession() : lock_(session_mutex) {
  install();
  first_error_text.clear();
  first_warning_text.clear();
}

VtkSession::~VtkSession() = default;

namespace {

// The first line of a VTK message, without VTK's source file and object
// address ("vtkXMLReader (0x...): could not load x.vtu" gives "could not
// load x.vtu").
std::string user_part(std::string s) {
  const std::size_t nl = s.find('\n');
  if (nl != std::string::npos) s.resize(nl);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  const std::size_t colon = s.find("): ");
  return colon == std::string::npos ? s : s.substr(colon + 3);
}

}  // namespace

std::string VtkSession::first_error() const { return user_part(first_error_text); }
std::string VtkSession::first_warning() const { return user_part(first_warning_text); }

void VtkSession::refuse_complaints(const std::string& path, const std::string& as, bool warnings) const {
  std::string complaint = first_error();
  if (complaint.empty() && warnings) complaint = first_warning();
  if (!complaint.empty()) throw DataError(path + ": cannot read it as " + as + ": " + complaint);
}

void refuse_memory(const std::string& path, const std::string& as) {
  throw DataError(path + ": cannot read it as " + as +
                  ": it declares more than memory holds (VTK could not allocate what its sizes ask for)");
}

void update_reader(vtkAlgorithm* reader, const VtkSession& vtk, const std::string& path, const std::string& as,
                   bool warnings) {
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    refuse_memory(path, as);
  }
  vtk.refuse_complaints(path, as, warnings);
}

}  // namespace hsb

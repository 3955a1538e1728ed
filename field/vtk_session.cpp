#include "field/vtk_session.h"

#include <vtkLogger.h>
#include <vtkOutputWindow.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

namespace hsb {
namespace {

std::mutex session_mutex;
std::string last_message;  // guarded by session_mutex while a session lives

class CapturingOutputWindow : public vtkOutputWindow {
 public:
  static CapturingOutputWindow* New() { return new CapturingOutputWindow; }
  void DisplayErrorText(const char* text) override { last_message = text ? text : ""; }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  void DisplayText(const char*) override {}
};

void on_log(void*, const vtkLogger::Message& message) {
  if (message.verbosity <= vtkLogger::VERBOSITY_ERROR) last_message = message.message ? message.message : "";
}

// Once: every VTK message goes to the session, none to the terminal, and
// VTK's own loops run in order.
void install() {
  static const bool installed = [] {
    vtkSMPTools::SetBackend("Sequential");
    vtkOutputWindow::SetInstance(vtkSmartPointer<CapturingOutputWindow>::New());
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    vtkLogger::AddCallback("hsb-capture", on_log, nullptr, vtkLogger::VERBOSITY_ERROR);
    return true;
  }();
  (void)installed;
}

}  // namespace

VtkSession::VtkSession() : lock_(session_mutex) {
  install();
  last_message.clear();
}

VtkSession::~VtkSession() = default;

std::string VtkSession::last_error() const {
  std::string s = last_message;
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  const std::size_t nl = s.rfind('\n');
  s = nl == std::string::npos ? s : s.substr(nl + 1);
  const std::size_t colon = s.find("): ");
  return colon == std::string::npos ? s : s.substr(colon + 3);
}

}  // namespace hsb

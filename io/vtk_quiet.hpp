#pragma once
// VTK reports its errors through its own output window (several lines on stderr, with source locations);
// our writers report a failure themselves, as one line. QuietVtk silences VTK's warnings and errors while
// it lives (process-wide switch; writers run on one thread).
#include <vtkObject.h>

namespace exactvis {

struct QuietVtk {
  QuietVtk() : was_(vtkObject::GetGlobalWarningDisplay()) { vtkObject::GlobalWarningDisplayOff(); }
  ~QuietVtk() { vtkObject::SetGlobalWarningDisplay(was_); }
  QuietVtk(const QuietVtk&) = delete;
  QuietVtk& operator=(const QuietVtk&) = delete;

 private:
  int was_;
};

}  // namespace exactvis

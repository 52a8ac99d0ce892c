#pragma once
// An X display for VTK's offscreen rendering on machines without one: Debian's VTK 9 renders through GLX
// only (no EGL/OSMesa build), so when DISPLAY is unset a private Xvfb server (the xvfb package, Mesa's
// software OpenGL) is started for the lifetime of this object, on a display number Xvfb picks itself
// (-displayfd), and stopped (by its process id) at the end. docs/cli.md, "aspect".
#include <string>

namespace exactvis {

class HeadlessDisplay {
 public:
  // Uses $DISPLAY if set; else starts Xvfb and sets DISPLAY. Throws OutputError("PATH: ...") naming `what`
  // when no display can be had.
  explicit HeadlessDisplay(const std::string& what);
  ~HeadlessDisplay();
  HeadlessDisplay(const HeadlessDisplay&) = delete;
  HeadlessDisplay& operator=(const HeadlessDisplay&) = delete;

 private:
  int pid_ = -1;
};

}  // namespace exactvis

#pragma once
// An X display for VTK's offscreen rendering (io/render_png, io/render_partition_png): Debian's VTK 9.1 is
// built for X11 only (no OSMesa, no EGL), so it needs a display. When DISPLAY is unset, a private virtual
// display is started (`Xvfb -displayfd`, Mesa's software OpenGL) for the lifetime of this object and that
// Xvfb process (only the one started here, by its id) is stopped at the end. Xvfb missing or failing is an
// OutputError ("FILE: cannot render: ...").
#include <string>
#include <sys/types.h>

namespace exactvis {

class HeadlessDisplay {
 public:
  // Uses $DISPLAY if set, else starts Xvfb and sets DISPLAY; `path` names the output file in errors.
  explicit HeadlessDisplay(const std::string& path);
  ~HeadlessDisplay();
  HeadlessDisplay(const HeadlessDisplay&) = delete;
  HeadlessDisplay& operator=(const HeadlessDisplay&) = delete;

 private:
  void stop();
  pid_t pid_ = -1;
  std::string display_;
};

}  // namespace exactvis

#pragma once
// A rendered picture of the lit scene for `exactvis shadows --png` (VTK, offscreen). The shadow mesh is drawn
// coloured by per-vertex irradiance (black = umbra, through orange to white at the largest irradiance), the
// lights in yellow and the other triangles in grey; the camera looks at the scene box from above one corner.
//
// Headless rendering: Debian's VTK 9.1 is built for X11 only (no OSMesa, no EGL), so it needs an X display.
// When DISPLAY is unset, the renderer starts its own virtual display (`Xvfb -displayfd`, Mesa's software
// OpenGL), renders, and stops that Xvfb process (only the one it started). Xvfb missing or failing is an
// OutputError ("FILE: cannot render: ...").
#include "kernel/scene.hpp"
#include "shadows/shadow_mesh.hpp"

#include <string>
#include <vector>

class vtkRenderWindow;
class vtkRenderer;

namespace exactvis {

// Renders `window` (offscreen, size and renderers set) and writes its back buffer to `path` as PNG.
// Returns whether the PNG writer succeeded. Shared by every offscreen picture (io/render_partition_png).
bool save_render_window_png(vtkRenderWindow* window, const std::string& path);

// One renderer filling an offscreen width x height window, rendered and written to `path` as PNG (through
// save_render_window_png). Shared by the single-view pictures (shadows, io/render_scene_png).
bool save_renderer_png(vtkRenderer* renderer, int width, int height, const std::string& path);

// Renders to `temp_path` (.png), width x height pixels. Returns false (or throws OutputError) on failure.
bool render_shadows_png(const std::string& temp_path, const Scene& scene, const shadows::ShadowResult& result,
                        const std::vector<int>& light, int width = 1280, int height = 960);

}  // namespace exactvis

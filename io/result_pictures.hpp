#pragma once
// The pictures of the 3D jobs (`--png F` of visible, pvs, events, export; docs/cli.md "Pictures"): each
// builds the layers of an io/render_scene_png.hpp picture from a result, with its legend. Colours:
// visible triangles green, hidden red, triangles not asked about light grey; the view cell or source polygon
// a blue wire frame; witnesses thin dark lines; EV surfaces orange, EEE surfaces purple over the scene in
// grey (the legend lists the kinds drawn); a scene alone coloured by object. Display only (double approximations of exact values).
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "io/render_scene_png.hpp"
#include "io/write_visibility_vtp.hpp"

#include <string>
#include <vector>

namespace exactvis {

// Input: the scene, per-triangle state parallel to scene.triangles (1 visible, 0 hidden, -1 not asked), the
// witnesses to draw (empty: none), the source's faces (a cell's 6 faces or one polygon; drawn as edges),
// and a title. Output: the picture; the legend counts each state drawn (states with no triangle are left out).
ScenePicture visibility_picture(const Scene& scene, const std::vector<int>& state,
                                const std::vector<WitnessSegment>& witnesses,
                                const std::vector<std::vector<Point3>>& source_faces, const std::string& title);

// Input: the scene and the events computed on it; strip pieces per free interval (events/event_surfaces.hpp;
// two exact ray casts per sample, so keep it small on large results). Output: the surfaces over the scene.
ScenePicture events_picture(const Scene& scene, const EvResult& ev, const EeeResult& eee, int samples_per_interval,
                            const std::string& title);

// The scene alone, each object in its own colour (legend: the first objects by name, then "N more").
ScenePicture scene_picture(const Scene& scene, const std::string& title);

}  // namespace exactvis

#include "io/result_pictures.hpp"

#include "events/event_surfaces.hpp"
#include "util/format_number.hpp"

#include <algorithm>
#include <map>

namespace exactvis {

namespace {

constexpr Rgb kVisible{80, 175, 90}, kHidden{205, 85, 75}, kNotAsked{200, 200, 200}, kSource{30, 90, 210},
    kWitness{40, 40, 40}, kEv{240, 150, 30}, kEee{140, 70, 190}, kScene{175, 175, 180};

}  // namespace

ScenePicture visibility_picture(const Scene& scene, const std::vector<int>& state,
                                const std::vector<WitnessSegment>& witnesses,
                                const std::vector<std::vector<Point3>>& source_faces, const std::string& title) {
  std::vector<Rgb> colours(scene.triangles.size(), kNotAsked);
  std::int64_t counts[3] = {0, 0, 0};  // not asked, hidden, visible
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const int s = i < state.size() ? state[i] : -1;
    colours[i] = s == 1 ? kVisible : s == 0 ? kHidden : kNotAsked;
    ++counts[std::clamp(s, -1, 1) + 1];
  }
  ScenePicture pic;
  pic.title = title;
  pic.meshes.push_back(scene_mesh(scene, colours));
  PictureLines source{{}, kSource, 3.0};
  for (const auto& face : source_faces)
    for (std::size_t k = 0; k < face.size(); ++k) source.segments.push_back({face[k], face[(k + 1) % face.size()]});
  pic.lines.push_back(std::move(source));
  PictureLines w{{}, kWitness, 1.0};
  for (const auto& s : witnesses) w.segments.push_back({s.p, s.q});
  const bool with_witnesses = !w.segments.empty();
  pic.lines.push_back(std::move(w));
  // The legend lists what is drawn (the title gives the counts).
  if (counts[2] > 0) pic.legend.push_back({"visible: " + format_count(counts[2]) + " triangles", kVisible});
  if (counts[1] > 0) pic.legend.push_back({"hidden: " + format_count(counts[1]) + " triangles", kHidden});
  if (counts[0] > 0) pic.legend.push_back({"not asked: " + format_count(counts[0]) + " triangles", kNotAsked});
  pic.legend.push_back({source_faces.size() == 1 ? "source polygon" : "view cell", kSource});
  if (with_witnesses) pic.legend.push_back({"witness segments", kWitness});
  return pic;
}

ScenePicture events_picture(const Scene& scene, const EvResult& ev, const EeeResult& eee, int samples_per_interval,
                            const std::string& title) {
  ScenePicture pic;
  pic.title = title;
  PictureMesh base = scene_mesh(scene, std::vector<Rgb>(scene.triangles.size(), kScene));
  base.opacity = 0.45;  // the surfaces lie between scene faces: see them through the scene
  base.cull_back_faces = true;
  pic.meshes.push_back(std::move(base));
  PictureMesh surfaces;
  surfaces.lit = false;
  for (const EventSurface& s : event_surfaces(scene, ev, eee, samples_per_interval)) {
    const Rgb c = s.kind == EventSurface::Kind::EV ? kEv : kEee;
    for (std::size_t k = 0; k + 1 < s.samples.size(); ++k) {
      const auto& a = s.samples[k];
      const auto& b = s.samples[k + 1];
      surfaces.triangles.push_back({a.back, a.front, b.front});
      surfaces.triangles.push_back({a.back, b.front, b.back});
      surfaces.colours.push_back(c);
      surfaces.colours.push_back(c);
    }
  }
  pic.meshes.push_back(std::move(surfaces));
  pic.legend.push_back({"scene", kScene});
  // Only the kinds drawn (the title gives both counts).
  if (!ev.events.empty())
    pic.legend.push_back({"EV event surfaces: " + format_count(static_cast<std::int64_t>(ev.events.size())) + " events", kEv});
  if (!eee.events.empty())
    pic.legend.push_back({"EEE event surfaces: " + format_count(static_cast<std::int64_t>(eee.events.size())) + " events", kEee});
  return pic;
}

ScenePicture scene_picture(const Scene& scene, const std::string& title) {
  std::vector<Rgb> colours;
  colours.reserve(scene.triangles.size());
  std::map<int, std::int64_t> per_object;
  for (const auto& t : scene.triangles) {
    colours.push_back(palette_colour(t.object));
    ++per_object[t.object];
  }
  ScenePicture pic;
  pic.title = title;
  pic.meshes.push_back(scene_mesh(scene, colours));
  constexpr std::size_t kShown = 12;
  std::size_t shown = 0;
  for (const auto& [object, n] : per_object) {
    if (shown++ == kShown) break;
    const std::string name = object < static_cast<int>(scene.objects.size()) ? scene.objects[object].name : "?";
    pic.legend.push_back({name + ": " + format_count(n) + " triangles", palette_colour(object)});
  }
  if (per_object.size() > kShown)
    pic.legend.push_back({format_count(static_cast<std::int64_t>(per_object.size() - kShown)) + " more objects",
                          Rgb{255, 255, 255}});
  return pic;
}

}  // namespace exactvis

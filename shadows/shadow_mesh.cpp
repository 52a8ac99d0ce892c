#include "shadows/shadow_mesh.hpp"

#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "kernel/triangle_index.hpp"
#include "shadows/point_irradiance.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>

namespace exactvis::shadows {

ShadowResult compute_shadows(const Scene& scene, const ShadowOptions& options) {
  if (options.light.empty()) throw std::invalid_argument("compute_shadows: no light triangles");
  ShadowResult res;
  const auto start = std::chrono::steady_clock::now();
  const TriangleIndex index(scene);
  std::vector<std::int64_t> receivers = options.receivers;
  if (receivers.empty()) {
    const std::set<int> light(options.light.begin(), options.light.end());
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
      if (!light.count(static_cast<int>(i))) receivers.push_back(static_cast<std::int64_t>(i));
  }
  EvOptions evo;
  evo.light_triangles = options.light;
  evo.progress = options.progress;
  evo.parallel = options.parallel;
  EeeOptions eeo;
  eeo.light_triangles = options.light;
  eeo.progress = options.progress;
  eeo.parallel = options.parallel;
  const EvResult ev = enumerate_ev_events(scene, evo);
  const EeeResult eee = enumerate_eee_events(scene, eeo);
  res.stats.ev_events = ev.events.size();
  res.stats.eee_events = eee.events.size();
  auto curves = event_curves(scene, index, options.light, ev, eee, receivers, options.eee);
  const auto mid = std::chrono::steady_clock::now();
  res.stats.seconds_events = std::chrono::duration<double>(mid - start).count();

  res.receivers.resize(receivers.size());
  std::atomic<std::uint64_t> backprojections{0};
  ProgressBar bar("shadows: receivers", receivers.size(), options.progress);
  for_each_index(receivers.size(), options.parallel, 1, [&](std::size_t i) {
    ReceiverShadows& out = res.receivers[i];
    out.triangle = receivers[i];
    const std::int64_t rid = scene.triangles[out.triangle].id;
    const ReceiverFrame frame = receiver_frame(scene, out.triangle);
    if (const auto it = curves.find(rid); it != curves.end()) out.curves = it->second;
    for (auto& c : contact_curves(scene, index, options.light, out.triangle)) out.curves.push_back(std::move(c));
    std::vector<std::vector<std::array<Exact, 2>>> polylines;
    for (const auto& c : out.curves) {
      std::vector<std::array<Exact, 2>> pl;
      for (const auto& p : c.points) pl.push_back(frame.to_uv(p));
      polylines.push_back(std::move(pl));
    }
    out.mesh = receiver_faces(polylines);
    for (const auto& f : out.mesh.faces) {
      FaceShading s;
      s.area_uv = f.area_uv;
      s.area = CGAL::to_double(f.area_uv) * frame.area_scale();
      s.sample = frame.to_3d(f.sample[0], f.sample[1]);
      Backprojection bp = backproject(scene, index, options.light, s.sample);
      s.light_class = bp.light_class;
      s.fraction_exact = bp.fraction_exact;
      s.fraction = bp.fraction;
      s.fraction_value = bp.fraction_value;
      s.irradiance = point_irradiance(scene, s.sample, frame.normal(), bp);
      s.blockers = std::move(bp.blockers);
      s.visible = std::move(bp.parts);
      out.faces.push_back(std::move(s));
      ++backprojections;
    }
    for (const auto& v : out.mesh.vertices) out.vertices.push_back(frame.to_3d(v[0], v[1]));
    if (options.vertex_irradiance) {
      for (const auto& v : out.vertices) {
        const Backprojection bp = backproject(scene, index, options.light, v);
        out.vertex_irradiance.push_back(point_irradiance(scene, v, frame.normal(), bp));
        ++backprojections;
      }
    }
    bar.advance();
  });
  res.stats.backprojections = backprojections.load();
  res.stats.seconds_receivers =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - mid).count();
  return res;
}

}  // namespace exactvis::shadows

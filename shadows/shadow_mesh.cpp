#include "shadows/shadow_mesh.hpp"

#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "kernel/triangle_index.hpp"
#include "shadows/blocker_eee_events.hpp"
#include "shadows/blocker_events.hpp"
#include "shadows/conic_arrangement.hpp"
#include "shadows/point_irradiance.hpp"
#include "shadows/polyline_arrangement.hpp"
#include "shadows/receiver_shaft.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <iostream>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>

namespace exactvis::shadows {

std::vector<ArrangementCurve> arrangement_curves(const std::vector<DiscontinuityCurve>& curves,
                                                 const ReceiverFrame& frame) {
  std::vector<ArrangementCurve> out;
  out.reserve(curves.size());
  for (const auto& c : curves) {
    ArrangementCurve a;
    for (const auto& p : c.points) a.points.push_back(frame.to_uv(p));
    if (c.kind == DiscontinuityCurve::Kind::EEE) a.conic = c.conic;
    out.push_back(std::move(a));
  }
  return out;
}

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
  EvResult ev = enumerate_ev_events(scene, evo);
  res.stats.ev_events = ev.events.size();
  BlockerEvOptions bo;  // the blocker-blocker EV and EEE events
  bo.parallel = options.parallel;
  bo.progress = options.progress;
  bo.cull = options.blocker_cull;
  if (options.blocker_events) {
    const auto before_bb = std::chrono::steady_clock::now();
    EvResult bb = blocker_ev_events(scene, options.light, bo);
    res.stats.seconds_blocker_ev = std::chrono::duration<double>(std::chrono::steady_clock::now() - before_bb).count();
    res.stats.blocker_ev_events = bb.events.size();
    for (auto& e : bb.events) ev.events.push_back(std::move(e));
  }
  const auto after_ev = std::chrono::steady_clock::now();
  EeeResult eee = enumerate_eee_events(scene, eeo);
  res.stats.eee_events = eee.events.size();
  if (options.blocker_events) {
    const auto before_bb = std::chrono::steady_clock::now();
    EeeResult bb = blocker_eee_events(scene, options.light, bo);
    res.stats.seconds_blocker_eee =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - before_bb).count();
    res.stats.blocker_eee_events = bb.events.size();
    for (auto& e : bb.events) eee.events.push_back(std::move(e));
  }
  const auto after_eee = std::chrono::steady_clock::now();
  res.stats.seconds_ev = std::chrono::duration<double>(after_ev - start).count();
  res.stats.seconds_eee = std::chrono::duration<double>(after_eee - after_ev).count();
  auto curves = event_curves(scene, index, options.light, ev, eee, receivers, options.eee);
  const auto mid = std::chrono::steady_clock::now();
  res.stats.seconds_events = std::chrono::duration<double>(mid - start).count();

  res.receivers.resize(receivers.size());
  std::atomic<std::uint64_t> backprojections{0}, conic_arcs{0}, chord_curves{0}, arrangement_failures{0}, trimmed_arcs{0},
      polyline_arrangements{0}, polyline_pieces{0}, cross_checked{0}, cross_mismatches{0},
      uncertified_samples{0}, box_candidates{0}, shaft_candidates{0}, shaft_outside{0};
  ProgressBar bar("shadows: receivers", receivers.size(), options.progress);
  std::mutex warn_mutex;
  for_each_index(receivers.size(), options.parallel, 1, [&](std::size_t i) {
    ReceiverShadows& out = res.receivers[i];
    out.triangle = receivers[i];
    const std::int64_t rid = scene.triangles[out.triangle].id;
    const ReceiverFrame frame = receiver_frame(scene, out.triangle);
    // The receiver's shaft (shadows/receiver_shaft.hpp): the blockers of every backprojection below. A point
    // outside the closed receiver (none expected: samples are inside faces of R, mesh vertices in R) takes
    // the indexed backprojection instead, which needs no precondition.
    std::optional<ReceiverShaft> shaft;
    if (options.shaft_restriction) {
      shaft = receiver_shaft(scene, index, options.light, out.triangle);
      box_candidates += shaft->box_candidates;
      for (const auto& c : shaft->candidates) shaft_candidates += c.size();
    }
    auto backproject_uv = [&](const Exact& u, const Exact& v, const Vec3<Exact>& x) {
      if (shaft && u >= 0 && v >= 0 && u + v <= 1) return backproject(scene, options.light, x, *shaft);
      if (shaft) ++shaft_outside;
      return backproject(scene, index, options.light, x);
    };
    if (const auto it = curves.find(rid); it != curves.end()) out.curves = it->second;
    for (auto& c : contact_curves(scene, index, options.light, out.triangle)) out.curves.push_back(std::move(c));
    const std::vector<ArrangementCurve> arcs = arrangement_curves(out.curves, frame);
    std::vector<std::vector<std::array<Exact, 2>>> polylines;
    for (const auto& a : arcs) polylines.push_back(a.points);
    out.mesh = receiver_faces(polylines);
    std::vector<std::array<Exact, 2>> queries;
    for (const auto& f : out.mesh.faces) queries.push_back(f.sample);
    ReceiverArrangement arr;
    if (options.polyline_first && std::any_of(arcs.begin(), arcs.end(), [](const ArrangementCurve& c) { return c.conic.has_value(); })) {
      arr = polyline_arrangement(arcs, queries);
      ReceiverArrangement cgal = receiver_arrangement(arcs, queries);
      if (!arr.failed && !cgal.failed && !cgal.polyline) {
        ++cross_checked;
        if (cgal.faces.size() != arr.faces.size()) ++cross_mismatches;
      }
      if (arr.failed) arr = std::move(cgal);
    } else {
      arr = receiver_arrangement(arcs, queries);
    }
    // A triangulation face not located in a face inside the receiver (CGAL 5.5's conic point location can
    // miss) makes the display mapping impossible: the certified polyline arrangement is tried instead
    // (shadows/polyline_arrangement.hpp), and if that fails too, the arrangement counts as failed.
    auto unlocated = [](const ReceiverArrangement& a) {
      return std::any_of(a.query_faces.begin(), a.query_faces.end(), [](int qf) { return qf < 0; });
    };
    if (!arr.failed && unlocated(arr) && !arr.polyline) {
      ReceiverArrangement poly = polyline_arrangement(arcs, queries);
      if (!poly.failed) arr = std::move(poly);
      else arr.failure = "a triangulation sample not located in CGAL's conic arrangement; " + poly.failure;
    }
    if (!arr.failed && unlocated(arr)) {
      arr.failed = true;
      if (arr.failure.empty()) arr.failure = "a triangulation sample not located in the arrangement";
    }
    if (arr.failed) {
      // Never silent: counted in the stats, said on stderr (with the receiver's id), and the curves dumped
      // under EXACTVIS_DUMP_ARRANGEMENTS.
      {
        const std::string why = "receiver triangle " + std::to_string(out.triangle) + " (id " + std::to_string(rid) +
                                "): exact arrangement failed (" + arr.failure + ")";
        std::string one_line = why;  // CGAL's messages span lines
        std::replace(one_line.begin(), one_line.end(), '\n', ' ');
        std::lock_guard<std::mutex> lock(warn_mutex);
        std::cerr << "exactvis shadows: warning: " << one_line
                  << "; its faces are the triangulation's (EEE arcs as chords)\n";
        dump_arrangement_curves(arcs, why);
      }
      // CGAL's conic traits failed (see conic_arrangement.hpp): the faces are the triangulation's, EEE arcs
      // as chords (exact chord-polygon areas; each sample's class is exact for the sample).
      out.arrangement_failed = true;
      ++arrangement_failures;
      arr = ReceiverArrangement{};
      for (std::size_t k = 0; k < out.mesh.faces.size(); ++k) {
        ReceiverArrangement::Face f;
        f.sample = out.mesh.faces[k].sample;
        f.area_uv = CGAL::to_double(out.mesh.faces[k].area_uv);
        arr.faces.push_back(f);
        arr.query_faces.push_back(static_cast<int>(k));
      }
    }
    if (arr.polyline) {
      out.polyline_arrangement = true;
      ++polyline_arrangements;
      polyline_pieces += arr.arc_pieces;
    }
    out.conic_arcs = arr.conic_arcs;
    out.chord_curves = arr.chord_curves;
    conic_arcs += arr.conic_arcs;
    trimmed_arcs += arr.trimmed_arcs;
    uncertified_samples += arr.uncertified_samples + arr.uncertified_lenses;
    chord_curves += arr.chord_curves;
    // Without conic arcs the triangulation's constraints are the arrangement's curves: its faces are the
    // arrangement's, one to one, and give the exact areas.
    std::vector<int> cdt_of(arr.faces.size(), -1);
    bool one_to_one = (arr.conic_arcs == 0 || out.arrangement_failed) && arr.faces.size() == out.mesh.faces.size();
    for (std::size_t k = 0; k < arr.query_faces.size(); ++k) {
      const int af = arr.query_faces[k];
      if (cdt_of[af] >= 0) {
        one_to_one = false;
        continue;
      }
      cdt_of[af] = static_cast<int>(k);
    }
    for (auto& tf : out.mesh.triangle_face) tf = arr.query_faces[tf];
    for (std::size_t fi = 0; fi < arr.faces.size(); ++fi) {
      const auto& f = arr.faces[fi];
      FaceShading s;
      s.area_uv_value = f.area_uv;
      s.conic_bounded = f.conic_bounded;
      if (one_to_one) {
        s.area_exact = true;
        s.area_uv = out.mesh.faces[cdt_of[fi]].area_uv;
        s.area_uv_value = CGAL::to_double(s.area_uv);
      }
      s.area = s.area_uv_value * frame.area_scale();
      s.sample = frame.to_3d(f.sample[0], f.sample[1]);
      Backprojection bp = backproject_uv(f.sample[0], f.sample[1], s.sample);
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
      for (std::size_t k = 0; k < out.vertices.size(); ++k) {
        const auto& v = out.vertices[k];
        const Backprojection bp = backproject_uv(out.mesh.vertices[k][0], out.mesh.vertices[k][1], v);
        out.vertex_irradiance.push_back(point_irradiance(scene, v, frame.normal(), bp));
        ++backprojections;
      }
    }
    bar.advance();
  });
  res.stats.backprojections = backprojections.load();
  res.stats.conic_arcs = conic_arcs.load();
  res.stats.chord_curves = chord_curves.load();
  res.stats.arrangement_failures = arrangement_failures.load();
  res.stats.trimmed_arcs = trimmed_arcs.load();
  res.stats.polyline_arrangements = polyline_arrangements.load();
  res.stats.polyline_pieces = polyline_pieces.load();
  res.stats.cross_checked = cross_checked.load();
  res.stats.cross_mismatches = cross_mismatches.load();
  res.stats.uncertified_samples = uncertified_samples.load();
  res.stats.shaft_box_candidates = box_candidates.load();
  res.stats.shaft_candidates = shaft_candidates.load();
  res.stats.shaft_outside_points = shaft_outside.load();
  res.stats.seconds_receivers =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - mid).count();
  return res;
}

}  // namespace exactvis::shadows

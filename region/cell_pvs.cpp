#include "region/cell_pvs.hpp"

#include <cmath>
#include <stdexcept>

namespace exactvis::region {

PvsContext::PvsContext(const Scene& scene)
    : scene_(scene), index_(scene), rays_(scene), bvh_(build_triangle_bvh(scene)) {
  if (scene.triangles.empty()) return;
  const Box3 b = bounding_box(scene);
  const double dx = b.hi.x - b.lo.x, dy = b.hi.y - b.lo.y, dz = b.hi.z - b.lo.z;
  diagonal_ = std::sqrt(dx * dx + dy * dy + dz * dz);
}

const ExtrudedScene& PvsContext::extruded() const {
  std::call_once(lazy_->once, [&] { lazy_->extruded = detect_extruded_scene(scene_); });
  return lazy_->extruded;
}

const std::vector<ConvexSolid>& PvsContext::solids() const {
  std::call_once(lazy_->solids_once, [&] { lazy_->solids = convex_solids(scene_); });
  return lazy_->solids;
}

const CoplanarPanels& PvsContext::coplanar_panels() const {
  std::call_once(lazy_->panels_once, [&] { lazy_->panels = region::coplanar_panels(scene_); });
  return lazy_->panels;
}

std::vector<std::string> visible_objects(const Scene& scene, const CellPvs& pvs) {
  std::vector<char> seen(scene.objects.size(), 0);
  for (const auto& v : pvs.visible) seen[scene.triangles[v.index].object] = 1;
  std::vector<std::string> out;
  for (std::size_t o = 0; o < seen.size(); ++o)
    if (seen[o]) out.push_back(scene.objects[o].name);
  return out;
}

void check_view_cell(const RationalBox3& cell) {
  for (int k = 0; k < 3; ++k)
    if (!(cell.lo[k] < cell.hi[k]))
      throw std::invalid_argument(std::string("view cell is empty or inverted in ") + "xyz"[k] +
                                  " (need lo < hi in every coordinate)");
}

}  // namespace exactvis::region

#include "api/skeleton.hpp"

#include "io/write_skeleton_json.hpp"
#include "util/text_split.hpp"

#include <stdexcept>
#include <vector>

namespace exactvis::api {

namespace {

// One side of --pair: an object's exact name, else a stable triangle id (a whole number that is one).
SkeletonPairSide pair_side(const Scene& scene, const std::string& text, const std::string& spec) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == text) return {static_cast<int>(i), -1};
  bool digits = !text.empty() && text.size() <= 18;
  for (char c : text) digits = digits && c >= '0' && c <= '9';
  if (digits) {
    const std::int64_t id = std::stoll(text);
    if (scene.index_of_id(id) >= 0) return {-1, id};
  }
  throw std::invalid_argument("--pair '" + spec + "': '" + text +
                              "' is neither an object name nor a triangle id of the scene");
}

}  // namespace

std::pair<SkeletonPairSide, SkeletonPairSide> parse_skeleton_pair(const Scene& scene, const std::string& spec) {
  const std::vector<std::string> items = split(spec, ',');
  if (items.size() != 2 || items[0].empty() || items[1].empty())
    throw std::invalid_argument("--pair '" + spec + "': expected two objects A,B (object names or triangle ids)");
  return {pair_side(scene, items[0], spec), pair_side(scene, items[1], spec)};
}

Skeleton3D skeleton(const Scene& scene, const SkeletonRequest& request) {
  SkeletonOptions options;
  options.progress = request.progress_bar;
  return request.pair ? build_pair_skeleton(scene, request.pair->first, request.pair->second, options)
                      : build_skeleton_3d(scene, options);
}

nlohmann::ordered_json skeleton_json(const Scene& scene, const Skeleton3D& skeleton) {
  return skeleton_to_json(scene, skeleton, full_selection(skeleton));
}

}  // namespace exactvis::api

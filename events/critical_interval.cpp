#include "events/critical_interval.hpp"

#include "kernel/rational_between.hpp"

#include <stdexcept>

namespace exactvis {

const char* cause_name(CriticalEnd::Cause c) {
  switch (c) {
    case CriticalEnd::Cause::EdgeEndpoint: return "edge_endpoint";
    case CriticalEnd::Cause::Occluder: return "occluder";
    case CriticalEnd::Cause::Tangency: return "tangency";
    case CriticalEnd::Cause::Singular: return "singular";
    case CriticalEnd::Cause::EndObjectChange: return "end_object_change";
  }
  return "?";
}

const char* feature_name(OccluderFeature::Kind k) {
  switch (k) {
    case OccluderFeature::Kind::Vertex: return "vertex";
    case OccluderFeature::Kind::Edge: return "edge";
    case OccluderFeature::Kind::Face: return "face";
    case OccluderFeature::Kind::WedgeSide: return "wedge_side";
  }
  return "?";
}

Exact rational_parameter(const RootNumber& t) {
  Exact q;
  if (!root_number_rational(t, &q)) throw std::logic_error("rational_parameter: irrational parameter");
  return q;
}

}  // namespace exactvis

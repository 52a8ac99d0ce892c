#pragma once
// The face id of a CGAL point-location result in an arrangement whose faces carry an int (Arr_face_extended_dcel,
// -1 = no id): shared by the conic and the certified polyline receiver arrangements.
#include <CGAL/Arr_point_location_result.h>

namespace exactvis::shadows {

// Input: a point-location result of an Arrangement with int face data. Output: the located face's id; on an
// edge or a vertex, the id of a face next to it that has one (-1 if none). Cost: O(1), or the vertex degree.
template <class Arrangement>
int arrangement_face_id(const typename CGAL::Arr_point_location_result<Arrangement>::Type& obj) {
  int id = -1;
  if (const auto* fh = boost::get<typename Arrangement::Face_const_handle>(&obj)) id = (*fh)->data();
  else if (const auto* hh = boost::get<typename Arrangement::Halfedge_const_handle>(&obj)) {
    id = (*hh)->face()->data();
    if (id < 0) id = (*hh)->twin()->face()->data();
  } else if (const auto* vh = boost::get<typename Arrangement::Vertex_const_handle>(&obj)) {
    auto h0 = (*vh)->incident_halfedges();
    auto h = h0;
    do {
      id = h->face()->data();
    } while (id < 0 && ++h != h0);
  }
  return id;
}

}  // namespace exactvis::shadows

// Area of any fracture inside a box, and P32.
#include "dda/dl/dfn3d_measures.hpp"
#include "dda/dl/fractures3d.hpp"

namespace dda::dl {

double fracture_area_in_box(const Fracture3& f, const Box3& box) {
  switch (f.shape) {
    case FractureShape::Disc: return disc_area_in_box({f.centre, f.normal, f.radius, f.set}, box);
    case FractureShape::Polygon: return polygon_area_in_box(f.vertices, box);
    case FractureShape::Plane: return polygon_area(plane_in_box(f.normal, f.offset(), box));
  }
  return 0;
}

double p32_in_box(const std::vector<Fracture3>& fractures, const Box3& box) {
  validate_box(box, "The P32 sampling box");
  double area = 0;
  for (const Fracture3& f : fractures) area += fracture_area_in_box(f, box);
  return area / box.volume();
}

}  // namespace dda::dl

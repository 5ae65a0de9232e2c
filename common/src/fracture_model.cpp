#include "dda/common/fracture_model.hpp"

#include "dda/common/error.hpp"

namespace dda {

const char* to_string(FractureShape s) {
  switch (s) {
    case FractureShape::Plane: return "plane";
    case FractureShape::Disc: return "disc";
    case FractureShape::Polygon: return "polygon";
  }
  return "unknown";
}

FractureShape fracture_shape_from_string(const std::string& word, const std::string& where) {
  for (FractureShape s : {FractureShape::Plane, FractureShape::Disc, FractureShape::Polygon})
    if (word == to_string(s)) return s;
  throw InputError((where.empty() ? "" : where + ": ") + "unknown fracture shape \"" + word +
                   "\", expected plane, disc or polygon.");
}

}  // namespace dda

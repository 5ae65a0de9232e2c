#include "dda/common/polyhedron_model.hpp"

#include "dda/common/error.hpp"

namespace dda {

const char* to_string(Removability r) {
  switch (r) {
    case Removability::NotExposed: return "not_exposed";
    case Removability::Tapered: return "tapered";
    case Removability::Removable: return "removable";
    case Removability::Falls: return "falls";
    case Removability::SlidesOne: return "slides_one_face";
    case Removability::SlidesTwo: return "slides_two_faces";
  }
  return "unknown";
}

Removability removability_from_string(const std::string& word, const std::string& where) {
  for (int code = 0; code <= static_cast<int>(Removability::SlidesTwo); ++code) {
    const auto r = static_cast<Removability>(code);
    if (word == to_string(r)) return r;
  }
  throw InputError((where.empty() ? "" : where + ": ") + "unknown removability \"" + word +
                   "\", expected not_exposed, tapered, removable, falls, slides_one_face or "
                   "slides_two_faces.");
}

}  // namespace dda

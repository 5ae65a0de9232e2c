#include "results_points.hpp"

#include "dda/common/error.hpp"

namespace dda::cli {

std::size_t measurement_point_index(const std::vector<std::string>& names, const std::string& name,
                                    const std::string& path) {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return k;
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  throw InputError(path + ": has no measurement point '" + name + "' (its points are " +
                   (known.empty() ? "none" : known) + ").");
}

std::size_t measurement_point_index(const df::Results& r, const std::string& name, const std::string& path) {
  return measurement_point_index(r.point_names, name, path);
}

}  // namespace dda::cli

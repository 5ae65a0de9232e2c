#pragma once
// Measurement points of a results file by name (dda history, compare, spectra).
#include <string>
#include <vector>

#include "dda/df/io/results.hpp"

namespace dda::cli {

// Index of the point `name` in `r.point_names`; InputError naming `path` and
// listing the points the file has otherwise.
std::size_t measurement_point_index(const df::Results& r, const std::string& name, const std::string& path);
// The same over the point names of any results file (2D or 3D).
std::size_t measurement_point_index(const std::vector<std::string>& names, const std::string& name,
                                    const std::string& path);

}  // namespace dda::cli

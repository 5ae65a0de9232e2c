#pragma once
// Importers of 3D fractures made by other programs: FracMan .fab files and
// CSV polygons. Both give convex Polygon fractures (polygon_fracture in
// fractures3d.hpp: fitted upper-hemisphere normal, vertices counter-clockwise
// about it) and the names of their sets. Errors are InputErrors
// "file:line: ..." naming the line the problem is on (for a bad polygon, the
// line that starts it).
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"

namespace dda::dl {

struct ImportedFractures {
  std::vector<Fracture3> fractures;  // set = index into set_names
  std::vector<std::string> set_names;
  std::vector<int> lines;            // per fracture, the 1-based line of the file where it starts
};

// FracMan ASCII .fab: the sections
//   BEGIN FORMAT ... END FORMAT          key = value lines; Length_Unit M(eter)
//                                        or Ft/Feet (converted to metres)
//   BEGIN PROPERTIES ... END PROPERTIES  ignored
//   BEGIN SETS ... END SETS              SetK = "name" (K the set number)
//   BEGIN FRACTURE ... END FRACTURE      per fracture: "id nnodes set [properties...]",
//                                        nnodes lines "i x y z", then "0 nx ny nz"
// in any order; BEGIN TESSFRACTURE, BEGIN ROCKBLOCK and any other section are
// skipped to their END. Keywords are case-insensitive; blank lines are
// skipped. The normal line is checked to be numbers but the normal is fitted
// from the vertices. A set number without a SETS entry is named "set K".
ImportedFractures read_fab(const std::string& path);

// CSV polygons: a header naming the columns fracture, set, x, y, z (any
// order, any case), then one row per vertex; the rows of one fracture are
// consecutive and name one set; the fracture and set are names (any text).
// Fields separated by commas, semicolons or blanks; blank lines and lines
// starting with '#' skipped.
ImportedFractures read_fracture_csv(const std::string& path);

}  // namespace dda::dl

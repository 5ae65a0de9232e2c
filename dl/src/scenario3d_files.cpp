// Section `fracture_files`: FracMan .fab files and CSV polygons.
#include <cctype>
#include <filesystem>

#include "builder.hpp"
#include "dda/common/scenario.hpp"
#include "dda/dl/fractures3d.hpp"
#include "dda/dl/import3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

void read_fracture_files3(const YamlNode& root, Builder3& b) {
  nlohmann::json rep = nlohmann::json::array();
  for (const YamlNode& n : root.list_or_empty("fracture_files")) {
    n.allow({"file", "set_prefix"});
    const std::string file = n.text("file");
    const std::string prefix = n.text("set_prefix", "");
    const std::string ext = lower_extension(file);
    if (ext != ".fab" && ext != ".csv")
      n.fail_key("file", "must name a FracMan .fab file or a .csv file of polygons, got '" + file + "'");
    ImportedFractures imported;
    try {
      const std::string path = resolve_scenario_path(n, file);
      imported = ext == ".fab" ? read_fab(path) : read_fracture_csv(path);
    } catch (const InputError& e) {
      fail_from(n, "file", "names a fracture file with an error", e);
    }
    // The file's sets become sets of the model, after all the generated ones.
    std::vector<int> set_of;
    for (const std::string& name : imported.set_names) {
      const std::string full = prefix + name;
      for (const JointSetInfo& s : b.model.sets)
        if (s.name == full)
          n.fail_key(prefix.empty() ? "file" : "set_prefix",
                     "brings the set '" + full + "', already the name of another set (" + s.origin +
                         "); give the file a set_prefix that makes its names new");
      set_of.push_back(b.add_new_set(full, ext.substr(1), n, "file"));
    }
    std::size_t kept = 0;
    for (Fracture3& f : imported.fractures) {
      f.centre = b.local(f.centre);  // files hold the user's coordinates
      for (Vec3& v : f.vertices) v = b.local(v);
      if (!(fracture_area_in_box(f, b.model.domain) > 0)) continue;  // DC would ignore it
      f.set = set_of[static_cast<std::size_t>(f.set)];
      b.model.fractures.push_back(std::move(f));
      ++kept;
    }
    nlohmann::json names = nlohmann::json::array();
    for (const std::string& s : imported.set_names) names.push_back(prefix + s);
    rep.push_back({{"file", file},
                   {"fractures", imported.fractures.size()},
                   {"in_domain", kept},
                   {"outside_domain", imported.fractures.size() - kept},
                   {"sets", names}});
  }
  b.report["fracture_files"] = rep;
}

}  // namespace dda::dl::detail

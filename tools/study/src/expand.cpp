#include "dda/study/expand.hpp"

#include "dda/common/error.hpp"
#include "dda/study/number_text.hpp"

namespace dda::study {

std::string case_id(std::size_t index, std::size_t count) {
  std::string digits = std::to_string(index);
  const std::size_t width = std::max<std::size_t>(4, std::to_string(count > 0 ? count - 1 : 0).size());
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return "c" + digits;
}

namespace {

void set_or_fail(const Case& c, YAML::Node doc, const KeyPath& path, const YAML::Node& value) {
  const std::string missing = set_at(doc, path, value);
  if (!missing.empty()) throw InputError("case " + c.id + ": " + path.text + ": " + missing + ".");
}

double number_at(const Case& c, const YAML::Node& doc, const KeyPath& path) {
  const auto node = get_at(doc, path);
  try {
    if (node) return node->as<double>();
  } catch (const YAML::Exception&) {
  }
  throw InputError("case " + c.id + ": " + path.text + " is no number to scatter.");
}

}  // namespace

Case make_case(const Study& study, std::size_t index) {
  const std::size_t seeds = std::max<std::size_t>(1, study.seeds.size());
  Case c;
  c.index = index;
  c.id = case_id(index, study.case_count());
  c.doc = YAML::Clone(study.base);
  const std::size_t draw = index % study.draws;
  const std::size_t seed_index = (index / study.draws) % seeds;
  std::size_t grid = index / study.draws / seeds;
  // The grid point's value of each key: the last key varies fastest.
  std::vector<std::size_t> pick(study.vary.size());
  for (std::size_t k = study.vary.size(); k-- > 0;) {
    pick[k] = grid % study.vary[k].values.size();
    grid /= study.vary[k].values.size();
  }
  for (std::size_t k = 0; k < study.vary.size(); ++k) {
    const VariedKey& v = study.vary[k];
    for (std::size_t p = 0; p < v.paths.size(); ++p) {
      set_or_fail(c, c.doc, v.paths[p], v.values[pick[k]][p]);
      c.values.push_back(v.texts[pick[k]][p]);
    }
  }
  if (!study.seeds.empty()) {
    c.seed = study.seeds[seed_index];
    c.doc["seed"] = *c.seed;
  }
  if (!study.sampled.empty() || !study.planes.empty()) {
    c.draw = draw;
    dl::Stream stream(study.sample_seed, "study.sample", draw);
    for (const SampledKey& s : study.sampled) {
      const std::string text = round_trip(s.law.draw(stream));
      set_or_fail(c, c.doc, s.path, YAML::Node(text));
      c.values.push_back(text);
    }
    for (const SampledPlane& p : study.planes) {
      analysis::Plane mean;
      mean.dip_deg = number_at(c, c.doc, p.dip);
      mean.dip_direction_deg = number_at(c, c.doc, p.dip_direction);
      const analysis::Plane drawn = fisher_draw(mean, p.kappa, stream);
      const std::string dip = round_trip(drawn.dip_deg), dd = round_trip(drawn.dip_direction_deg);
      set_or_fail(c, c.doc, p.dip, YAML::Node(dip));
      set_or_fail(c, c.doc, p.dip_direction, YAML::Node(dd));
      c.values.push_back(dip);
      c.values.push_back(dd);
    }
  }
  return c;
}

}  // namespace dda::study

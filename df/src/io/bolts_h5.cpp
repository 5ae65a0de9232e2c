// Rock-bolt histories in the results files (bolts_h5.hpp).
#include "io/bolts_h5.hpp"

namespace dda::df::h5io {

void write_bolt_series(h5::Writer& w, const std::vector<std::string>& names,
                       const std::vector<std::vector<BoltSample>>& histories, const std::string& force_what) {
  h5::Id g = w.group("bolts");
  w.attr_text(g.get(), "description", "rock bolt series: sample 0 is the start of the run, then one per step");
  w.strings(g.get(), "name", names, "", "bolt names, in the order of the columns");
  const std::size_t nb = histories.size();
  const std::size_t ns = nb ? histories[0].size() : 0;
  std::vector<double> time, force, length;
  std::vector<std::int32_t> broken;
  for (std::size_t s = 0; s < ns; ++s) {
    time.push_back(histories[0][s].time);
    for (std::size_t b = 0; b < nb; ++b) {
      force.push_back(histories[b][s].force);
      length.push_back(histories[b][s].length);
      broken.push_back(histories[b][s].broken ? 1 : 0);
    }
  }
  w.f64(g.get(), "time", time, {ns}, "s", "time of each sample");
  w.f64(g.get(), "force", force, {ns, nb}, "N", force_what);
  w.f64(g.get(), "length", length, {ns, nb}, "m", "current length");
  w.i32(g.get(), "broken", broken, "", "1 once the bolt has broken; row-major (samples, bolts)");
}

void read_bolt_series(const h5::Reader& r, std::vector<std::string>& names,
                      std::vector<std::vector<BoltSample>>& histories) {
  names = r.strings("/bolts/name");
  const std::size_t nb = names.size();
  const std::size_t ns = length(r, "/bolts/time");
  const auto time = read_f64(r, "/bolts/time", {ns});
  const auto force = read_f64(r, "/bolts/force", {ns, nb});
  const auto len = read_f64(r, "/bolts/length", {ns, nb});
  const auto broken = read_i64(r, "/bolts/broken", ns * nb);
  histories.assign(nb, std::vector<BoltSample>(ns));
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t b = 0; b < nb; ++b)
      histories[b][s] = {time[s], force[s * nb + b], len[s * nb + b], broken[s * nb + b] != 0};
}

}  // namespace dda::df::h5io

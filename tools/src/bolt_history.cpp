// Rock-bolt histories for `dda history` (bolt_history.hpp).
#include "bolt_history.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace dda::cli {

namespace {

void put(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

std::string bolt_summary(const std::vector<std::string>& names, const std::vector<std::vector<df::BoltSample>>& h) {
  if (names.empty() || h.empty() || h[0].empty()) return "";
  std::string out = "bolt            force (N)    length (m)  max force (N)  broken at t (s)\n";
  for (std::size_t b = 0; b < names.size(); ++b) {
    double most = h[b].front().force;
    std::string broke = "-";
    for (const df::BoltSample& s : h[b]) {
      most = std::max(most, s.force);
      if (s.broken && broke == "-") {
        char t[32];
        std::snprintf(t, sizeof t, "%g", s.time);
        broke = t;
      }
    }
    char line[200];
    std::snprintf(line, sizeof line, "%-14s %11.6g %13.6g %14.6g  %s\n", names[b].c_str(), h[b].back().force,
                  h[b].back().length, most, broke.c_str());
    out += line;
  }
  return out;
}

std::string bolts_csv(const std::vector<std::string>& names, const std::vector<std::vector<df::BoltSample>>& h) {
  std::string out = "t";
  for (const std::string& n : names)
    for (const char* c : {"force", "length", "broken"}) out += "," + n + "." + c;
  out += "\n";
  const std::size_t ns = h.empty() ? 0 : h[0].size();
  for (std::size_t s = 0; s < ns; ++s) {
    put(out, h[0][s].time);
    for (const auto& bolt : h) {
      out += ',';
      put(out, bolt[s].force);
      out += ',';
      put(out, bolt[s].length);
      out += bolt[s].broken ? ",1" : ",0";
    }
    out += "\n";
  }
  return out;
}

}  // namespace dda::cli

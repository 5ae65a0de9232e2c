#include "dda/study/summary.hpp"

#include <cmath>
#include <limits>

#include "dda/common/atomic_file.hpp"
#include "dda/common/h5_util.hpp"
#include "dda/common/provenance.hpp"
#include "dda/study/number_text.hpp"

namespace dda::study {

nlohmann::json record_json(const CaseRecord& r) {
  nlohmann::json measures = nlohmann::json::array();
  for (double v : r.measures) measures.push_back(std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v));
  return {{"status", r.ok ? "ok" : "failed"}, {"seconds", r.seconds}, {"error", r.error}, {"measures", measures}};
}

std::optional<CaseRecord> record_from_json(const nlohmann::json& j, std::size_t measures) {
  try {
    CaseRecord r;
    r.ok = j.at("status").get<std::string>() == "ok";
    r.seconds = j.at("seconds").get<double>();
    r.error = j.at("error").get<std::string>();
    const auto& m = j.at("measures");
    // A failed case has no values; a finished one has one per measure.
    if (!m.is_array() || m.size() != (r.ok ? measures : 0)) return std::nullopt;
    for (const auto& v : m) r.measures.push_back(v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>());
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

std::vector<std::string> summary_header(const Study& study) {
  std::vector<std::string> h{"case", "seed", "draw"};
  for (const std::string& c : study.value_columns()) h.push_back(c);
  for (const MeasureSpec& m : study.measures) h.push_back(m.name);
  if (study.failure) h.push_back("failed");
  for (const char* c : {"status", "seconds", "error"}) h.push_back(c);
  return h;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// Whether case i failed by the study's rule: 1, 0, or "" when the case has
// no value of that measure.
std::string failed_cell(const Study& study, const CaseRecord& r) {
  for (std::size_t k = 0; k < study.measures.size(); ++k)
    if (study.measures[k].name == study.failure->measure) {
      if (!r.ok || k >= r.measures.size() || std::isnan(r.measures[k])) return "";
      return study.failure->failed(r.measures[k]) ? "1" : "0";
    }
  return "";
}

std::vector<std::string> row(const Study& study, const Case& c, const CaseRecord& r) {
  std::vector<std::string> cells{c.id, c.seed ? std::to_string(*c.seed) : "", c.draw ? std::to_string(*c.draw) : ""};
  cells.insert(cells.end(), c.values.begin(), c.values.end());
  for (std::size_t k = 0; k < study.measures.size(); ++k)
    cells.push_back(r.ok && k < r.measures.size() ? round_trip(r.measures[k]) : "");
  if (study.failure) cells.push_back(failed_cell(study, r));
  cells.push_back(r.ok ? "ok" : "failed");
  cells.push_back(round_trip(r.seconds));
  cells.push_back(r.error);
  return cells;
}

}  // namespace

std::string summary_csv(const Study& study, const std::vector<Case>& cases, const std::vector<CaseRecord>& records) {
  std::string out;
  const auto line = [&out](const std::vector<std::string>& cells) {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (k) out += ',';
      out += csv_field(cells[k]);
    }
    out += "\n";
  };
  line(summary_header(study));
  for (std::size_t i = 0; i < cases.size(); ++i) line(row(study, cases[i], records[i]));
  return out;
}

void write_summary_csv(const std::string& path, const Study& study, const std::vector<Case>& cases,
                       const std::vector<CaseRecord>& records) {
  write_text_atomically(path, summary_csv(study, cases, records));
}

void write_study_h5(const std::string& path, const Study& study, const std::vector<Case>& cases,
                    const std::vector<CaseRecord>& records) {
  AtomicOutput out(path);
  {
    h5::Writer w(path, out.temp_path());
    w.attr_text(w.file(), "format", "dda-study");
    w.attr_text(w.file(), "version", version_string());
    w.attr_text(w.file(), "study_file", study.file);
    w.attr_text(w.file(), "study_text", study.text);
    w.attr_text(w.file(), "case_kind", study.kind == CaseKind::wedge ? "wedge" : "pipeline");
    h5::Id g = w.group("cases");
    std::vector<std::string> ids, status, errors;
    std::vector<std::int64_t> seeds, draws;
    std::vector<double> seconds;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      ids.push_back(cases[i].id);
      seeds.push_back(cases[i].seed ? static_cast<std::int64_t>(*cases[i].seed) : -1);
      draws.push_back(cases[i].draw ? static_cast<std::int64_t>(*cases[i].draw) : -1);
      status.push_back(records[i].ok ? "ok" : "failed");
      errors.push_back(records[i].error);
      seconds.push_back(records[i].seconds);
    }
    w.strings(g.get(), "id", ids, "", "case id, as its folder is named");
    w.i64(g.get(), "seed", seeds, "", "the scenario seed of the case; -1 when the study sets none");
    w.i64(g.get(), "draw", draws, "", "the Monte Carlo draw of the case; -1 when the study samples nothing");
    w.strings(g.get(), "status", status, "", "ok or failed");
    w.strings(g.get(), "error", errors, "", "the error of a failed case");
    w.f64(g.get(), "seconds", seconds, {seconds.size()}, "s", "wall time of the case");
    h5::Id values = w.group("values");
    const std::vector<std::string> columns = study.value_columns();
    for (std::size_t k = 0; k < columns.size(); ++k) {
      std::vector<std::string> column;
      for (const Case& c : cases) column.push_back(c.values[k]);
      w.strings(values.get(), columns[k], column, "", "the case's value of this key path, as text");
    }
    h5::Id measures = w.group("measures");
    for (std::size_t k = 0; k < study.measures.size(); ++k) {
      std::vector<double> column;
      for (const CaseRecord& r : records)
        column.push_back(r.ok && k < r.measures.size() ? r.measures[k] : std::numeric_limits<double>::quiet_NaN());
      w.f64(measures.get(), study.measures[k].name, column, {column.size()}, "",
            "measure '" + study.measures[k].kind + "' of each case; NaN where there is none");
    }
    w.close();
  }
  out.commit();
}

}  // namespace dda::study

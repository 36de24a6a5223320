// `eccd report --merge` (app/report_parts.hpp): joins the parts written by
// `--shard i/n` runs into one report, after checking that they belong together.
#include "app/report_parts.hpp"
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/option_names.hpp"
#include "app/scene_files.hpp"
#include "app/time_left.hpp"
#include "compare/csv.hpp"
#include "compare/harness.hpp"
#include "compare/harness_families.hpp"
#include "compare/scene_generator.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <regex>
#include <thread>

namespace fs = std::filesystem;

namespace eccd::report_detail {

// A file of a part, read whole (merge validation needs the exact bytes).
std::string read_part_file(const fs::path& p, bool required) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) {
    if (!required) return {};
    throw std::invalid_argument(p.string() + ": missing (not an `eccd report --shard` part)");
  }
  try {  // a regular file of bounded size only: never a FIFO (blocks), /dev/zero (balloons)
    return read_bounded_file(p.string(), kMaxReportFileBytes, "the limit of a report's own file");
  } catch (const SceneError& e) {
    throw std::invalid_argument(e.what());
  }
}

// Strict "i/n": digits only, 0 <= i < n <= 100000.
std::pair<int, int> parse_shard_text(const std::string& t, const std::string& where) {
  auto bad = [&]() -> std::pair<int, int> {
    throw std::invalid_argument(where + ": shard \"" + t.substr(0, 40) + "\" is not i/n with 0 <= i < n");
  };
  auto slash = t.find('/');
  if (slash == std::string::npos) return bad();
  auto num = [&](const std::string& d) {
    if (d.empty() || d.size() > 6 || d.find_first_not_of("0123456789") != std::string::npos) bad();
    return std::stoi(d);
  };
  int i = num(t.substr(0, slash)), n = num(t.substr(slash + 1));
  if (n < 1 || n > 100000 || i >= n) return bad();
  return {i, n};
}

// The records of a CSV part after its header (compare/csv.hpp reads them, quoting
// and all), each written back as csv_line writes it; a truncated last line, bad
// quoting or a row with the wrong number of fields is an error naming the file
// and the line.
std::vector<std::string> csv_rows(const std::string& text, const std::string& header, const fs::path& file) {
  if (!text.empty() && text.back() != '\n')
    throw std::invalid_argument(file.string() + ": truncated (the last line is incomplete)");
  std::vector<CsvRecord> recs = csv_records(text, file.string());
  std::vector<std::string> head = csv_split(header);
  if (recs.empty() || recs[0].fields != head)
    throw std::invalid_argument(file.string() + ": line 1: not the expected header");
  std::vector<std::string> rows;
  for (std::size_t k = 1; k < recs.size(); ++k) {
    if (recs[k].fields.size() != head.size())
      throw std::invalid_argument(file.string() + ": line " + std::to_string(recs[k].line) + ": " +
                                  std::to_string(recs[k].fields.size()) + " fields, expected " +
                                  std::to_string(head.size()) + " (truncated or edited?)");
    rows.push_back(csv_line(recs[k].fields));
  }
  return rows;
}

// What run_merge has read of the parts so far.
struct MergedParts {
  std::vector<std::string> rows, cells;
  nlohmann::json meta;
  std::vector<std::string> seen;                                           // part folder per shard index
  std::vector<std::pair<fs::path, nlohmann::ordered_json>> scene_indexes;  // each part's scenes/index.json
  double wall = 0;
};

// Reads and checks the part in `dir` (its meta.json against the first part's, its shard not given twice, its
// CSVs' row counts) and adds it to `parts`; std::invalid_argument (exit 2) names the file and what is wrong.
void read_part(const ReportArgs& a, const std::string& dir, const std::string& header, const std::string& map_header,
               MergedParts& parts) {
  auto& [rows, cells, meta, seen, scene_indexes, wall] = parts;
  fs::path d(dir);
  const fs::path mp = d / "meta.json";
  std::error_code ec;
  if (!fs::is_directory(d, ec)) throw std::invalid_argument(dir + ": not a folder (an `eccd report --shard` part)");
  std::string mtext = read_part_file(mp, true);
  nlohmann::json m;
  try {  // nesting bounded (io/scene_reader.hpp): 100 000 '[' are refused at the 65th
    m = parse_json_document(mtext, mp.string());
  } catch (const SceneError& e) {
    throw std::invalid_argument(std::string(e.what()) + " (a report's meta.json; truncated?)");
  }
  if (!m.is_object()) throw std::invalid_argument(mp.string() + ": not a report's meta.json (expected a JSON object)");
  const nlohmann::json& shards = m["shards"];
  if (!shards.is_number_unsigned() || shards.get<std::uint64_t>() < 1 || shards.get<std::uint64_t>() > 100000)
    throw std::invalid_argument(mp.string() + ": /shards: expected a positive integer");
  int n = shards.get<int>(), i = 0;
  if (m["shard"].is_string()) {
    auto [si, sn] = parse_shard_text(m["shard"].get<std::string>(), mp.string() + ": /shard");
    if (sn != n)
      throw std::invalid_argument(mp.string() + ": /shard says " + std::to_string(sn) + " shards but /shards is " +
                                  std::to_string(n));
    i = si;
  } else if (!m["shard"].is_null() || n != 1) {
    throw std::invalid_argument(mp.string() + ": /shard: expected \"i/n\"");
  }
  if (!m["command"].is_string()) throw std::invalid_argument(mp.string() + ": /command: expected a string");
  if (!m["wall_seconds"].is_number()) throw std::invalid_argument(mp.string() + ": /wall_seconds: expected a number");
  if (meta.is_null()) {
    meta = m;
    seen.assign(std::size_t(n), "");
  } else {
    for (const char* k : {"seed", "mpfr_bits", "degrees", "dims", "families", "separations", "count_per_combination",
                          "grid", "shards", "failure_map"})
      if (m[k] != meta[k])
        throw std::invalid_argument(dir + ": was run with a different " + std::string(k) + " than " + a.merge[0]);
  }
  if (!seen[std::size_t(i)].empty())
    throw std::invalid_argument(dir + ": shard " + std::to_string(i) + "/" + std::to_string(n) + " given twice (also " +
                                seen[std::size_t(i)] + ")");
  seen[std::size_t(i)] = dir;
  wall += m["wall_seconds"].get<double>();
  const fs::path rp = d / "results.csv";
  std::vector<std::string> r = csv_rows(read_part_file(rp, true), header, rp);
  if (m.contains("result_rows") &&
      (!m["result_rows"].is_number_unsigned() || m["result_rows"].get<std::uint64_t>() != r.size()))
    throw std::invalid_argument(rp.string() + ": " + std::to_string(r.size()) + " row(s), but " + mp.string() +
                                " says " + m["result_rows"].dump() + " (truncated?)");
  rows.insert(rows.end(), r.begin(), r.end());
  scene_indexes.emplace_back(d, read_scene_index(d / "scenes" / "index.json"));
  const fs::path fp = d / "failure_map.csv";
  std::string ftext = read_part_file(fp, !m["failure_map"].is_null());
  if (!ftext.empty() || !m["failure_map"].is_null()) {
    std::vector<std::string> c = csv_rows(ftext, map_header, fp);
    if (m.contains("map_rows") &&
        (!m["map_rows"].is_number_unsigned() || m["map_rows"].get<std::uint64_t>() != c.size()))
      throw std::invalid_argument(fp.string() + ": " + std::to_string(c.size()) + " row(s), but " + mp.string() +
                                  " says " + m["map_rows"].dump() + " (truncated?)");
    cells.insert(cells.end(), c.begin(), c.end());
  }
}

int run_merge(const ReportArgs& a) {
  if (a.merge.size() < 1) throw std::invalid_argument("--merge needs the part folders");
  if (a.resume)
    throw std::invalid_argument("--resume: not with --merge (a merge only joins finished parts: run it again)");
  std::string name;
  fs::path out = output_folder(a, "", name);
  fs::path partial = out;
  partial += ".partial";
  check_replaceable(out, kMarker, looks_like_old_report);
  check_replaceable(partial, kMarker);
  for (const auto& dir : a.merge) {  // the output replaces OUT: never one of the parts it reads
    std::error_code ec;
    for (const fs::path& o : {out, partial})
      if (fs::exists(o, ec) && fs::equivalent(o, fs::path(dir), ec))
        throw OutputError(o.string() + ": refusing to write the merged report there: it is the part " + dir +
                          " given to --merge (choose another --name or --out)");
  }
  MergedParts parts;
  std::string header = results_csv_header();
  const std::string map_header = "pipeline,ix,iy,dx_ulps,dy_ulps,answer,exact";
  for (const auto& dir : a.merge) read_part(a, dir, header, map_header, parts);
  auto& [rows, cells, meta, seen, scene_indexes, wall] = parts;
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (seen[i].empty())
      throw std::invalid_argument("--merge: shard " + std::to_string(i) + "/" + std::to_string(seen.size()) +
                                  " is missing");
  if (!meta["failure_map"].is_null() &&
      (!meta["failure_map"].is_object() || !meta["failure_map"]["pipelines"].is_array() ||
       !std::all_of(meta["failure_map"]["pipelines"].begin(), meta["failure_map"]["pipelines"].end(),
                    [](const nlohmann::json& x) { return x.is_string(); })))
    throw std::invalid_argument((fs::path(a.merge[0]) / "meta.json").string() +
                                ": /failure_map/pipelines: expected an array of strings");
  for (const auto& c : cells) {  // sort_map reads ix and iy as integers
    auto f = csv_split(c, "failure_map.csv row");
    for (int k : {1, 2})
      if (f[std::size_t(k)].empty() || f[std::size_t(k)].size() > 6 ||
          f[std::size_t(k)].find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument("--merge: failure_map.csv row \"" + c.substr(0, 80) +
                                    "\": ix and iy must be small non-negative integers");
  }
  sort_results(rows);
  InterruptGuard guard;  // a merge is quick and not resumable: interrupted, its partial output is removed
  auto interrupted = [&]() {
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw Interrupted("interrupted by " + signal_name() + ": " + partial.string() + " removed (run the merge again)");
  };
  start_partial(partial, out);
  std::string csv = header + "\n";
  for (auto& r : rows) csv += r + "\n";
  write_file(partial / "results.csv", csv);
  if (!cells.empty()) {
    sort_map(cells, meta["failure_map"]["pipelines"].get<std::vector<std::string>>());
    std::string m = "pipeline,ix,iy,dx_ulps,dy_ulps,answer,exact\n";
    for (auto& c : cells) m += c + "\n";
    write_file(partial / "failure_map.csv", m);
  }
  stamp_format(meta, "eccd-report-meta/1");
  meta["name"] = name;
  meta["command"] = meta["command"].get<std::string>() + "  (parts joined by: " + command_line() + ")";
  meta["wall_seconds"] = wall;
  meta["shard"] = nullptr;
  meta["result_rows"] = rows.size();
  meta["no_ground_truth"] = no_ground_truth_meta(rows);
  meta["map_rows"] = cells.size();
  if (meta.contains("externals") && meta["externals"].is_array())
    meta["externals"] = externals_meta(meta["externals"], rows);
  if (meta.contains("fcl") && meta["fcl"].is_object() &&
      meta["pipelines"].is_array()) {  // the parts' counts, recounted over all rows
    meta["fcl"]["skipped"] = nlohmann::json::object();
    for (const auto& [label, n] : fcl_skipped(meta["pipelines"].get<std::vector<std::string>>(), rows))
      meta["fcl"]["skipped"][label] = n;
  }
  write_file(partial / "meta.json", meta.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  merge_scene_files(partial, out, scene_indexes);
  if (!a.no_figures) {
    try {
      if (meta["failure_map"].is_object() && meta["failure_map"]["scene"].is_string())
        write_map_picture(partial, meta["failure_map"]["scene"].get<std::string>());
      run_figures(partial);
    } catch (const std::exception&) {
      if (g_interrupted) interrupted();
      throw;
    }
  }
  if (g_interrupted) interrupted();
  finish_output(partial, out);
  if (!quiet()) std::fprintf(stderr, "eccd report: joined %zu part(s) into %s\n", a.merge.size(), out.string().c_str());
  std::cout << (out / (a.no_figures ? "results.csv" : "report.md")).string() << "\n";
  return 0;
}

}  // namespace eccd::report_detail

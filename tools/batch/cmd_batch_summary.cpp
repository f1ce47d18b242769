// meshdiff batch-summary: merges the JSON-lines outputs of batch runs (shards,
// resumed runs) into one flat CSV, one row per pair, and lists the pairs that
// failed or are missing.
#include "batch_list.h"
#include "cli.h"
#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/html.h"
#include "options.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace meshdiff::cli {

namespace {

struct SummaryArgs
{
    std::vector<std::string> inputs;
    std::string csv;
    std::string html;
    std::string pairs;
    bool quiet = false;
};

// The record kept per id: the last ok line, else the last line.
struct Record
{
    nlohmann::json line;
    bool ok = false;
};

// Reads the batch records of one JSON-lines file into \p records (in the order
// of first appearance, \p order). A last line without its newline (a killed
// run's torn record) is skipped with a warning; any other line that is not a
// batch record is an error naming the file and line.
void read_records(const std::string& path, std::map<std::string, Record>& records, std::vector<std::string>& order)
{
    if (std::filesystem::is_directory(path)) throw IoError(fmt::format("{}: is a directory, not a batch output", path));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(fmt::format("{}: cannot open the batch output", path));
    std::stringstream buf;
    buf << in.rdbuf();
    std::string text = buf.str();
    if (!text.empty() && text.back() != '\n') {
        const auto keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
        std::cerr << fmt::format("batch-summary: {}: skipped a torn last line (a killed run's record)\n", path);
        text.resize(keep);
    }
    std::size_t lineno = 0, start = 0;
    while (start < text.size()) {
        const auto end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        start = end + 1;
        ++lineno;
        if (line.empty() || line == "\r") continue;
        auto j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_discarded() || !j.is_object() || !j.contains("id") || !j["id"].is_string() || !j.contains("status") ||
            !j["status"].is_string())
            throw IoError(fmt::format("{}:{}: not a meshdiff batch record", path, lineno));
        const std::string id = j["id"].get<std::string>();
        const bool ok = j["status"] == "ok";
        if (ok && !(j.contains("result") && j["result"].is_object()))
            throw IoError(fmt::format("{}:{}: an ok record without its result object", path, lineno));
        auto [it, fresh] = records.try_emplace(id);
        if (fresh) order.push_back(id);
        if (ok || !it->second.ok) it->second = {std::move(j), ok};  // the last ok line wins
    }
}

// One CSV row: column name -> cell text; the column order is the order of
// first appearance over all rows.
class Table
{
public:
    void set(std::size_t row, const std::string& column, std::string value)
    {
        if (rows_.size() <= row) rows_.resize(row + 1);
        if (index_.emplace(column, columns_.size()).second) columns_.push_back(column);
        rows_[row][column] = std::move(value);
    }

    void write(std::ostream& out) const
    {
        for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << quote(columns_[c]);
        out << "\n";
        for (const auto& row : rows_) {
            for (std::size_t c = 0; c < columns_.size(); ++c) {
                const auto it = row.find(columns_[c]);
                out << (c ? "," : "") << (it == row.end() ? "" : quote(it->second));
            }
            out << "\n";
        }
    }

private:
    static std::string quote(const std::string& s)
    {
        if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
        std::string q = "\"";
        for (const char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        return q + "\"";
    }

    std::vector<std::string> columns_;
    std::map<std::string, std::size_t> index_;
    std::vector<std::map<std::string, std::string>> rows_;
};

// A JSON scalar as a CSV cell: numbers in their shortest round-trip form,
// booleans as true/false, null as an empty cell.
std::string cell(const nlohmann::json& v)
{
    if (v.is_null()) return "";
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

// The scalars under \p j, one column each, named by their path joined with
// '_' (below \p prefix); strings only for the Hausdorff method and where it
// is attained, the distance kind of each direction (point clouds), and the
// reasons of *_unavailable fields. Lists of numbers
// (histograms, coordinates) and the sampling settings are left out; a list of objects with a "threshold" (the
// F-scores) gives one group of columns per threshold.
void flatten(Table& t, std::size_t row, const std::string& prefix, const nlohmann::json& j)
{
    static const std::set<std::string> skipped = {"location", "sampling", "formula"};
    for (auto it = j.begin(); it != j.end(); ++it) {
        const std::string name = prefix.empty() ? it.key() : prefix + "_" + it.key();
        const nlohmann::json& v = it.value();
        if (skipped.count(it.key())) continue;
        if (v.is_object()) {
            flatten(t, row, name, v);
        } else if (v.is_array()) {
            for (const auto& e : v)
                if (e.is_object() && e.contains("threshold") && e["threshold"].is_number()) {
                    nlohmann::json rest = e;
                    rest.erase("threshold");
                    flatten(t, row, fmt::format("{}_{}", name, cell(e["threshold"])), rest);
                }
        } else if (!v.is_string() || name.find("hausdorff_method") != std::string::npos ||
                   name.find("hausdorff_attained") != std::string::npos ||
                   name.find("distance_kind") != std::string::npos ||
                   (name.size() > 12 && name.compare(name.size() - 12, 12, "_unavailable") == 0)) {
            t.set(row, name, cell(v));
        }
    }
}

// d_L and the relative change per ring level and per radius, and the global ones.
void roughness_columns(Table& t, std::size_t row, const nlohmann::json& rd)
{
    auto per = [&](const char* key, const char* dist, const char* rel, const char* tag) {
        if (!rd.contains(key) || !rd[key].is_array()) return;
        const auto& keys = rd[key];
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const std::string label = fmt::format("{}{}", tag, cell(keys[i]));
            if (rd.contains(dist) && i < rd[dist].size()) t.set(row, "d_" + label, cell(rd[dist][i]));
            if (rd.contains(rel) && i < rd[rel].size()) t.set(row, "relative_change_" + label, cell(rd[rel][i]));
        }
    };
    per("levels", "distance", "relative_change", "L");
    if (rd.contains("global") && rd["global"].is_object()) {
        t.set(row, "d_global", cell(rd["global"].value("distance", nlohmann::json())));
        t.set(row, "relative_change_global", cell(rd["global"].value("relative_change", nlohmann::json())));
    }
    per("radii", "distance_radii", "relative_change_radii", "r");
}

void mesh_columns(Table& t, std::size_t row, const char* side, const nlohmann::json& result)
{
    if (!result.contains(side) || !result[side].is_object()) return;
    const auto& p = result[side];
    if (p.contains("mesh") && p["mesh"].is_object()) {
        for (const char* k : {"vertices", "faces"})
            if (p["mesh"].contains(k)) t.set(row, fmt::format("{}_{}", side, k), cell(p["mesh"][k]));
    }
    if (p.contains("sigma_global")) t.set(row, fmt::format("{}_sigma_global", side), cell(p["sigma_global"]));
}

int run_summary(const SummaryArgs& a)
{
    std::vector<std::string> inputs_and_pairs = a.inputs;
    if (!a.pairs.empty()) inputs_and_pairs.push_back(a.pairs);
    if (!a.csv.empty()) refuse_overwriting_inputs("--csv", a.csv, inputs_and_pairs);
    if (!a.html.empty()) {
        if (a.html == "-") throw OptionError("--html", "is a file: '-' (standard output) is not offered");
        refuse_overwriting_inputs("--html", a.html, inputs_and_pairs);
        if (!a.csv.empty() && (a.csv == a.html || same_file(a.csv, a.html)))
            throw OptionError("--html", "is the --csv file too");
    }
    std::map<std::string, Record> records;
    std::vector<std::string> order;
    for (const auto& path : a.inputs) read_records(path, records, order);

    std::vector<std::string> ids;  // the rows, in order
    std::set<std::string> listed;
    if (!a.pairs.empty()) {
        for (const Pair& p : read_pairs(a.pairs)) {
            ids.push_back(p.id);
            listed.insert(p.id);
        }
        std::size_t extra = 0;
        for (const auto& id : order)
            if (!listed.count(id)) ++extra;
        if (extra)
            std::cerr << fmt::format(
                "batch-summary: {} record id(s) not in {} are left out (first: '{}')\n", extra, a.pairs,
                *std::find_if(order.begin(), order.end(), [&](const std::string& id) { return !listed.count(id); }));
    } else {
        ids = order;
    }

    Table table;
    nlohmann::json merged = nlohmann::json::array();  // the page's records, one per row
    std::size_t ok = 0, failed = 0, missing = 0;
    std::vector<std::string> problems;
    for (std::size_t row = 0; row < ids.size(); ++row) {
        const std::string& id = ids[row];
        table.set(row, "id", id);
        const auto it = records.find(id);
        if (it == records.end()) {
            ++missing;
            table.set(row, "status", "missing");
            merged.push_back({{"id", id}, {"status", "missing"}});
            problems.push_back(fmt::format("missing: {}", id));
            continue;
        }
        const nlohmann::json& j = it->second.line;
        merged.push_back(j);
        table.set(row, "status", j["status"].get<std::string>());
        for (const char* k : {"original", "processed", "exit_code", "error", "elapsed_seconds", "meshdiff_version"})
            table.set(row, k, j.contains(k) ? cell(j[k]) : "");
        if (!it->second.ok) {
            ++failed;
            problems.push_back(fmt::format("failed: {}: {}", id, j.contains("error") ? cell(j["error"]) : "?"));
            continue;
        }
        ++ok;
        const nlohmann::json& r = j["result"];
        mesh_columns(table, row, "original", r);
        mesh_columns(table, row, "processed", r);
        if (r.contains("surface_distance") && r["surface_distance"].is_object()) {
            const nlohmann::json& sd = r["surface_distance"];
            // The headline columns first: the Hausdorff distance (the certified
            // upper bound, or the sampled maximum), the means and RMS.
            const bool certified = sd.contains("hausdorff") && sd["hausdorff"].is_object() &&
                                   sd["hausdorff"].value("method", "") == "certified";
            table.set(row, "hausdorff",
                      certified ? cell(sd["hausdorff"].value("upper", nlohmann::json()))
                                : cell(sd.value("sampled_hausdorff", nlohmann::json())));
            for (const char* dir : {"forward", "backward"})
                for (const char* k : {"mean", "rms"})
                    if (sd.contains(dir) && sd[dir].contains(k))
                        table.set(row, fmt::format("{}_{}", dir, k), cell(sd[dir][k]));
            flatten(table, row, "", sd);
        }
        if (r.contains("same_connectivity") && r["same_connectivity"].is_object())
            flatten(table, row, "same_connectivity", r["same_connectivity"]);
        if (r.contains("roughness_distance") && r["roughness_distance"].is_object())
            roughness_columns(table, row, r["roughness_distance"]);
    }

    if (!a.html.empty()) {
        SummaryHtmlOptions html;
        html.command = command_line();
        html.page_dir = std::filesystem::path(a.html).parent_path().string();
        write_html_file(a.html, batch_summary_html(merged, html));
    }
    if (!a.csv.empty())
        write_atomically(a.csv, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            if (!out) throw IoError(fmt::format("{}: cannot write", a.csv));
            table.write(out);
            out.flush();
            if (!out) throw IoError(fmt::format("{}: write failed", a.csv));
        });
    const std::string written = a.html.empty() ? a.csv : a.csv.empty() ? a.html : a.csv + " and " + a.html;
    if (!a.quiet) {
        constexpr std::size_t kShown = 20;
        for (std::size_t i = 0; i < problems.size() && i < kShown; ++i) std::cerr << problems[i] << "\n";
        if (problems.size() > kShown) std::cerr << fmt::format("... and {} more\n", problems.size() - kShown);
    }
    std::cerr << fmt::format("batch-summary: {} pairs: {} ok, {} failed, {} missing; {} written\n", ids.size(), ok,
                             failed, missing, written);
    return failed + missing ? kBatchFailures : kOk;
}

}  // namespace

void add_batch_summary_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<SummaryArgs>();
    auto* sub = app.add_subcommand("batch-summary",
                                   "merge batch outputs (shards, resumed runs) into one flat CSV, one row per pair, "
                                   "and/or one HTML page; list the pairs that failed or are missing (exit 6 if any)");
    sub->add_option("OUT", args->inputs, "JSON-lines outputs of meshdiff batch")->required();
    sub->add_option("--csv", args->csv, "the CSV to write (one row per pair; pandas.read_csv reads it as it is)");
    sub->add_option("--html", args->html,
                    "the summary page to write: one self-contained HTML file with a sortable table of every pair, "
                    "a plot per measure, and links to the pages of batch --html-dir");
    sub->add_option("--pairs", args->pairs,
                    "the pair list (PAIRS.csv) of the batch: rows follow it, and pairs without a record are "
                    "listed as missing");
    sub->add_flag("-q,--quiet", args->quiet, "do not list the failed and missing pairs (the summary line stays)");
    sub->callback([args, &action] {
        if (args->csv.empty() && args->html.empty()) throw CLI::RequiredError("--csv or --html");
        action = [args] { return run_summary(*args); };
    });
}

}  // namespace meshdiff::cli

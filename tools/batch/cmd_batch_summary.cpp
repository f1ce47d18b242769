// meshdiff batch-summary: merges the JSON-lines outputs of batch runs (shards,
// resumed runs) into one flat CSV, one row per pair, and lists the pairs that
// failed or are missing.
#include "batch_list.h"
#include "batch_records.h"
#include "cli.h"
#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/csv.h"
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
        const std::size_t keep = whole_lines_end(text);
        std::cerr << fmt::format("batch-summary: {}: skipped a torn last line (a killed run's record)\n", path);
        text.resize(keep);
    }
    for_each_record(text, text.size(), path, "", [&](BatchRecord&& r) {
        if (r.ok && !(r.json.contains("result") && r.json["result"].is_object()))
            throw IoError(fmt::format("{}:{}: an ok record without its result object", path, r.line));
        auto [it, fresh] = records.try_emplace(r.id);
        if (fresh) order.push_back(r.id);
        if (r.ok || !it->second.ok) it->second = {std::move(r.json), r.ok};  // the last ok line wins
    });
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

    CsvTable table;
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
            table.set(row, k, j.contains(k) ? csv_cell(j[k]) : "");
        if (!it->second.ok) {
            ++failed;
            problems.push_back(fmt::format("failed: {}: {}", id, j.contains("error") ? csv_cell(j["error"]) : "?"));
            continue;
        }
        ++ok;
        add_comparison_columns(table, row, j["result"]);
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

#include "cli.h"
#include "commands.h"
#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/report/json.h"
#include "options.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace meshdiff::cli {

namespace {

struct BatchArgs
{
    std::string pairs;
    std::string out;
    std::string shard = "0/1";
    CompareCliOptions compare;
    int threads = 0;
    bool quiet = false;
};

struct Pair
{
    std::size_t line = 0;
    std::string id, original, processed;
};

// Splits one CSV line; fields may be quoted with "" (a doubled quote inside
// a quoted field is a literal quote).
std::vector<std::string> split_csv(const std::string& line)
{
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted) {
            if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (ch == '"') {
                quoted = false;
            } else {
                fields.back() += ch;
            }
        } else if (ch == '"') {
            quoted = true;
        } else if (ch == ',') {
            fields.emplace_back();
        } else if (ch != '\r') {
            fields.back() += ch;
        }
    }
    for (auto& f : fields) {
        const auto b = f.find_first_not_of(" \t"), e = f.find_last_not_of(" \t");
        f = b == std::string::npos ? "" : f.substr(b, e - b + 1);
    }
    return fields;
}

std::vector<Pair> read_pairs(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw IoError(fmt::format("{}: cannot open the pair list", path));
    const auto base = std::filesystem::path(path).parent_path();
    auto resolve = [&](const std::string& p) {
        const std::filesystem::path fp(p);
        return fp.is_absolute() ? fp.string() : (base / fp).lexically_normal().string();
    };
    std::vector<Pair> pairs;
    std::string line;
    std::size_t lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        const auto fields = split_csv(line);
        if (fields.size() == 1 && fields[0].empty()) continue;
        if (!fields[0].empty() && fields[0][0] == '#') continue;
        if (lineno == 1 && fields[0] == "original") continue;  // header
        if (fields.size() < 2 || fields[0].empty() || fields[1].empty())
            throw InvalidArgumentError(
                fmt::format("{}:{}: expected 'original,processed[,id]', got '{}'", path, lineno, line));
        Pair p;
        p.line = lineno;
        p.original = resolve(fields[0]);
        p.processed = resolve(fields[1]);
        p.id = fields.size() > 2 && !fields[2].empty() ? fields[2] : fields[0] + " -> " + fields[1];
        pairs.push_back(std::move(p));
    }
    return pairs;
}

constexpr std::size_t kMaxShards = 1000000;

std::pair<std::size_t, std::size_t> parse_shard(const std::string& s)
{
    const auto slash = s.find('/');
    std::size_t i = 0, n = 0;
    try {
        if (slash == std::string::npos) throw std::invalid_argument("no slash");
        // Digits only: stoul would take "-1" as the largest unsigned number.
        if (s.find_first_not_of("0123456789/") != std::string::npos) throw std::invalid_argument("sign");
        std::size_t used = 0;
        i = std::stoul(s.substr(0, slash), &used);
        if (used != slash) throw std::invalid_argument("index");
        n = std::stoul(s.substr(slash + 1), &used);
        if (used != s.size() - slash - 1) throw std::invalid_argument("count");
    } catch (const std::exception&) {
        throw InvalidArgumentError(fmt::format("--shard: '{}' is not I/N (0 <= I < N)", s));
    }
    if (n == 0 || i >= n || n > kMaxShards)
        throw InvalidArgumentError(fmt::format("--shard: '{}' needs 0 <= I < N <= {}", s, kMaxShards));
    return {i, n};
}

int run_batch(const BatchArgs& a)
{
    set_threads(a.threads);
    refuse_overwriting_inputs("--out", a.out, {a.pairs});
    if (std::filesystem::is_directory(a.pairs))
        throw IoError(fmt::format("{}: is a directory, not a pair list", a.pairs));
    const auto [shard, n_shards] = parse_shard(a.shard);
    const CompareOptions options = to_compare_options(a.compare);
    const std::vector<Pair> pairs = read_pairs(a.pairs);

    // Resume: ids already recorded as done are skipped; errors are retried.
    std::set<std::string> done;
    {
        std::ifstream prev(a.out);
        std::string line;
        while (prev && std::getline(prev, line)) {
            const auto j = nlohmann::json::parse(line, nullptr, false);
            if (j.is_discarded() || !j.is_object()) continue;  // a torn last line from a killed run
            if (j.value("status", "") == "ok" && j.contains("id")) done.insert(j["id"].get<std::string>());
        }
    }
    std::ofstream out(a.out, std::ios::app);
    if (!out) throw IoError(fmt::format("{}: cannot open for appending", a.out));

    std::size_t ok = 0, failed = 0, skipped = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (k % n_shards != shard) continue;
        const Pair& p = pairs[k];
        if (done.count(p.id)) {
            ++skipped;
            continue;
        }
        nlohmann::json line;
        int code = kOk;
        std::string error;
        try {
            const LoadedMesh a_mesh = read_mesh(p.original);
            const LoadedMesh b_mesh = read_mesh(p.processed);
            line = batch_ok_json(p.id, p.original, p.processed, compare_meshes(a_mesh, b_mesh, options));
            ++ok;
        } catch (const std::exception& e) {
            const Failure f = failure_of(e);
            code = f.code;
            error = f.message;
            line = batch_error_json(p.id, p.original, p.processed, error, code);
            ++failed;
        }
        out << line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
        out.flush();
        if (!out) throw IoError(fmt::format("{}: write failed", a.out));
        if (!a.quiet)
            std::cerr << fmt::format("[{}/{}] {} {}{}\n", k + 1, pairs.size(), code == kOk ? "ok   " : "ERROR", p.id,
                                     code == kOk ? "" : ": " + error);
    }
    std::cerr << fmt::format("batch: {} ok, {} failed, {} already done (shard {}/{}, {} pairs in the list)\n", ok,
                             failed, skipped, shard, n_shards, pairs.size());
    return failed ? kBatchFailures : kOk;
}

}  // namespace

void add_batch_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<BatchArgs>();
    auto* sub = app.add_subcommand("batch",
                                   "compare many pairs listed in a CSV (original,processed[,id]); one JSON line per "
                                   "pair, resumable, shardable");
    sub->add_option("PAIRS", args->pairs,
                    "CSV file: original,processed[,id] per line; relative paths are relative "
                    "to the CSV's folder; '#' lines and an 'original,...' header are skipped")
        ->required();
    sub->add_option("--out", args->out, "JSON-lines output, appended to; pairs already recorded as ok are skipped")
        ->required();
    sub->add_option("--shard", args->shard, "I/N: process only pairs whose 0-based index k has k % N == I")
        ->capture_default_str();
    add_compare_options(sub, args->compare);
    sub->add_option("--threads", args->threads, "worker threads per comparison (0: all cores)");
    sub->add_flag("-q,--quiet", args->quiet, "no per-pair progress on stderr");
    sub->callback([args, &action] { action = [args] { return run_batch(*args); }; });
}

}  // namespace meshdiff::cli

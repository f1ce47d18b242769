#include "batch_list.h"
#include "batch_records.h"
#include "cli.h"
#include "commands.h"
#include "interrupt.h"
#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/version.h"
#include "options.h"
#include "subprocess.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
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
    CompareOutputCliOptions outputs;  // --color-range only: the maps of --maps-dir
    Given threads;
    bool quiet = false;
    bool progress = false;
    double pair_timeout = 0.0;  // seconds; 0: none
    std::string maps_dir;       // distance maps of every pair, when set
    std::string html_dir;       // the HTML report of every pair, when set
    CLI::App* app = nullptr;    // the parsed subcommand (its options are passed on to each pair)
};

// The exit_code of a pair that ran out of time (as coreutils' timeout).
constexpr int kPairTimeout = 124;

// The prefix of a pair's distance maps in --maps-dir: the id with every
// character other than letters, digits, '.', '-' and '_' replaced by '_',
// plus a hash of the id when that changed it (so that two ids stay two files).
std::string map_prefix(const std::string& dir, const std::string& id)
{
    std::string safe;
    for (const char ch : id)
        safe += std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '-' || ch == '_' ? ch : '_';
    if (safe.empty() || safe[0] == '.') safe = "_" + safe;
    if (safe != id) {
        std::uint64_t h = 14695981039346656037ull;  // FNV-1a
        for (const char ch : id) h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull;
        safe += fmt::format("-{:08x}", std::uint32_t(h));
    }
    return (std::filesystem::path(dir) / safe).string();
}

// The command line of one pair's child process: `meshdiff compare ORIGINAL
// PROCESSED --json -` with the batch's comparison options as they were given.
std::vector<std::string> compare_args(const BatchArgs& a, const Pair& p)
{
    std::vector<std::string> args{"meshdiff", "compare"};
    static const std::set<std::string> batch_only = {"out",          "shard",    "quiet",    "progress",
                                                     "pair-timeout", "maps-dir", "html-dir", "help"};
    for (const CLI::Option* o : a.app->get_options()) {
        if (o->count() == 0 || o->get_lnames().empty() || batch_only.count(o->get_lnames()[0])) continue;
        const std::string name = "--" + o->get_lnames()[0];
        const std::vector<std::string>& values = o->results();
        // A flag or a one-value option as --NAME=VALUE, so that a value that
        // starts with '-' stays a value (and --flag=false stays false); an
        // option of N values (--color-range MIN MAX) as --NAME V1 .. VN.
        const auto n = std::size_t(std::max(1, o->get_expected_max()));
        if (n == 1) {
            for (const auto& value : values) args.push_back(name + "=" + value);
            continue;
        }
        for (std::size_t i = 0; i < values.size(); i += n) {
            args.push_back(name);
            for (std::size_t j = i; j < std::min(values.size(), i + n); ++j) args.push_back(values[j]);
        }
    }
    if (!a.maps_dir.empty()) args.insert(args.end(), {"--distance-maps", map_prefix(a.maps_dir, p.id)});
    if (!a.html_dir.empty()) args.insert(args.end(), {"--html", map_prefix(a.html_dir, p.id) + ".html"});
    // The files after "--": a name that starts with '-' stays a file name.
    args.insert(args.end(), {"--json", "-", "--", p.original, p.processed});
    return args;
}

// Compares one pair in a child process, so that a crash, an abort or a hang
// (beyond --pair-timeout) of this pair becomes its error line.
nlohmann::json compare_pair(const BatchArgs& a, const std::string& self, const Pair& p, int& code, std::string& error)
{
    const ChildResult r = run_child(self, compare_args(a, p), a.pair_timeout, interrupted);
    if (r.timed_out) {
        code = kPairTimeout;
        error = fmt::format("timed out after {} s (--pair-timeout)", a.pair_timeout);
    } else if (r.signal != 0) {
        code = kInternal;
        error = fmt::format("the comparison was killed by signal {} ({})", r.signal, strsignal(r.signal));
    } else if (r.exit_code != kOk) {
        code = r.exit_code;
        error = r.err;
        if (error.rfind("meshdiff: ", 0) == 0) error = error.substr(10);
        while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
    } else {
        auto result = nlohmann::json::parse(r.out, nullptr, false);
        if (!result.is_discarded()) {
            code = kOk;
            return batch_ok_json(p.id, p.original, p.processed, std::move(result));
        }
        code = kInternal;
        error = "the comparison wrote no readable JSON";
    }
    return batch_error_json(p.id, p.original, p.processed, error, code);
}

constexpr const char* kNotBatchOutput = "; --out must be a file that only batch writes (left as it was)";

// The ids recorded as ok in an existing output. Every whole line must be a
// batch record, else the file is not one batch writes and it is refused
// (exit 3) untouched. A last line without its newline that starts as a record
// does is one torn by a killed run: once every other line is known to be a
// record, it is cut off the file (the pair runs again). A target that is not
// a regular file (a device such as /dev/null or /dev/full, a FIFO) has no
// records and is never read.
std::set<std::string> finished_ids(int fd, const std::string& path)
{
    struct stat st
    {};
    if (fstat(fd, &st) != 0) throw IoError(fmt::format("{}: cannot stat: {}", path, std::strerror(errno)));
    if (!S_ISREG(st.st_mode)) return {};
    std::string text;
    char buf[1 << 16];
    ssize_t got = 0;
    while ((got = pread(fd, buf, sizeof buf, off_t(text.size()))) > 0) text.append(buf, std::size_t(got));
    if (got < 0) throw IoError(fmt::format("{}: read failed: {}", path, std::strerror(errno)));
    const std::size_t whole = whole_lines_end(text);
    std::set<std::string> done;
    for_each_record(text, whole, path, kNotBatchOutput, [&](BatchRecord&& r) {
        if (r.ok) done.insert(r.id);
    });
    if (whole < text.size()) {
        // Every record batch writes starts with {" (an object with its keys in order).
        if (text.compare(whole, 2, "{\"") != 0)
            throw IoError(fmt::format("{}:{}: not a meshdiff batch record{}", path,
                                      std::count(text.begin(), text.begin() + std::ptrdiff_t(whole), '\n') + 1,
                                      kNotBatchOutput));
        if (ftruncate(fd, off_t(whole)) != 0) throw IoError(fmt::format("{}: cannot cut a torn last line", path));
        std::cerr << fmt::format("batch: {}: dropped a torn last line (a killed run's record)\n", path);
    }
    return done;
}

int run_batch(const BatchArgs& a)
{
    set_threads(a.threads);
    install_interrupt_handlers();
    refuse_overwriting_inputs("--out", a.out, {a.pairs});
    validate_pair_timeout(a.pair_timeout);
    const auto [shard, n_shards] = parse_shard(a.shard);
    {
        // Every option checked here, before any pair runs, as each pair's compare will check it.
        CompareOutputs outputs = to_compare_outputs(a.outputs);
        if (!a.maps_dir.empty()) outputs.distance_maps = map_prefix(a.maps_dir, "pair");
        if (!a.html_dir.empty()) outputs.html = map_prefix(a.html_dir, "pair") + ".html";
        validate(outputs, to_compare_options(a.compare), {});
    }
    for (const auto& [dir, what] : {std::pair{a.maps_dir, "maps"}, std::pair{a.html_dir, "HTML reports"}}) {
        if (dir.empty()) continue;
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (ec || !std::filesystem::is_directory(dir))
            throw IoError(
                fmt::format("{}: cannot create the {} folder ({})", dir, what, ec ? ec.message() : "not a directory"));
    }
    const std::vector<Pair> pairs = read_pairs(a.pairs);
    // No pair's mesh is the output either (exit 2, before --out is opened).
    for (const Pair& p : pairs) refuse_overwriting_inputs("--out", a.out, {p.original, p.processed});
    const std::string self = self_executable();

    // One writer per output: a second batch on the same --out is refused.
    const int fd = open(a.out.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw IoError(fmt::format("{}: cannot open for appending: {}", a.out, std::strerror(errno)));
    struct Closer
    {
        int fd;
        ~Closer() { close(fd); }
    } closer{fd};
    if (flock(fd, LOCK_EX | LOCK_NB) != 0)
        throw IoError(fmt::format("{}: another meshdiff batch is writing this file (it is locked)", a.out));
    // Resume: ids already recorded as ok are skipped; errors are retried.
    const std::set<std::string> done = finished_ids(fd, a.out);

    std::size_t ok = 0, failed = 0, skipped = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (interrupted()) break;
        if (k % n_shards != shard) continue;
        const Pair& p = pairs[k];
        if (done.count(p.id)) {
            ++skipped;
            continue;
        }
        int code = kOk;
        std::string error;
        const auto t0 = std::chrono::steady_clock::now();
        nlohmann::json line = compare_pair(a, self, p, code, error);
        // Ctrl-C reaches the pair's process too (or is passed on to it): the
        // pair is not recorded and runs again on resume.
        if (interrupted()) break;
        line["elapsed_seconds"] =
            std::round(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() * 1000.0) / 1000.0;
        line["meshdiff_version"] = MESHDIFF_VERSION;
        if (code == kOk && !a.maps_dir.empty()) {
            const std::string prefix = map_prefix(a.maps_dir, p.id);
            line["distance_maps"] = {{"original", prefix + "_original.ply"}, {"processed", prefix + "_processed.ply"}};
        }
        if (code == kOk && !a.html_dir.empty()) line["html"] = map_prefix(a.html_dir, p.id) + ".html";
        (code == kOk ? ok : failed) += 1;
        // One write of the whole record with its newline: a kill leaves a whole line or a torn last one.
        const std::string text = line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
        if (write(fd, text.data(), text.size()) != ssize_t(text.size()))
            throw IoError(fmt::format("{}: write failed: {}", a.out, std::strerror(errno)));
        if (!a.quiet)
            std::cerr << fmt::format("[{}/{}] {} {}{}\n", k + 1, pairs.size(), code == kOk ? "ok   " : "ERROR", p.id,
                                     code == kOk ? "" : ": " + error);
    }
    if (interrupted()) {
        std::cerr << fmt::format(
            "meshdiff: batch interrupted by {}: {} ok, {} failed recorded in {}; the pair that was running is not "
            "recorded; the same command resumes\n",
            interrupt_signal() == SIGTERM ? "SIGTERM" : "SIGINT", ok, failed, a.out);
        return kInterrupted;
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
    sub->add_option("--shard", args->shard,
                    "I/N: process only pairs whose 0-based index k has k % N == I; 'auto' takes I and N from a Slurm "
                    "job array, 'auto/N' takes I from Slurm or GNU parallel ($PARALLEL_SEQ - 1)")
        ->capture_default_str();
    add_compare_options(sub, args->compare);
    sub->add_option("--color-range", args->outputs.color_range,
                    "with --maps-dir: the distance colour range of the maps of every pair: MIN MAX, LO:HI, max or "
                    "pNN (as compare's)")
        ->expected(1, 2);
    add_html_face_budget_option(sub, args->outputs.html_face_budget);
    add_threads_option(sub, args->threads);
    auto* progress = sub->add_flag("--progress", args->progress,
                                   "show the progress (one line per pair on stderr; the default, as for compare "
                                   "when stderr is not a terminal with --progress)");
    sub->add_flag("-q,--quiet", args->quiet, "no per-pair progress on stderr")->excludes(progress);
    sub->add_option("--pair-timeout", args->pair_timeout,
                    "seconds one pair may take before it is stopped and recorded as an error (exit_code 124); 0: "
                    "no limit")
        ->capture_default_str();
    sub->add_option("--html-dir", args->html_dir,
                    "write the HTML report of every pair into this folder: ID.html (the id made file-safe, as for "
                    "--maps-dir); the record names it (\"html\")");
    sub->add_option("--maps-dir", args->maps_dir,
                    "write both distance maps of every pair into this folder: ID_original.ply and ID_processed.ply "
                    "(the id made file-safe), one colour scale per pair");
    args->app = sub;
    sub->callback([args, &action] { action = [args] { return run_batch(*args); }; });
}

}  // namespace meshdiff::cli

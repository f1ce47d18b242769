#include "batch_list.h"

#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

namespace meshdiff::cli {

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
    // Only a regular file is read as a list (a directory, a device such as
    // /dev/zero or a FIFO is refused before it is opened: no read without end, no block).
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        throw IoError(fmt::format("{}: cannot open the pair list: {}", path, ec ? ec.message() : "no such file"));
    if (std::filesystem::is_directory(status)) throw IoError(fmt::format("{}: is a directory, not a pair list", path));
    if (!std::filesystem::is_regular_file(status))
        throw IoError(fmt::format("{}: is not a regular file (a device, FIFO or socket), not a pair list", path));
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
    std::map<std::string, std::size_t> id_line;
    while (std::getline(in, line)) {
        ++lineno;
        // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first field.
        if (lineno == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
        // A comment starts with '#' as written; a quoted "#x.ply" is a file name.
        const auto first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line[first] == '#') continue;
        const auto fields = split_csv(line);
        if (fields.size() == 1 && fields[0].empty()) continue;
        if (lineno == 1 && fields[0] == "original") continue;  // header
        if (fields.size() < 2 || fields[0].empty() || fields[1].empty())
            throw InvalidArgumentError(
                fmt::format("{}:{}: expected 'original,processed[,id]', got '{}'", path, lineno, line));
        Pair p;
        p.line = lineno;
        p.original = resolve(fields[0]);
        p.processed = resolve(fields[1]);
        p.id = fields.size() > 2 && !fields[2].empty() ? fields[2] : fields[0] + " -> " + fields[1];
        // Resume finds pairs by id: two pairs with one id would be one pair.
        const auto [it, fresh] = id_line.emplace(p.id, lineno);
        if (!fresh)
            throw InvalidArgumentError(
                fmt::format("{}:{}: the id '{}' is already used on line {}", path, lineno, p.id, it->second));
        pairs.push_back(std::move(p));
    }
    if (in.bad()) throw IoError(fmt::format("{}: read failed", path));
    return pairs;
}

namespace {

std::pair<std::size_t, std::size_t> parse_numeric_shard(const std::string& s)
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
    validate_shard(i, n, s);
    return {i, n};
}

}  // namespace

namespace {
// A non-negative integer from the environment variable \p name, or -1 when it
// is unset; an error when it is set but not a number.
long long env_number(const char* name)
{
    const char* v = std::getenv(name);
    if (!v) return -1;
    const std::string s(v);
    if (s.empty() || s.size() > 12 || s.find_first_not_of("0123456789") != std::string::npos)
        throw InvalidArgumentError(fmt::format("--shard auto: {}='{}' is not a non-negative integer", name, s));
    return std::stoll(s);
}
}  // namespace

std::pair<std::size_t, std::size_t> parse_shard(const std::string& s)
{
    if (s != "auto" && s.rfind("auto/", 0) != 0) return parse_numeric_shard(s);
    const long long task = env_number("SLURM_ARRAY_TASK_ID");
    const long long task_min = env_number("SLURM_ARRAY_TASK_MIN");
    const long long task_count = env_number("SLURM_ARRAY_TASK_COUNT");
    long long index = -1;
    std::string from;
    if (task >= 0) {
        index = task - std::max(0LL, task_min);
        from = "SLURM_ARRAY_TASK_ID";
    } else {
        const long long seq = env_number("PARALLEL_SEQ");
        if (seq >= 1) {
            index = seq - 1;
            from = "PARALLEL_SEQ";
        }
    }
    if (index < 0)
        throw InvalidArgumentError(fmt::format(
            "--shard {}: neither a Slurm job array (SLURM_ARRAY_TASK_ID) nor GNU parallel (PARALLEL_SEQ) is set", s));
    long long count = -1;
    if (s == "auto") {
        if (from != "SLURM_ARRAY_TASK_ID" || task_count < 1)
            throw InvalidArgumentError(fmt::format(
                "--shard auto: the shard count is known only in a Slurm job array (SLURM_ARRAY_TASK_COUNT); under {} "
                "give it: --shard auto/N",
                from));
        count = task_count;
    } else {
        const auto n = parse_numeric_shard("0/" + s.substr(5)).second;
        count = (long long)n;
    }
    return parse_numeric_shard(fmt::format("{}/{}", index, count));
}

}  // namespace meshdiff::cli

#include "batch_records.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

namespace meshdiff::cli {

std::size_t whole_lines_end(const std::string& text)
{
    const auto last_newline = text.rfind('\n');
    return last_newline == std::string::npos ? 0 : last_newline + 1;
}

void for_each_record(const std::string& text, std::size_t end, const std::string& path, const std::string& note,
                     const std::function<void(BatchRecord&&)>& on_record)
{
    std::size_t lineno = 0, start = 0;
    while (start < end) {
        const auto stop = text.find('\n', start);
        const std::string line = text.substr(start, stop - start);
        start = stop + 1;
        ++lineno;
        if (line.empty() || line == "\r") continue;
        auto j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_discarded() || !j.is_object() || !j.contains("id") || !j["id"].is_string() || !j.contains("status") ||
            !j["status"].is_string())
            throw IoError(fmt::format("{}:{}: not a meshdiff batch record{}", path, lineno, note));
        BatchRecord r;
        r.id = j["id"].get<std::string>();
        r.ok = j["status"] == "ok";
        r.line = lineno;
        r.json = std::move(j);
        on_record(std::move(r));
    }
}

}  // namespace meshdiff::cli

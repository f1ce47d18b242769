// The records of a batch output (JSON lines, one object per pair), read one
// way by batch (to resume) and batch-summary (to merge).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <string>

namespace meshdiff::cli {

//! One line of a batch output that is a batch record: an object with a
//! string "id" and a string "status".
struct BatchRecord
{
    nlohmann::json json;
    std::string id;
    bool ok = false;     //!< status "ok"
    std::size_t line{};  //!< 1-based line number in the file
};

//! Where the whole lines of \p text end: one past its last newline (0 if it
//! has none). What follows is a torn last line, the record of a killed run.
std::size_t whole_lines_end(const std::string& text);

//! Calls \p on_record for each record in the whole lines text[0, end) of the
//! batch output \p path, in file order; blank lines are skipped. A line that
//! is not a batch record throws IoError "PATH:LINE: not a meshdiff batch
//! record" followed by \p note.
void for_each_record(const std::string& text, std::size_t end, const std::string& path, const std::string& note,
                     const std::function<void(BatchRecord&&)>& on_record);

}  // namespace meshdiff::cli

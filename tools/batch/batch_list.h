//! \file batch_list.h
//! \brief The pair list of `meshdiff batch` and `meshdiff batch-summary`
//! (PAIRS.csv), and the --shard argument.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace meshdiff::cli {

//! One pair of the list.
struct Pair
{
    std::size_t line = 0;  //!< 1-based line in the CSV
    std::string id, original, processed;
};

//! Splits one CSV line; fields may be quoted with "" (a doubled quote inside
//! a quoted field is a literal quote); surrounding blanks are trimmed.
std::vector<std::string> split_csv(const std::string& line);

//! Reads PAIRS.csv: original,processed[,id] per line, relative paths resolved
//! against the CSV's folder, '#' lines, blank lines and an 'original,...'
//! header skipped, the id defaulting to "original -> processed".
//! \throw IoError if the file cannot be read; InvalidArgumentError for a
//!        malformed line or a repeated id.
std::vector<Pair> read_pairs(const std::string& path);

//! Parses --shard: "I/N" (0 <= I < N <= 1,000,000); "auto" (Slurm job array:
//! I = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN, N = SLURM_ARRAY_TASK_COUNT);
//! "auto/N" (I from the Slurm array as above, else from GNU parallel's job
//! sequence number: I = PARALLEL_SEQ - 1). Returns {I, N}.
//! \throw InvalidArgumentError naming what is wrong or missing.
std::pair<std::size_t, std::size_t> parse_shard(const std::string& s);

}  // namespace meshdiff::cli

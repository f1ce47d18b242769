//! \file report/csv.h
//! \brief The CSV view of the compare report (presentation layer, target
//! meshdiff::report): one flat row per comparison, the columns named by the
//! JSON paths of "meshdiff.compare/2" (report/json.h) joined with '_'. It sits
//! beside the JSON it flattens, so a schema change and its CSV view are
//! edited together; `meshdiff batch-summary --csv` writes it.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace meshdiff {

//! A table of text cells: column name -> cell, one map per row; the columns
//! are written in their order of first appearance over all rows, a cell no
//! row set is empty. Cells holding a comma, a quote or a line break are quoted
//! (RFC 4180).
class CsvTable
{
public:
    //! Sets the cell of \p column in row \p row (rows grow as needed).
    void set(std::size_t row, const std::string& column, std::string value);
    //! The header line and every row.
    void write(std::ostream& out) const;

private:
    std::vector<std::string> columns_;
    std::map<std::string, std::size_t> index_;
    std::vector<std::map<std::string, std::string>> rows_;
};

//! A JSON scalar as a CSV cell: numbers in their shortest round-trip form,
//! booleans as true/false, strings as they are, null as an empty cell.
std::string csv_cell(const nlohmann::json& v);

//! The columns of one "meshdiff.compare/2" object \p result in row \p row:
//! each mesh's vertices, faces and sigma_global; the headline surface distance
//! columns (hausdorff: the certified upper bound or the sampled maximum,
//! forward/backward mean and rms), then every scalar of surface_distance and
//! same_connectivity; d_L and the relative change per ring level, radius and
//! the global level.
void add_comparison_columns(CsvTable& table, std::size_t row, const nlohmann::json& result);

}  // namespace meshdiff

#include "meshdiff/report/csv.h"

#include <fmt/format.h>

#include <set>

namespace meshdiff {

namespace {

std::string quote(const std::string& s)
{
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (const char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
}

}  // namespace

void CsvTable::set(std::size_t row, const std::string& column, std::string value)
{
    if (rows_.size() <= row) rows_.resize(row + 1);
    if (index_.emplace(column, columns_.size()).second) columns_.push_back(column);
    rows_[row][column] = std::move(value);
}

void CsvTable::write(std::ostream& out) const
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

std::string csv_cell(const nlohmann::json& v)
{
    if (v.is_null()) return "";
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

namespace {

// The scalars under \p j, one column each, named by their path joined with
// '_' (below \p prefix); strings only for the Hausdorff method and where it
// is attained, the distance kind of each direction (point clouds), and the
// reasons of *_unavailable fields. Lists of numbers
// (histograms, coordinates) and the sampling settings are left out; a list of objects with a "threshold" (the
// F-scores) gives one group of columns per threshold.
void flatten(CsvTable& t, std::size_t row, const std::string& prefix, const nlohmann::json& j)
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
                    flatten(t, row, fmt::format("{}_{}", name, csv_cell(e["threshold"])), rest);
                }
        } else if (!v.is_string() || name.find("hausdorff_method") != std::string::npos ||
                   name.find("hausdorff_attained") != std::string::npos ||
                   name.find("distance_kind") != std::string::npos ||
                   (name.size() > 12 && name.compare(name.size() - 12, 12, "_unavailable") == 0)) {
            t.set(row, name, csv_cell(v));
        }
    }
}

// d_L and the relative change per ring level and per radius, and the global ones.
void roughness_columns(CsvTable& t, std::size_t row, const nlohmann::json& rd)
{
    auto per = [&](const char* key, const char* dist, const char* rel, const char* tag) {
        if (!rd.contains(key) || !rd[key].is_array()) return;
        const auto& keys = rd[key];
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const std::string label = fmt::format("{}{}", tag, csv_cell(keys[i]));
            if (rd.contains(dist) && i < rd[dist].size()) t.set(row, "d_" + label, csv_cell(rd[dist][i]));
            if (rd.contains(rel) && i < rd[rel].size()) t.set(row, "relative_change_" + label, csv_cell(rd[rel][i]));
        }
    };
    per("levels", "distance", "relative_change", "L");
    if (rd.contains("global") && rd["global"].is_object()) {
        t.set(row, "d_global", csv_cell(rd["global"].value("distance", nlohmann::json())));
        t.set(row, "relative_change_global", csv_cell(rd["global"].value("relative_change", nlohmann::json())));
    }
    per("radii", "distance_radii", "relative_change_radii", "r");
}

void mesh_columns(CsvTable& t, std::size_t row, const char* side, const nlohmann::json& result)
{
    if (!result.contains(side) || !result[side].is_object()) return;
    const auto& p = result[side];
    if (p.contains("mesh") && p["mesh"].is_object()) {
        for (const char* k : {"vertices", "faces"})
            if (p["mesh"].contains(k)) t.set(row, fmt::format("{}_{}", side, k), csv_cell(p["mesh"][k]));
    }
    if (p.contains("sigma_global")) t.set(row, fmt::format("{}_sigma_global", side), csv_cell(p["sigma_global"]));
}

}  // namespace

void add_comparison_columns(CsvTable& table, std::size_t row, const nlohmann::json& result)
{
    mesh_columns(table, row, "original", result);
    mesh_columns(table, row, "processed", result);
    if (result.contains("surface_distance") && result["surface_distance"].is_object()) {
        const nlohmann::json& sd = result["surface_distance"];
        // The headline columns first: the Hausdorff distance (the certified
        // upper bound, or the sampled maximum), the means and RMS.
        const bool certified = sd.contains("hausdorff") && sd["hausdorff"].is_object() &&
                               sd["hausdorff"].value("method", "") == "certified";
        table.set(row, "hausdorff",
                  certified ? csv_cell(sd["hausdorff"].value("upper", nlohmann::json()))
                            : csv_cell(sd.value("sampled_hausdorff", nlohmann::json())));
        for (const char* dir : {"forward", "backward"})
            for (const char* k : {"mean", "rms"})
                if (sd.contains(dir) && sd[dir].contains(k))
                    table.set(row, fmt::format("{}_{}", dir, k), csv_cell(sd[dir][k]));
        flatten(table, row, "", sd);
    }
    if (result.contains("same_connectivity") && result["same_connectivity"].is_object())
        flatten(table, row, "same_connectivity", result["same_connectivity"]);
    if (result.contains("roughness_distance") && result["roughness_distance"].is_object())
        roughness_columns(table, row, result["roughness_distance"]);
}

}  // namespace meshdiff

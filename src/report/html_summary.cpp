// The summary page of a batch (meshdiff batch-summary --html): a table of
// every pair, rendered here (so that it reads without JavaScript), made
// sortable and plotted by src/report/html/summary.js.
#include "meshdiff/error.h"
#include "meshdiff/report/html.h"
#include "meshdiff/version.h"
#include "report/html_assets.h"
#include "report/html_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <set>
#include <string_view>

namespace meshdiff {

namespace {

using html_text::escape_html;
using html_text::script_safe;

// A column of the table: \p path gives, for a record, the dotted path of its
// value in the record ("" when the record has none).
struct Column
{
    std::string key;    // data-key of its cells
    std::string label;  // header
    std::string title;  // header tooltip
    bool numeric;
    std::function<std::string(const nlohmann::json&)> path;
};

const nlohmann::json* at(const nlohmann::json& j, const std::string& path)
{
    const nlohmann::json* p = &j;
    std::size_t start = 0;
    while (start <= path.size()) {
        const auto end = std::min(path.find('.', start), path.size());
        const std::string k = path.substr(start, end - start);
        if (p->is_object() && p->contains(k)) {
            p = &(*p)[k];
        } else if (p->is_array() && !k.empty() && k.find_first_not_of("0123456789") == std::string::npos &&
                   std::stoul(k) < p->size()) {
            p = &(*p)[std::stoul(k)];
        } else {
            return nullptr;
        }
        start = end + 1;
    }
    return p;
}

// \p prefix + "." + the index of \p level in the record's array at \p levels_path ("" if absent).
std::string level_path(const nlohmann::json& r, const std::string& levels_path, const std::string& prefix, int level)
{
    const nlohmann::json* levels = at(r, levels_path);
    if (!levels || !levels->is_array()) return "";
    for (std::size_t i = 0; i < levels->size(); ++i)
        if ((*levels)[i].is_number_integer() && (*levels)[i].get<int>() == level)
            return fmt::format("{}.{}", prefix, i);
    return "";
}

bool certified(const nlohmann::json& r)
{
    const nlohmann::json* m = at(r, "result.surface_distance.hausdorff.method");
    return m && *m == "certified";
}

// The levels given, else 1, 2, 5 where some record has them, else the first three levels of the records.
std::vector<int> chosen_levels(const nlohmann::json& records, const std::vector<int>& given)
{
    if (!given.empty()) return given;
    std::set<int> present;
    for (const auto& r : records)
        if (const nlohmann::json* l = at(r, "result.roughness_distance.levels"); l && l->is_array())
            for (const auto& x : *l)
                if (x.is_number_integer()) present.insert(x.get<int>());
    std::vector<int> out;
    for (int l : {1, 2, 5})
        if (present.count(l)) out.push_back(l);
    if (out.empty())
        for (int l : present)
            if (out.size() < 3) out.push_back(l);
    return out;
}

std::vector<Column> columns(const nlohmann::json& records, const std::vector<int>& levels)
{
    const auto fixed = [](std::string p) { return [p](const nlohmann::json&) { return p; }; };
    const std::string sd = "result.surface_distance.";
    std::vector<Column> c = {
        {"id", "id", "the pair's id", false, fixed("id")},
        {"original", "original", "the original mesh", false, fixed("original")},
        {"processed", "processed", "the processed mesh", false, fixed("processed")},
        {"status", "status", "ok, error or missing", false, fixed("status")},
        {"hausdorff", "Hausdorff", "the certified Hausdorff upper bound (the sampled maximum if not certified)", true,
         [sd](const nlohmann::json& r) { return certified(r) ? sd + "hausdorff.upper" : sd + "sampled_hausdorff"; }},
        {"hausdorff_relative", "Hausdorff rel.", "the same relative to the bounding box diagonal", true,
         [sd](const nlohmann::json& r) {
             return certified(r) ? sd + "hausdorff.relative.upper" : sd + "sampled_hausdorff_relative";
         }},
        {"forward_mean", "fwd mean", "mean distance, original to processed", true, fixed(sd + "forward.mean")},
        {"forward_rms", "fwd RMS", "RMS distance, original to processed", true, fixed(sd + "forward.rms")},
        {"backward_mean", "bwd mean", "mean distance, processed to original", true, fixed(sd + "backward.mean")},
        {"backward_rms", "bwd RMS", "RMS distance, processed to original", true, fixed(sd + "backward.rms")}};
    const std::string rd = "result.roughness_distance.";
    bool global = false;
    for (const auto& r : records) global = global || at(r, rd + "global.distance") != nullptr;
    for (int l : levels)
        c.push_back({fmt::format("d_L{}", l), fmt::format("d_{}", l),
                     fmt::format("roughness distance d_L, level {}", l), true,
                     [rd, l](const nlohmann::json& r) { return level_path(r, rd + "levels", rd + "distance", l); }});
    if (global)
        c.push_back({"d_global", "d_global", "roughness distance, global level", true, fixed(rd + "global.distance")});
    for (int l : levels)
        c.push_back(
            {fmt::format("local_L{}", l), fmt::format("local_{}", l),
             fmt::format("local roughness difference RMS, level {}", l), true,
             [rd, l](const nlohmann::json& r) { return level_path(r, rd + "local.levels", rd + "local.rms", l); }});
    if (global)
        c.push_back({"local_global", "local_global", "local roughness difference RMS, global level", true,
                     fixed(rd + "local.global")});
    c.push_back({"error", "error", "the error message of a failed pair", false, fixed("error")});
    return c;
}

// \p path percent-encoded for an href (a relative or absolute file path).
std::string href_of(const std::string& path)
{
    std::string out;
    for (const unsigned char ch : path) {
        if (std::isalnum(ch) || std::string_view("-._~/").find(char(ch)) != std::string_view::npos)
            out += char(ch);
        else
            out += fmt::format("%{:02X}", ch);
    }
    return out;
}

// The link to the page \p target (relative to the working directory) from a page in \p page_dir.
std::string link_to(const std::string& target, const std::string& page_dir)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path abs = fs::absolute(target, ec).lexically_normal();
    if (ec) return href_of(target);
    const fs::path base = fs::absolute(page_dir.empty() ? "." : page_dir, ec).lexically_normal();
    const fs::path rel = ec ? fs::path() : abs.lexically_relative(base);
    return rel.empty() ? "file://" + href_of(abs.generic_string()) : href_of(rel.generic_string());
}

std::string cell(const Column& c, const nlohmann::json& r)
{
    const std::string path = c.path(r);
    const nlohmann::json* v = path.empty() ? nullptr : at(r, path);
    std::string td = fmt::format("<td data-key=\"{}\"", c.key);
    if (!c.numeric) td += " class=\"l\"";
    if (v && !v->is_null()) td += fmt::format(" data-path=\"{}\"", escape_html(path));
    if (v && v->is_number()) return td + fmt::format(" data-value=\"{}\">{:.6g}</td>", v->dump(), v->get<double>());
    if (v && v->is_string()) return td + ">" + escape_html(v->get<std::string>()) + "</td>";
    return td + "></td>";
}

std::string table(const nlohmann::json& records, const std::vector<Column>& cols, const std::string& page_dir)
{
    std::string t = "<table id=\"pairs\">\n<thead><tr>";
    for (const Column& c : cols)
        t += fmt::format("<th data-key=\"{}\" data-type=\"{}\" title=\"{}\"{}>{}</th>", c.key,
                         c.numeric ? "num" : "text", escape_html(c.title), c.numeric ? "" : " class=\"l\"",
                         escape_html(c.label));
    t += "<th class=\"l\" data-key=\"report\">report</th></tr></thead>\n<tbody>\n";
    for (std::size_t i = 0; i < records.size(); ++i) {
        const nlohmann::json& r = records[i];
        t += fmt::format("<tr data-index=\"{}\" class=\"{}\">", i, escape_html(r.value("status", "")));
        for (const Column& c : cols) t += cell(c, r);
        const auto html = r.find("html");
        if (html != r.end() && html->is_string())
            t += fmt::format("<td class=\"l\" data-key=\"report\"><a href=\"{}\">page</a></td>",
                             escape_html(link_to(html->get<std::string>(), page_dir)));
        else
            t += "<td class=\"l\" data-key=\"report\"></td>";
        t += "</tr>\n";
    }
    return t + "</tbody>\n</table>\n";
}

}  // namespace

std::string batch_summary_html(const nlohmann::json& records, const SummaryHtmlOptions& o)
{
    if (!records.is_array() || !std::all_of(records.begin(), records.end(), [](auto& r) { return r.is_object(); }))
        throw InvalidArgumentError("html: the batch summary needs an array of records");
    const std::vector<Column> cols = columns(records, chosen_levels(records, o.levels));
    std::size_t ok = 0, failed = 0, missing = 0;
    for (const auto& r : records) {
        const std::string s = r.value("status", "");
        (s == "ok" ? ok : s == "missing" ? missing : failed) += 1;
    }
    nlohmann::json plotted = nlohmann::json::array();
    for (const Column& c : cols)
        if (c.numeric) plotted.push_back({{"key", c.key}, {"label", c.label}, {"title", c.title}});
    const nlohmann::json meta = {{"version", MESHDIFF_VERSION}, {"command", o.command}, {"plots", plotted}};
    const auto dump = [](const nlohmann::json& j) {
        return script_safe(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    };
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += "<title>meshdiff batch summary</title>\n";
    page += "<meta name=\"generator\" content=\"meshdiff " MESHDIFF_VERSION "\">\n<style>\n";
    page += assets::report_css();
    page += assets::summary_css();
    page += "</style>\n</head>\n<body>\n<main id=\"app\">\n<h1>meshdiff batch summary</h1>\n";
    page += fmt::format("<p class=\"sub\" id=\"counts\">{} pairs: {} ok, {} failed, {} missing</p>\n", records.size(),
                        ok, failed, missing);
    page +=
        "<h2>Pairs</h2>\n<p class=\"sub\">Click a column's header to sort by it (again: the other way); "
        "empty cells stay last. Distances in the meshes' units.</p>\n";
    page += table(records, cols, o.page_dir);
    page += "<h2>Per pair</h2>\n<div class=\"row\" id=\"plots\"></div>\n";
    page += "<h2>Made by</h2>\n<code class=\"cmd\" id=\"command\">" + escape_html(o.command) + "</code>\n";
    page += "<p class=\"sub\" id=\"version\">meshdiff " MESHDIFF_VERSION "</p>\n</main>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-summary\">" + dump(records) + "</script>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-meta\">" + dump(meta) + "</script>\n";
    page += "<script>\n";
    page += assets::summary_js();
    page += "\n</script>\n</body>\n</html>\n";
    return page;
}

}  // namespace meshdiff

#include "meshdiff/report/html.h"

#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/colormap.h"
#include "meshdiff/report/vertex_maps.h"
#include "meshdiff/version.h"
#include "report/html_assets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace meshdiff {

namespace {

std::string base64(const void* data, std::size_t bytes)
{
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* p = static_cast<const unsigned char*>(data);
    std::string out;
    out.reserve((bytes + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes; i += 3) {
        const unsigned v = unsigned(p[i]) << 16 | unsigned(p[i + 1]) << 8 | p[i + 2];
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
    }
    if (i + 1 == bytes) {
        const unsigned v = unsigned(p[i]) << 16;
        out += {digits[v >> 18], digits[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes) {
        const unsigned v = unsigned(p[i]) << 16 | unsigned(p[i + 1]) << 8;
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], '='};
    }
    return out;
}

template <class T>
std::string base64(const std::vector<T>& v)
{
    return base64(v.data(), v.size() * sizeof(T));
}

// A field as 16-bit steps over [lo, hi] of its values (65535: none): a quarter
// of doubles' bytes, and 1/65534 of the range is finer than any colour.
nlohmann::json quantized(const std::vector<double>& values)
{
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double x : values)
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!(lo <= hi)) lo = hi = 0.0;
    std::vector<std::uint16_t> q(values.size(), 65535);
    const double step = hi > lo ? (hi - lo) / 65534.0 : 1.0;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (std::isfinite(values[i])) q[i] = std::uint16_t(std::lround((values[i] - lo) / step));
    return {{"encoding", "uint16"}, {"lo", lo}, {"step", step}, {"data", base64(q)}};
}

// The q-quantile (0..1) of the absolute finite values of both arrays.
double abs_quantile(const std::vector<double>& a, const std::vector<double>& b, double q)
{
    std::vector<double> v;
    v.reserve(a.size() + b.size());
    for (const auto* s : {&a, &b})
        for (double x : *s)
            if (std::isfinite(x)) v.push_back(std::abs(x));
    if (v.empty()) return 0.0;
    const auto k = std::size_t(std::llround(q * double(v.size() - 1)));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

struct Field
{
    std::string name;   // "distance", "D_1", ..., "D_global"
    std::string label;  // what the colour bar says
    const std::vector<double>* original;
    const std::vector<double>* processed;
};

std::vector<Field> fields_of(const Comparison& c)
{
    std::vector<Field> f;
    if (c.original_vertex_distance.size() == c.original.topology.vertices &&
        c.processed_vertex_distance.size() == c.processed.topology.vertices && c.original.topology.vertices > 0)
        f.push_back(
            {"distance", "distance to the other surface", &c.original_vertex_distance, &c.processed_vertex_distance});
    if (c.original_profile && c.processed_profile) {
        const RoughnessProfile& a = *c.original_profile;
        const RoughnessProfile& b = *c.processed_profile;
        if (a.D.size() == a.levels.size() && b.D.size() == b.levels.size() && a.levels.size() == b.levels.size() &&
            !a.D.empty() && a.D[0].size() == c.original.topology.vertices &&
            b.D[0].size() == c.processed.topology.vertices)
            for (std::size_t k = 0; k < a.levels.size(); ++k)
                f.push_back({fmt::format("D_{}", a.levels[k].level),
                             fmt::format("roughness D_{} (curvature deviation, 1/length of the unit-scaled mesh)",
                                         a.levels[k].level),
                             &a.D[k], &b.D[k]});
        if (a.has_global && b.has_global && a.D_global.size() == c.original.topology.vertices &&
            b.D_global.size() == c.processed.topology.vertices)
            f.push_back({"D_global", "roughness D_global (curvature deviation, 1/length of the unit-scaled mesh)",
                         &a.D_global, &b.D_global});
        // Metric levels (--radii): D within a radius of the unit-scaled mesh.
        for (std::size_t k = 0; k < a.radii.size() && k < a.D_radii.size() && k < b.D_radii.size(); ++k)
            if (a.D_radii[k].size() == c.original.topology.vertices &&
                b.D_radii[k].size() == c.processed.topology.vertices)
                f.push_back({fmt::format("D_r{:g}", a.radii[k].radius),
                             fmt::format("roughness D within radius {:g} of the unit-scaled mesh (1/length)",
                                         a.radii[k].radius),
                             &a.D_radii[k], &b.D_radii[k]});
    }
    return f;
}

nlohmann::json mesh_view(const Mesh& mesh, const std::vector<Field>& fields, bool original, std::size_t budget)
{
    std::vector<const std::vector<double>*> values;
    for (const Field& f : fields) values.push_back(original ? f.original : f.processed);
    const DisplayMesh d = reduce_for_display(mesh, values, budget);
    nlohmann::json j = {{"positions", base64(d.positions)},
                        {"indices", base64(d.indices)},
                        {"vertices", d.positions.size() / 3},
                        {"faces", d.indices.size() / 3},
                        {"full_vertices", d.full_vertices},
                        {"full_faces", d.full_faces},
                        {"reduced", d.reduced}};
    nlohmann::json fj = nlohmann::json::object();
    for (std::size_t i = 0; i < fields.size(); ++i)
        fj[fields[i].name] = fields[i].name == "distance"
                                 ? nlohmann::json{{"encoding", "float64"}, {"data", base64(d.values[i])}}
                                 : quantized(d.values[i]);
    j["fields"] = fj;
    return j;
}

nlohmann::json view_json(const Comparison& c, const Mesh& original, const Mesh& processed, const HtmlOptions& o)
{
    const std::vector<Field> fields = fields_of(c);
    nlohmann::json ranges = nlohmann::json::array();
    for (const Field& f : fields) {
        nlohmann::json r = {{"name", f.name}, {"label", f.label}};
        if (f.name == "distance") {
            r["map"] = "sequential";
            if (o.color_range) {
                r["range"] = {o.color_range->first, o.color_range->second};
                r["rule"] = o.color_rule.empty() ? "given" : o.color_rule;
            } else {
                const auto range = distance_color_range(c, kDefaultHtmlPercentile);
                r["range"] = {range.first, range.second};
                r["rule"] = "0 to the 99th percentile of both meshes' vertex distances";
            }
        } else {
            // The vertex data map's rule (vertex_maps.h profile_map(): robust_symmetric_range), over both meshes.
            double R = abs_quantile(*f.original, *f.processed, 0.95);
            if (!(R > 0.0)) R = 1.0;
            r["map"] = "diverging";
            r["range"] = {-R, R};
            r["rule"] = "symmetric, the 95th percentile of |D| over both meshes";
        }
        ranges.push_back(r);
    }
    return {{"fields", ranges},
            {"face_budget", o.face_budget},
            {"meshes",
             {mesh_view(original, fields, true, o.face_budget), mesh_view(processed, fields, false, o.face_budget)}}};
}

// \p text with "</" written "<\/" (the same JSON, and no "</script>" can end the element early).
std::string script_safe(const std::string& text)
{
    std::string out;
    out.reserve(text.size() + 16);
    for (std::size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
    }
    return out;
}

std::string escape_html(const std::string& s)
{
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

}  // namespace

std::string comparison_html(const Comparison& c, const Mesh& original, const Mesh& processed,
                            const nlohmann::json& report, const HtmlOptions& o)
{
    if (o.face_budget < 1000)
        throw InvalidArgumentError(fmt::format("html: a face budget of {} is below 1000", o.face_budget));
    if (o.color_range && !(std::isfinite(o.color_range->first) && std::isfinite(o.color_range->second) &&
                           o.color_range->first < o.color_range->second))
        throw InvalidArgumentError("html: the colour range needs finite MIN < MAX");
    const auto dump = [](const nlohmann::json& j) {
        return script_safe(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    };
    const nlohmann::json meta = {{"version", MESHDIFF_VERSION}, {"command", o.command}};
    std::string page;
    page.reserve(assets::three_js().size() + 1'000'000);
    page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += fmt::format("<title>meshdiff: {} vs {}</title>\n", escape_html(c.original.input.path),
                        escape_html(c.processed.input.path));
    page += "<meta name=\"generator\" content=\"meshdiff " MESHDIFF_VERSION "\">\n<style>\n";
    page += assets::report_css();
    page +=
        "</style>\n</head>\n<body>\n<noscript>This report needs JavaScript; its data is in the "
        "meshdiff-report element of the page's source.</noscript>\n<main id=\"app\"></main>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-report\">" + dump(report) + "</script>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-meta\">" + dump(meta) + "</script>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-view\">" + dump(view_json(c, original, processed, o)) +
            "</script>\n";
    page += "<script>\n";
    page += assets::three_js();
    page += "\n</script>\n<script>\n";
    page += assets::orbit_controls_js();
    page += "\n</script>\n<script>\n";
    page += assets::report_js();
    page += "\n</script>\n</body>\n</html>\n";
    return page;
}

void write_html_file(const std::string& path, const std::string& page)
{
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw IoError(fmt::format("{}: cannot open for writing", path));
        out.write(page.data(), std::streamsize(page.size()));
        out.close();
        if (!out) throw IoError(fmt::format("{}: write failed", path));
    });
}

}  // namespace meshdiff

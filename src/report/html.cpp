#include "meshdiff/report/html.h"

#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/colormap.h"
#include "meshdiff/report/vertex_maps.h"
#include "meshdiff/version.h"
#include "report/html_assets.h"
#include "report/html_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>

namespace meshdiff {

namespace {

using html_text::escape_html;
using html_text::script_safe;

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

// The q-quantile (0..1) of the absolute finite values of the arrays.
double abs_quantile(const std::vector<const std::vector<double>*>& arrays, double q)
{
    std::vector<double> v;
    for (const auto* s : arrays)
        for (double x : *s)
            if (std::isfinite(x)) v.push_back(std::abs(x));
    if (v.empty()) return 0.0;
    const auto k = std::size_t(std::llround(q * double(v.size() - 1)));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

// A per-vertex field the view can colour by: one array per mesh drawn.
struct Field
{
    std::string name;   // "distance", "H", "D_1", ..., "D_global", "D_r0.05"
    std::string label;  // what the colour bar says
    std::vector<const std::vector<double>*> per_mesh;
    double symmetric_range = 0.0;  // > 0: the range [-R, R] of a diverging field, with its rule
    std::string rule = {};
};

const char* const kUnitScaled = "1/length of the unit-scaled mesh";

// The D fields (levels, global, radii) of \p profiles, each with the vertex count of its mesh.
void add_roughness_fields(std::vector<Field>& f, const std::vector<const RoughnessProfile*>& profiles,
                          const std::vector<std::size_t>& vertices)
{
    const RoughnessProfile& a = *profiles[0];
    auto all = [&](auto member) {
        std::vector<const std::vector<double>*> out;
        for (std::size_t m = 0; m < profiles.size(); ++m) {
            const std::vector<double>* v = member(*profiles[m]);
            if (!v || v->size() != vertices[m]) return std::vector<const std::vector<double>*>{};
            out.push_back(v);
        }
        return out;
    };
    for (std::size_t k = 0; k < a.levels.size(); ++k) {
        auto d = all([k](const RoughnessProfile& p) { return k < p.D.size() ? &p.D[k] : nullptr; });
        if (!d.empty())
            f.push_back({fmt::format("D_{}", a.levels[k].level),
                         fmt::format("roughness D_{} (curvature deviation, {})", a.levels[k].level, kUnitScaled), d});
    }
    if (a.has_global) {
        auto d = all([](const RoughnessProfile& p) { return p.has_global ? &p.D_global : nullptr; });
        if (!d.empty())
            f.push_back({"D_global", fmt::format("roughness D_global (curvature deviation, {})", kUnitScaled), d});
    }
    for (std::size_t k = 0; k < a.radii.size(); ++k) {
        auto d = all([k](const RoughnessProfile& p) { return k < p.D_radii.size() ? &p.D_radii[k] : nullptr; });
        if (!d.empty())
            f.push_back({fmt::format("D_r{:g}", a.radii[k].radius),
                         fmt::format("roughness D within radius {:g} ({})", a.radii[k].radius, kUnitScaled), d});
    }
}

std::vector<Field> fields_of(const Comparison& c)
{
    std::vector<Field> f;
    if (c.original_vertex_distance.size() == c.original.topology.vertices &&
        c.processed_vertex_distance.size() == c.processed.topology.vertices && c.original.topology.vertices > 0)
        f.push_back(
            {"distance", "distance to the other surface", {&c.original_vertex_distance, &c.processed_vertex_distance}});
    if (c.original_profile && c.processed_profile)
        add_roughness_fields(f, {&*c.original_profile, &*c.processed_profile},
                             {c.original.topology.vertices, c.processed.topology.vertices});
    return f;
}

nlohmann::json mesh_view(const Mesh& mesh, const std::string& role, const std::vector<Field>& fields, std::size_t m,
                         std::size_t budget)
{
    std::vector<const std::vector<double>*> values;
    for (const Field& f : fields) values.push_back(f.per_mesh[m]);
    const DisplayMesh d = reduce_for_display(mesh, values, budget);
    nlohmann::json j = {{"role", role},
                        {"positions", base64(d.positions)},
                        {"indices", base64(d.indices)},
                        {"vertices", d.positions.size() / 3},
                        {"faces", d.indices.size() / 3},
                        {"full_vertices", d.full_vertices},
                        {"full_faces", d.full_faces},
                        {"reduced", d.reduced}};
    nlohmann::json fj = nlohmann::json::object();
    for (std::size_t i = 0; i < fields.size(); ++i)
        fj[fields[i].name] = fields[i].name == "distance" || fields[i].name == "H"
                                 ? nlohmann::json{{"encoding", "float64"}, {"data", base64(d.values[i])}}
                                 : quantized(d.values[i]);
    j["fields"] = fj;
    return j;
}

// The view's data: each field's colour map and range, and the meshes as drawn. \p distance_range is the
// distance field's range (used only if there is one).
nlohmann::json view_json(const std::vector<Field>& fields,
                         const std::vector<std::pair<const Mesh*, std::string>>& meshes, const HtmlOptions& o,
                         const std::function<std::pair<double, double>()>& distance_range)
{
    nlohmann::json ranges = nlohmann::json::array();
    for (const Field& f : fields) {
        nlohmann::json r = {{"name", f.name}, {"label", f.label}};
        if (f.name == "distance") {
            r["map"] = "sequential";
            if (o.color_range) {
                r["range"] = {o.color_range->first, o.color_range->second};
                r["rule"] = o.color_rule.empty() ? "given" : o.color_rule;
            } else {
                const auto range = distance_range();
                r["range"] = {range.first, range.second};
                r["rule"] = "0 to the 99th percentile of both meshes' vertex distances";
            }
        } else {
            // The vertex data map's rule (vertex_maps.h profile_map(): robust_symmetric_range), over every mesh.
            double R = f.symmetric_range > 0.0 ? f.symmetric_range : abs_quantile(f.per_mesh, 0.95);
            if (!(R > 0.0)) R = 1.0;
            r["map"] = "diverging";
            r["range"] = {-R, R};
            r["rule"] = !f.rule.empty() ? f.rule
                                        : "symmetric, the 95th percentile of |value| over " +
                                              std::string(meshes.size() > 1 ? "both meshes" : "the mesh");
        }
        ranges.push_back(r);
    }
    nlohmann::json mj = nlohmann::json::array();
    for (std::size_t m = 0; m < meshes.size(); ++m)
        mj.push_back(mesh_view(*meshes[m].first, meshes[m].second, fields, m, o.face_budget));
    return {{"fields", ranges}, {"face_budget", o.face_budget}, {"meshes", mj}};
}

}  // namespace

namespace {

void check(const HtmlOptions& o)
{
    if (o.face_budget < kMinHtmlFaceBudget)
        throw InvalidArgumentError(
            fmt::format("html: a face budget of {} is below {}", o.face_budget, kMinHtmlFaceBudget));
    if (o.color_range && !(std::isfinite(o.color_range->first) && std::isfinite(o.color_range->second) &&
                           o.color_range->first < o.color_range->second))
        throw InvalidArgumentError("html: the colour range needs finite MIN < MAX");
}

// The page: \p title, the JSON report, the meta data and the view's data, then the scripts.
std::string page(const std::string& title, const nlohmann::json& report, const HtmlOptions& o,
                 const nlohmann::json& view)
{
    const auto dump = [](const nlohmann::json& j) {
        return script_safe(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    };
    const nlohmann::json meta = {{"version", MESHDIFF_VERSION}, {"command", o.command}};
    std::string page;
    page.reserve(assets::three_js().size() + 1'000'000);
    page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += "<title>" + escape_html(title) + "</title>\n";
    page += "<meta name=\"generator\" content=\"meshdiff " MESHDIFF_VERSION "\">\n<style>\n";
    page += assets::report_css();
    page +=
        "</style>\n</head>\n<body>\n<noscript>This report needs JavaScript; its data is in the "
        "meshdiff-report element of the page's source.</noscript>\n<main id=\"app\"></main>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-report\">" + dump(report) + "</script>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-meta\">" + dump(meta) + "</script>\n";
    page += "<script type=\"application/json\" id=\"meshdiff-view\">" + dump(view) + "</script>\n";
    page += "<script>\n";
    page += assets::three_js();
    page += "\n</script>\n<script>\n";
    page += assets::orbit_controls_js();
    page += "\n</script>\n<script>\n";
    page += assets::report_js();
    page += "\n</script>\n</body>\n</html>\n";
    return page;
}

}  // namespace

std::string comparison_html(const Comparison& c, const Mesh& original, const Mesh& processed,
                            const nlohmann::json& report, const HtmlOptions& o)
{
    check(o);
    const nlohmann::json view = view_json(fields_of(c), {{&original, "original"}, {&processed, "processed"}}, o,
                                          [&c] { return distance_color_range(c, kDefaultHtmlPercentile); });
    return page(fmt::format("meshdiff: {} vs {}", c.original.input.path, c.processed.input.path), report, o, view);
}

std::string profile_html(const RoughnessProfile& profile, const Mesh& mesh, const std::string& path,
                         const nlohmann::json& report, const HtmlOptions& o)
{
    check(o);
    std::vector<Field> fields;
    if (profile.H.size() == mesh.n_vertices()) {
        // As the vertex data map (vertex_maps.h profile_map()): the given R, else robust_symmetric_range(H).
        const bool given = o.color_range.has_value();
        fields.push_back({"H",
                          fmt::format("mean curvature H ({})", kUnitScaled),
                          {&profile.H},
                          given ? o.color_range->second : robust_symmetric_range(profile.H),
                          given ? "symmetric, given" : "symmetric, the 95th percentile of |H|"});
    }
    add_roughness_fields(fields, {&profile}, {mesh.n_vertices()});
    const nlohmann::json view = view_json(fields, {{&mesh, "mesh"}}, o, [] { return std::pair{0.0, 1.0}; });
    return page("meshdiff profile: " + path, report, o, view);
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

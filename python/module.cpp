// The Python module `meshdiff`: the library on numpy arrays (docs/python.md).
//
// Every function converts its arguments once (with the GIL held), releases the
// GIL for the computation and builds the Python result with the GIL held again.
// The dicts are the CLI's JSON reports (report/json.h) converted value by value,
// so the numbers are bit for bit those of `meshdiff ... --json`.
#include "convert.h"
#include "docs.h"
#include "interrupt.h"
#include "meshdiff/compare.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/roughness/corsini.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/version.h"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace meshdiff::python {
namespace {

// ---------------------------------------------------------------- DistanceIndex

// A digest of \p mesh's coordinates and faces: DistanceIndex::of() tells
// by it that a mesh given beside the index is the one it indexes.
std::uint64_t mesh_digest(const Mesh& mesh)
{
    const std::hash<std::string_view> hash;
    const std::size_t points =
        hash(std::string_view(reinterpret_cast<const char*>(mesh.points.data()), mesh.points.size() * sizeof(Vec3)));
    const std::size_t faces =
        hash(std::string_view(reinterpret_cast<const char*>(mesh.faces.data()), mesh.faces.size() * sizeof(Face)));
    return std::uint64_t(points) * 0x9E3779B97F4A7C15ULL ^ std::uint64_t(faces);
}

class DistanceIndex
{
public:
    DistanceIndex(const ArrayLike& V, const ArrayLike& F)
    {
        const LoadedMesh m = mesh_from(V, F, "V", "F");
        py::gil_scoped_release release;
        index_ = std::make_unique<ClosestPointIndex>(m.mesh);
        n_vertices_ = m.mesh.n_vertices();
        digest_ = mesh_digest(m.mesh);
    }

    py::tuple query(const ArrayLike& P, const py::object& threads) const
    {
        const std::vector<Vec3> points = points_from(P.object, "P", true);
        std::vector<ClosestPoint> c;
        {
            ThreadScope scope(threads);
            py::gil_scoped_release release;
            c = index_->closest_points(points);
        }
        const auto k = py::ssize_t(c.size());
        py::array_t<double> distance(k);
        py::array_t<std::int64_t> face(k);
        py::array_t<double> point({k, py::ssize_t(3)});
        for (std::size_t i = 0; i < c.size(); ++i) {
            distance.mutable_data()[i] = c[i].distance;
            face.mutable_data()[i] = std::int64_t(c[i].face);
            for (std::size_t j = 0; j < 3; ++j) point.mutable_data()[3 * i + j] = c[i].point[Eigen::Index(j)];
        }
        return py::make_tuple(distance, face, point);
    }

    //! The index, after checking that \p mesh (named \p which, given as
    //! \p keyword) is the mesh it was built of: the same vertex and face
    //! counts, coordinates and faces. Without the GIL.
    //! \throw BadArgument naming \p keyword otherwise.
    const ClosestPointIndex& of(const Mesh& mesh, const char* keyword, const char* which) const
    {
        if (mesh.n_vertices() != n_vertices_ || mesh.n_faces() != index_->n_faces())
            throw BadArgument(
                fmt::format("{}: the DistanceIndex is of a mesh with {} vertices and {} faces, the {} "
                            "has {} and {}",
                            keyword, n_vertices_, index_->n_faces(), which, mesh.n_vertices(), mesh.n_faces()));
        if (mesh_digest(mesh) != digest_)
            throw BadArgument(
                fmt::format("{}: the DistanceIndex is of another mesh than the {} (same vertex and face "
                            "counts, other coordinates or faces)",
                            keyword, which));
        return *index_;
    }

    std::size_t n_faces() const { return index_->n_faces(); }
    std::size_t memory_bytes() const { return index_->memory_bytes(); }
    py::tuple bounds() const
    {
        const BoundingBox b = index_->bounds();
        return py::make_tuple(points_array({b.min}).attr("reshape")(3), points_array({b.max}).attr("reshape")(3));
    }

private:
    std::unique_ptr<ClosestPointIndex> index_;
    std::size_t n_vertices_ = 0;
    std::uint64_t digest_ = 0;
};

// The keywords of compare() and compare_files() that only Python has: maps=
// and the caller's indexes (DistanceIndex or None).
struct PythonKeywords
{
    py::object maps, index_original, index_processed;
};

// The DistanceIndex given as \p keyword, or nullptr for None.
const DistanceIndex* index_arg(Obj v, const char* keyword)
{
    if (v.is_none()) return nullptr;
    if (!py::isinstance<DistanceIndex>(v))
        throw py::type_error(fmt::format("{}: expected a meshdiff.DistanceIndex or None, got {}", keyword,
                                         py::repr(v).cast<std::string>()));
    return &v.cast<const DistanceIndex&>();
}

// \p p's D per vertex as an (n, columns) array: the ring levels' columns and
// the global one (\p radii false), or the metric levels' (\p radii true).
py::array_t<double> d_array(const RoughnessProfile& p, bool radii)
{
    std::vector<const std::vector<double>*> columns;
    for (const auto& c : radii ? p.D_radii : p.D) columns.push_back(&c);
    if (!radii && p.has_global) columns.push_back(&p.D_global);
    const std::size_t n = p.vertices, k = columns.size();
    py::array_t<double> D({py::ssize_t(n), py::ssize_t(k)});
    double* d = D.mutable_data();
    for (std::size_t c = 0; c < k; ++c)
        for (std::size_t i = 0; i < n; ++i) d[i * k + c] = (*columns[c])[i];
    return D;
}

// compare(..., maps=True): the per-vertex arrays that \p c kept (docs/python.md).
py::dict maps_dict(const Comparison& c)
{
    py::dict maps;
    auto vector = [&](const char* key, const std::vector<double>& v) {
        if (!v.empty()) maps[key] = vector_array(v);
    };
    vector("distance_original", c.original_vertex_distance);
    vector("distance_processed", c.processed_vertex_distance);
    vector("signed_distance_original", c.original_vertex_signed_distance);
    vector("signed_distance_processed", c.processed_vertex_signed_distance);
    for (const auto& [side, p] : {std::pair{"original", &c.original_profile}, {"processed", &c.processed_profile}}) {
        if (!*p || (*p)->H.size() != (*p)->vertices) continue;  // no roughness, or its vertex data not kept
        maps[py::str(std::string("D_") + side)] = d_array(**p, false);
        if (!(*p)->radii.empty()) maps[py::str(std::string("D_radii_") + side)] = d_array(**p, true);
    }
    if (c.local_roughness && !c.local_roughness->vertex.empty()) {
        const LocalRoughnessDistance& l = *c.local_roughness;
        const std::size_t n = l.vertices, k = l.vertex.size();
        py::array_t<double> local({py::ssize_t(n), py::ssize_t(k)});
        for (std::size_t c2 = 0; c2 < k; ++c2)
            for (std::size_t i = 0; i < n; ++i) local.mutable_data()[i * k + c2] = l.vertex[c2][i];
        maps["local_processed"] = local;
    }
    return maps;
}

// ---------------------------------------------------------------- functions

py::object py_read_mesh(const py::object& path_obj, bool report)
{
    const std::string path = path_from(path_obj, "path");
    LoadedMesh m;
    {
        py::gil_scoped_release release;
        m = read_file(path);
    }
    py::tuple vf = py::make_tuple(points_array(m.mesh.points), faces_array(m.mesh.faces));
    if (!report) return std::move(vf);
    return py::make_tuple(vf[0], vf[1], input_report_dict(m));
}

// compare_meshes() with the outputs \p a asks for, as `meshdiff compare` runs it.
py::dict run_compare(const CompareKeywords& a, const PythonKeywords& extra,
                     const std::function<std::pair<LoadedMesh, LoadedMesh>()>& load, const std::string& original_name,
                     const std::string& processed_name, const std::vector<std::string>& inputs,
                     const std::string& command)
{
    CompareOutputs outputs = compare_outputs(a);
    outputs.command = command;  // shown by the HTML report
    const CompareOptions checked = compare_options(a);
    validate(outputs, checked, inputs);
    CompareOptions options = with_outputs(checked, outputs);
    const bool maps = flag(extra.maps, "maps", false);
    if (maps) {  // what the maps are made of (the report stays the same, bit for bit)
        options.vertex_distances = options.vertex_distances || options.distance;
        options.profile.keep_vertex_data = true;
    }
    const DistanceIndex* index_original = index_arg(extra.index_original, "index_original");
    const DistanceIndex* index_processed = index_arg(extra.index_processed, "index_processed");
    nlohmann::json j;
    std::optional<Comparison> kept;  // for the maps
    {
        ThreadScope scope(a.threads);
        py::gil_scoped_release release;
        const auto [original, processed] = load();
        if (index_original) options.index_original = &index_original->of(original.mesh, "index_original", "original");
        if (index_processed)
            options.index_processed = &index_processed->of(processed.mesh, "index_processed", "processed mesh");
        Comparison c = compare_meshes(original, processed, options);
        StagedOutputs staged;  // every output file, or none
        write_outputs(c, original, processed, outputs, original_name, processed_name);
        j = comparison_json(c);
        if (!outputs.json.empty()) write_json_file(outputs.json, j);
        staged.commit();
        if (maps) kept = std::move(c);
    }
    py::dict result = to_python(j);
    if (kept) result["maps"] = maps_dict(*kept);
    return result;
}

py::dict py_compare(const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2, const ArrayLike& F2,
                    const CompareKeywords& a, const PythonKeywords& extra)
{
    auto meshes = std::make_shared<std::pair<LoadedMesh, LoadedMesh>>(mesh_or_cloud_from(V1, F1, "V1", "F1"),
                                                                      mesh_or_cloud_from(V2, F2, "V2", "F2"));
    return run_compare(
        a, extra, [meshes] { return std::move(*meshes); }, "<array V1>", "<array V2>", {},
        "meshdiff.compare(V1, F1, V2, F2, ...) (Python)");
}

py::dict py_compare_files(Obj original, Obj processed, const CompareKeywords& a, const PythonKeywords& extra)
{
    const std::string pa = path_from(original, "original"), pb = path_from(processed, "processed");
    return run_compare(
        a, extra,
        [&] {
            return std::pair{read_file(pa, true), read_file(pb, true)};
        },
        pa, pb, {pa, pb}, "meshdiff.compare_files('" + pa + "', '" + pb + "', ...) (Python)");
}

py::dict run_profile(const ProfileKeywords& a, const std::function<LoadedMesh()>& load,
                     const std::vector<std::string>& inputs, const std::string& command)
{
    ProfileRequest r = profile_request(a);
    r.command = command;  // shown by the HTML report
    validate(r, inputs);
    nlohmann::json j;
    {
        ThreadScope scope(a.threads);
        py::gil_scoped_release release;
        StagedOutputs staged;  // every output file, or none
        const ProfileReport report = profile_report(load(), r);
        if (!r.json.empty()) write_json_file(r.json, report.json);
        staged.commit();
        j = report.json;
    }
    return to_python(j);
}

py::dict py_profile(const ArrayLike& V, const ArrayLike& F, const ProfileKeywords& a)
{
    auto mesh = std::make_shared<LoadedMesh>(mesh_from(V, F, "V", "F"));
    return run_profile(
        a, [mesh] { return std::move(*mesh); }, {}, "meshdiff.profile(V, F, ...) (Python)");
}

py::dict py_profile_file(Obj path_obj, const ProfileKeywords& a)
{
    const std::string path = path_from(path_obj, "path");
    return run_profile(
        a, [&] { return read_file(path); }, {path}, "meshdiff.profile_file('" + path + "', ...) (Python)");
}

py::dict py_corsini_profile(const ArrayLike& V, const ArrayLike& F, Obj levels, Obj global_level, Obj unbiased,
                            Obj threads)
{
    CorsiniOptions options;
    if (auto l = levels_arg(levels)) options.levels = std::move(*l);
    options.global = flag(global_level, "profile.global", options.global);
    options.unbiased = flag(unbiased, "corsini_unbiased", options.unbiased);
    validate(options);
    const LoadedMesh m = mesh_from(V, F, "V", "F");
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        j = corsini_profile_json(mesh_facts(m), corsini_profile(m.mesh, options));
    }
    return to_python(j);
}

py::array_t<double> py_mean_curvature(const ArrayLike& V, const ArrayLike& F, Obj method, Obj weighting,
                                      Obj min_neighbors, Obj max_normal_angle_deg, Obj threads)
{
    CurvatureOptions o;
    if (auto c = choice<CurvatureMethod>(method, "profile.curvature.method")) o.method = *c;
    if (auto w = choice<RowWeighting>(weighting, "profile.curvature.weighting")) o.weighting = *w;
    if (auto n = whole(min_neighbors, "min_neighbors"))
        o.min_neighbors = int(std::min<std::uint64_t>(*n, std::uint64_t(INT_MAX)));
    if (auto a = number(max_normal_angle_deg, "max_normal_angle_deg")) o.max_normal_angle_deg = *a;
    const LoadedMesh m = mesh_from(V, F, "V", "F");
    CurvatureField field;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        field = mean_curvature(m.mesh, o);
    }
    return vector_array(field.H);
}

py::tuple py_roughness(const ArrayLike& V, const ArrayLike& F, Obj levels, Obj global_level, Obj curvature,
                       Obj weighting, Obj normalize, Obj threads)
{
    ProfileOptions defaults;
    defaults.global = false;  // roughness(): the global column only when asked for
    ProfileOptions options = profile_options(levels, py::none(), global_level, curvature, weighting, defaults);
    if (auto n = choice<NormalizeMethod>(normalize, "profile.normalize")) options.normalize = *n;
    options.keep_vertex_data = true;
    validate(options);
    const LoadedMesh m = mesh_from(V, F, "V", "F");
    RoughnessProfile p;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        p = roughness_profile(m.mesh, options);
    }
    const std::size_t n = m.mesh.n_vertices(), columns = p.levels.size() + (p.has_global ? 1 : 0);
    py::array_t<double> D({py::ssize_t(n), py::ssize_t(columns)});
    py::array_t<double> sigma(static_cast<py::ssize_t>(columns));
    double* d = D.mutable_data();
    for (std::size_t c = 0; c < columns; ++c) {
        const bool global = c == p.levels.size();
        const std::vector<double>& column = global ? p.D_global : p.D[c];
        for (std::size_t i = 0; i < n; ++i) d[i * columns + c] = column[i];
        sigma.mutable_data()[c] = global ? p.global.sigma : p.levels[c].sigma;
    }
    return py::make_tuple(D, sigma);
}

py::dict py_surface_distance(const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2, const ArrayLike& F2,
                             Obj samples, Obj density, Obj face_sampling, Obj seed, Obj vertex_samples,
                             Obj edge_samples, Obj face_samples, Obj return_samples, Obj threads, Obj hausdorff,
                             Obj hausdorff_tolerance, Obj hausdorff_abs_tolerance, Obj hausdorff_budget)
{
    const SamplingOptions o =
        sampling_options(samples, density, face_sampling, seed, vertex_samples, edge_samples, face_samples);
    const bool with_samples = flag(return_samples, "return_samples", false);
    const std::optional<HausdorffOptions> certify =
        surface_distance_hausdorff(hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance, hausdorff_budget);
    const LoadedMesh a = mesh_from(V1, F1, "V1", "F1");
    const LoadedMesh b = mesh_from(V2, F2, "V2", "F2");
    DistanceOptions options;
    options.sampling = o;
    options.hausdorff = certify;
    options.keep_samples = with_samples;
    SurfaceDistance r;
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        r = surface_distance(a.mesh, b.mesh, options);
        j = surface_distance_json(r, o);
    }
    if (!with_samples) return to_python(j);
    py::dict out = to_python(j);
    out["forward"] = direction_dict(j["forward"], r.forward_samples);
    out["backward"] = direction_dict(j["backward"], r.backward_samples);
    return out;
}

py::array_t<double> py_vertex_distances(const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2,
                                        const ArrayLike& F2, Obj threads)
{
    const LoadedMesh a = mesh_from(V1, F1, "V1", "F1");
    const LoadedMesh b = mesh_from(V2, F2, "V2", "F2");
    std::vector<double> d;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        d = vertex_distances(a.mesh, ClosestPointIndex(b.mesh));
    }
    return vector_array(d);
}

// ---------------------------------------------------------------- bindings

// The RoughnessKeywords that compare() and profile() share.
RoughnessKeywords roughness_keywords(Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
                                     Obj unbiased_variance, Obj normalize, Obj trim, Obj bootstrap, Obj bootstrap_seed,
                                     Obj paper)
{
    RoughnessKeywords kw;
    kw.levels = levels;
    kw.radii = radii;
    kw.global_level = global_level;
    kw.curvature = curvature;
    kw.weighting = weighting;
    kw.measure = measure;
    kw.unbiased_variance = unbiased_variance;
    kw.normalize = normalize;
    kw.trim = trim;
    kw.bootstrap = bootstrap;
    kw.bootstrap_seed = bootstrap_seed;
    kw.paper = paper;
    return kw;
}

// The CompareKeywords of the keywords of compare() and compare_files().
CompareKeywords compare_keywords(Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
                                 Obj unbiased_variance, Obj normalize, Obj trim, Obj bootstrap, Obj bootstrap_seed,
                                 Obj paper, Obj local, Obj local_trim, Obj k, Obj roughness, Obj distance, Obj samples,
                                 Obj density, Obj face_sampling, Obj seed, Obj vertex_samples, Obj edge_samples,
                                 Obj face_samples, Obj hausdorff, Obj hausdorff_tolerance, Obj hausdorff_abs_tolerance,
                                 Obj hausdorff_budget, Obj fscore, Obj histogram, Obj json, Obj distance_map,
                                 Obj distance_map_original, Obj distance_maps, Obj samples_out, Obj html,
                                 Obj color_range, Obj html_face_budget, Obj threads)
{
    CompareKeywords kw;
    static_cast<RoughnessKeywords&>(kw) =
        roughness_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance, normalize,
                           trim, bootstrap, bootstrap_seed, paper);
    kw.local = local;
    kw.local_trim = local_trim;
    kw.k = k;
    kw.roughness = roughness;
    kw.distance = distance;
    kw.samples = samples;
    kw.density = density;
    kw.face_sampling = face_sampling;
    kw.seed = seed;
    kw.vertex_samples = vertex_samples;
    kw.edge_samples = edge_samples;
    kw.face_samples = face_samples;
    kw.hausdorff = hausdorff;
    kw.hausdorff_tolerance = hausdorff_tolerance;
    kw.hausdorff_abs_tolerance = hausdorff_abs_tolerance;
    kw.hausdorff_budget = hausdorff_budget;
    kw.fscore = fscore;
    kw.histogram = histogram;
    kw.json = json;
    kw.distance_map = distance_map;
    kw.distance_map_original = distance_map_original;
    kw.distance_maps = distance_maps;
    kw.samples_out = samples_out;
    kw.html = html;
    kw.color_range = color_range;
    kw.html_face_budget = html_face_budget;
    kw.threads = threads;
    return kw;
}

// The ProfileKeywords of the keywords of profile() and profile_file().
ProfileKeywords profile_keywords(Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
                                 Obj unbiased_variance, Obj normalize, Obj trim, Obj bootstrap, Obj bootstrap_seed,
                                 Obj paper, Obj json, Obj vertex_data, Obj html, Obj color_range, Obj exact,
                                 Obj exact_property, Obj html_face_budget, Obj threads)
{
    ProfileKeywords kw;
    static_cast<RoughnessKeywords&>(kw) =
        roughness_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance, normalize,
                           trim, bootstrap, bootstrap_seed, paper);
    kw.json = json;
    kw.vertex_data = vertex_data;
    kw.html = html;
    kw.color_range = color_range;
    kw.exact = exact;
    kw.exact_property = exact_property;
    kw.html_face_budget = html_face_budget;
    kw.threads = threads;
    return kw;
}

// The library's limits of the options: LIMITS (docs/python.md states them; a test checks them against these).
void add_limits(py::module_& m)
{
    py::dict limits;
    limits["levels"] = kMaxLevels;
    limits["level"] = kMaxLevel;
    limits["radii"] = kMaxRadii;
    limits["radius"] = kMaxRadius;
    limits["mean_ball_vertices"] = kMaxMeanBallVertices;
    limits["threads"] = kMaxThreads;
    limits["samples"] = kMaxSamples;
    limits["hausdorff_budget"] = kMaxHausdorffBudget;
    limits["hausdorff_tolerance"] = py::make_tuple(kMinHausdorffTolerance, kMaxHausdorffTolerance);
    limits["fscore"] = kMaxFscoreThresholds;
    limits["fscore_threshold"] = kMaxFscoreThreshold;
    limits["histogram"] = kMaxHistogramBins;
    m.attr("LIMITS") = limits;
}

// read_mesh().
void def_reading(py::module_& m)
{
    m.def("read_mesh", &py_read_mesh, kReadMeshDoc, py::arg("path"), py::kw_only(), py::arg("report") = false);
}

// Registers \p name (compare() or compare_files()): its leading arguments
// \p lead, then the keywords of every compare option with their defaults, one
// list for both functions.
template <class F, class... Lead>
void def_compare_like(py::module_& m, const char* name, F&& f, const std::string& doc, Lead... lead)
{
    const CompareOptions defaults;
    m.def(name, std::forward<F>(f), doc.c_str(), lead..., py::kw_only(), py::arg("levels") = py::none(),
          py::arg("radii") = py::none(), py::arg("global_level") = py::bool_(defaults.profile.global),
          py::arg("curvature") = py::none(), py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
          py::arg("unbiased_variance") = py::bool_(defaults.corsini_unbiased), py::arg("normalize") = py::none(),
          py::arg("trim") = py::none(), py::arg("bootstrap") = py::none(), py::arg("bootstrap_seed") = py::none(),
          py::arg("paper") = py::bool_(false), py::arg("local") = py::bool_(defaults.local),
          py::arg("local_trim") = py::none(), py::arg("k") = py::none(),
          py::arg("roughness") = py::bool_(defaults.roughness), py::arg("distance") = py::bool_(defaults.distance),
          py::arg("samples") = py::none(), py::arg("density") = py::none(), py::arg("face_sampling") = py::none(),
          py::arg("seed") = py::none(), py::arg("vertex_samples") = py::bool_(defaults.sampling.vertices),
          py::arg("edge_samples") = py::bool_(defaults.sampling.edges),
          py::arg("face_samples") = py::bool_(defaults.sampling.faces), py::arg("hausdorff") = py::none(),
          py::arg("hausdorff_tolerance") = py::none(), py::arg("hausdorff_abs_tolerance") = py::none(),
          py::arg("hausdorff_budget") = py::none(), py::arg("fscore") = py::none(), py::arg("histogram") = py::none(),
          py::arg("json") = py::none(), py::arg("distance_map") = py::none(),
          py::arg("distance_map_original") = py::none(), py::arg("distance_maps") = py::none(),
          py::arg("samples_out") = py::none(), py::arg("html") = py::none(), py::arg("color_range") = py::none(),
          py::arg("html_face_budget") = py::none(), py::arg("threads") = py::none(), py::arg("maps") = py::bool_(false),
          py::arg("index_original") = py::none(), py::arg("index_processed") = py::none());
}

// compare() and compare_files().
void def_compare(py::module_& m)
{
    const std::string compare_doc = std::string(kCompareDoc) + kCompareOptionsDoc;
    const std::string compare_files_doc = std::string(kCompareFilesDoc) + kCompareOptionsDoc;
    def_compare_like(
        m, "compare",
        [](const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2, const ArrayLike& F2, Obj levels, Obj radii,
           Obj global_level, Obj curvature, Obj weighting, Obj measure, Obj unbiased_variance, Obj normalize, Obj trim,
           Obj bootstrap, Obj bootstrap_seed, Obj paper, Obj local, Obj local_trim, Obj k, Obj roughness, Obj distance,
           Obj samples, Obj density, Obj face_sampling, Obj seed, Obj vertex_samples, Obj edge_samples,
           Obj face_samples, Obj hausdorff, Obj hausdorff_tolerance, Obj hausdorff_abs_tolerance, Obj hausdorff_budget,
           Obj fscore, Obj histogram, Obj json, Obj distance_map, Obj distance_map_original, Obj distance_maps,
           Obj samples_out, Obj html, Obj color_range, Obj html_face_budget, Obj threads, Obj maps, Obj index_original,
           Obj index_processed) {
            return py_compare(
                V1, F1, V2, F2,
                compare_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance,
                                 normalize, trim, bootstrap, bootstrap_seed, paper, local, local_trim, k, roughness,
                                 distance, samples, density, face_sampling, seed, vertex_samples, edge_samples,
                                 face_samples, hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance,
                                 hausdorff_budget, fscore, histogram, json, distance_map, distance_map_original,
                                 distance_maps, samples_out, html, color_range, html_face_budget, threads),
                PythonKeywords{maps, index_original, index_processed});
        },
        compare_doc, py::arg("V1"), py::arg("F1"), py::arg("V2"), py::arg("F2"));
    def_compare_like(
        m, "compare_files",
        [](Obj original, Obj processed, Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting,
           Obj measure, Obj unbiased_variance, Obj normalize, Obj trim, Obj bootstrap, Obj bootstrap_seed, Obj paper,
           Obj local, Obj local_trim, Obj k, Obj roughness, Obj distance, Obj samples, Obj density, Obj face_sampling,
           Obj seed, Obj vertex_samples, Obj edge_samples, Obj face_samples, Obj hausdorff, Obj hausdorff_tolerance,
           Obj hausdorff_abs_tolerance, Obj hausdorff_budget, Obj fscore, Obj histogram, Obj json, Obj distance_map,
           Obj distance_map_original, Obj distance_maps, Obj samples_out, Obj html, Obj color_range,
           Obj html_face_budget, Obj threads, Obj maps, Obj index_original, Obj index_processed) {
            return py_compare_files(
                original, processed,
                compare_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance,
                                 normalize, trim, bootstrap, bootstrap_seed, paper, local, local_trim, k, roughness,
                                 distance, samples, density, face_sampling, seed, vertex_samples, edge_samples,
                                 face_samples, hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance,
                                 hausdorff_budget, fscore, histogram, json, distance_map, distance_map_original,
                                 distance_maps, samples_out, html, color_range, html_face_budget, threads),
                PythonKeywords{maps, index_original, index_processed});
        },
        compare_files_doc, py::arg("original"), py::arg("processed"));
}

// profile() and profile_file().
void def_profile(py::module_& m)
{
    const std::string profile_doc = std::string(kProfileDoc) + kProfileOptionsDoc;
    const std::string profile_file_doc = std::string(kProfileFileDoc) + kProfileOptionsDoc;
    const ProfileRequest pdefaults;
    m.def(
        "profile",
        [](const ArrayLike& V, const ArrayLike& F, Obj levels, Obj radii, Obj global_level, Obj curvature,
           Obj weighting, Obj measure, Obj unbiased_variance, Obj normalize, Obj trim, Obj bootstrap,
           Obj bootstrap_seed, Obj paper, Obj json, Obj vertex_data, Obj html, Obj color_range, Obj exact,
           Obj exact_property, Obj html_face_budget, Obj threads) {
            return py_profile(
                V, F,
                profile_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance,
                                 normalize, trim, bootstrap, bootstrap_seed, paper, json, vertex_data, html,
                                 color_range, exact, exact_property, html_face_budget, threads));
        },
        profile_doc.c_str(), py::arg("V"), py::arg("F"), py::kw_only(), py::arg("levels") = py::none(),
        py::arg("radii") = py::none(), py::arg("global_level") = py::bool_(pdefaults.profile.global),
        py::arg("curvature") = py::none(), py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
        py::arg("unbiased_variance") = py::bool_(pdefaults.corsini_unbiased), py::arg("normalize") = py::none(),
        py::arg("trim") = py::none(), py::arg("bootstrap") = py::none(), py::arg("bootstrap_seed") = py::none(),
        py::arg("paper") = py::bool_(false), py::arg("json") = py::none(), py::arg("vertex_data") = py::none(),
        py::arg("html") = py::none(), py::arg("color_range") = py::none(),
        py::arg("exact") = py::bool_(pdefaults.exact), py::arg("exact_property") = py::none(),
        py::arg("html_face_budget") = py::none(), py::arg("threads") = py::none());
    m.def(
        "profile_file",
        [](Obj path, Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
           Obj unbiased_variance, Obj normalize, Obj trim, Obj bootstrap, Obj bootstrap_seed, Obj paper, Obj json,
           Obj vertex_data, Obj html, Obj color_range, Obj exact, Obj exact_property, Obj html_face_budget,
           Obj threads) {
            return py_profile_file(
                path, profile_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance,
                                       normalize, trim, bootstrap, bootstrap_seed, paper, json, vertex_data, html,
                                       color_range, exact, exact_property, html_face_budget, threads));
        },
        profile_file_doc.c_str(), py::arg("path"), py::kw_only(), py::arg("levels") = py::none(),
        py::arg("radii") = py::none(), py::arg("global_level") = py::bool_(pdefaults.profile.global),
        py::arg("curvature") = py::none(), py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
        py::arg("unbiased_variance") = py::bool_(pdefaults.corsini_unbiased), py::arg("normalize") = py::none(),
        py::arg("trim") = py::none(), py::arg("bootstrap") = py::none(), py::arg("bootstrap_seed") = py::none(),
        py::arg("paper") = py::bool_(false), py::arg("json") = py::none(), py::arg("vertex_data") = py::none(),
        py::arg("html") = py::none(), py::arg("color_range") = py::none(),
        py::arg("exact") = py::bool_(pdefaults.exact), py::arg("exact_property") = py::none(),
        py::arg("html_face_budget") = py::none(), py::arg("threads") = py::none());
}

// corsini_profile(), mean_curvature() and roughness().
void def_roughness(py::module_& m)
{
    m.def("corsini_profile", &py_corsini_profile, kCorsiniProfileDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = py::none(), py::arg("global_level") = py::bool_(true),
          py::arg("unbiased") = py::bool_(false), py::arg("threads") = py::none());
    m.def("mean_curvature", &py_mean_curvature, kMeanCurvatureDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("method") = py::none(), py::arg("weighting") = py::none(), py::arg("min_neighbors") = py::none(),
          py::arg("max_normal_angle_deg") = py::none(), py::arg("threads") = py::none());
    m.def("roughness", &py_roughness, kRoughnessDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = py::none(), py::arg("global_level") = py::bool_(false), py::arg("curvature") = py::none(),
          py::arg("weighting") = py::none(), py::arg("normalize") = py::none(), py::arg("threads") = py::none());
}

// surface_distance() and vertex_distances().
void def_distances(py::module_& m)
{
    m.def("surface_distance", &py_surface_distance, kSurfaceDistanceDoc, py::arg("V1"), py::arg("F1"), py::arg("V2"),
          py::arg("F2"), py::kw_only(), py::arg("samples") = py::none(), py::arg("density") = py::none(),
          py::arg("face_sampling") = py::none(), py::arg("seed") = py::none(),
          py::arg("vertex_samples") = py::bool_(true), py::arg("edge_samples") = py::bool_(true),
          py::arg("face_samples") = py::bool_(true), py::arg("return_samples") = py::bool_(false),
          py::arg("threads") = py::none(), py::arg("hausdorff") = py::none(),
          py::arg("hausdorff_tolerance") = py::none(), py::arg("hausdorff_abs_tolerance") = py::none(),
          py::arg("hausdorff_budget") = py::none());
    m.def("vertex_distances", &py_vertex_distances, kVertexDistancesDoc, py::arg("V1"), py::arg("F1"), py::arg("V2"),
          py::arg("F2"), py::kw_only(), py::arg("threads") = py::none());
}

// The class DistanceIndex.
void def_distance_index(py::module_& m)
{
    py::class_<DistanceIndex>(m, "DistanceIndex", kDistanceIndexDoc)
        .def(py::init<const ArrayLike&, const ArrayLike&>(), py::arg("V"), py::arg("F"))
        .def("query", &DistanceIndex::query, kQueryDoc, py::arg("P"), py::kw_only(), py::arg("threads") = py::none())
        .def_property_readonly("n_faces", &DistanceIndex::n_faces, kNFacesDoc)
        .def_property_readonly("bounds", &DistanceIndex::bounds, kBoundsDoc)
        .def_property_readonly("memory_bytes", &DistanceIndex::memory_bytes, kMemoryBytesDoc)
        .def("__repr__", [](const DistanceIndex& d) {
            return "<meshdiff.DistanceIndex over " + std::to_string(d.n_faces()) + " triangles>";
        });
}

}  // namespace
}  // namespace meshdiff::python

PYBIND11_MODULE(_meshdiff, m)
{
    using namespace meshdiff::python;
    m.doc() = kModuleDoc;
    m.attr("__version__") = MESHDIFF_VERSION;
    m.attr("SAMPLE_KINDS") = py::make_tuple("vertex", "edge", "face", "point");
    py::register_exception_translator(translate_exceptions);
    add_limits(m);
    def_reading(m);
    def_compare(m);
    def_profile(m);
    def_roughness(m);
    def_distances(m);
    def_distance_index(m);
    def_progress(m);
}

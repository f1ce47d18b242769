// The Python module `meshdiff`: the library on numpy arrays (docs/python.md).
//
// Every function converts its arguments once (with the GIL held), releases the
// GIL for the computation and builds the Python result with the GIL held again.
// The dicts are the CLI's JSON reports (report/json.h) converted value by value,
// so the numbers are bit for bit those of `meshdiff ... --json`.
#include "meshdiff/closest_point.h"
#include "meshdiff/compare.h"
#include "meshdiff/corsini.h"
#include "meshdiff/curvature.h"
#include "meshdiff/error.h"
#include "meshdiff/facts.h"
#include "meshdiff/io.h"
#include "meshdiff/metric_levels.h"
#include "meshdiff/report/json.h"
#include "meshdiff/roughness.h"
#include "meshdiff/surface_distance.h"
#include "meshdiff/version.h"

#include <fmt/format.h>
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
using namespace meshdiff;

// An argument that numpy can make an array of (an ndarray, a list of lists,
// ...): taken as is and checked by the function, so that a wrong shape or dtype
// is a ValueError naming the argument; shown as numpy.typing.ArrayLike.
struct ArrayLike
{
    py::object object;
};

namespace pybind11::detail {
template <>
struct type_caster<ArrayLike>
{
    PYBIND11_TYPE_CASTER(ArrayLike, const_name("numpy.typing.ArrayLike"));
    bool load(handle src, bool /*convert*/)
    {
        value.object = reinterpret_borrow<object>(src);
        return true;
    }
    static handle cast(const ArrayLike& a, return_value_policy /*policy*/, handle /*parent*/)
    {
        return a.object.inc_ref();
    }
};
}  // namespace pybind11::detail

namespace {

// ---------------------------------------------------------------- errors

// A missing file: raised as FileNotFoundError(ENOENT, message, path).
struct FileMissing
{
    std::string message;
    std::string path;
};

// An argument with the wrong shape, type or values: ValueError.
struct BadArgument : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

void translate_exceptions(std::exception_ptr p)
{
    try {
        if (p) std::rethrow_exception(p);
    } catch (const FileMissing& e) {
        const py::tuple args = py::make_tuple(ENOENT, e.message, e.path);
        PyErr_SetObject(PyExc_FileNotFoundError, args.ptr());
    } catch (const BadArgument& e) {
        PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const IoError& e) {
        PyErr_SetString(PyExc_OSError, e.what());
    } catch (const InvalidMeshError& e) {
        PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InvalidArgumentError& e) {
        PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SolverError& e) {
        PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const Error& e) {
        PyErr_SetString(PyExc_RuntimeError, e.what());
    }
}

[[noreturn]] void bad(const std::string& message)
{
    throw BadArgument(message);
}

// ---------------------------------------------------------------- threads

// Sets the OpenMP thread count of the calling thread for one call (0: leave
// the default, all cores or OMP_NUM_THREADS, as the CLI does) and restores it.
class ThreadScope
{
public:
    explicit ThreadScope(int threads) : saved_(omp_get_max_threads())
    {
        if (threads < 0) bad("threads: " + std::to_string(threads) + " must be >= 0 (0: all cores)");
        if (threads > 0) omp_set_num_threads(threads);
    }
    ~ThreadScope() { omp_set_num_threads(saved_); }
    ThreadScope(const ThreadScope&) = delete;
    ThreadScope& operator=(const ThreadScope&) = delete;

private:
    int saved_;
};

// ---------------------------------------------------------------- arrays in

// "(2, 4)", as numpy prints a shape.
std::string shape_text(const py::array& a)
{
    return std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim())))));
}

char dtype_kind(const py::array& a)
{
    return a.dtype().kind();
}

// A numpy array of \p obj (no copy when it already is one).
py::array as_array(const py::handle& obj, const char* name)
{
    py::array a = py::array::ensure(obj);
    if (!a) {
        PyErr_Clear();
        bad(std::string(name) + ": cannot be converted to a numpy array");
    }
    return a;
}

// The rows of an (n, 3) array of numbers as points.
std::vector<Vec3> points_from(const py::handle& obj, const char* name, bool allow_empty = false)
{
    const py::array a = as_array(obj, name);
    const char kind = dtype_kind(a);
    if (kind != 'f' && kind != 'i' && kind != 'u')
        bad(std::string(name) + ": expected a float array of shape (n, 3), got dtype " +
            std::string(py::str(a.dtype())));
    if (a.ndim() != 2 || a.shape(1) != 3) bad(std::string(name) + ": expected shape (n, 3), got " + shape_text(a));
    if (a.shape(0) == 0 && !allow_empty) bad(std::string(name) + ": no vertices (shape (0, 3))");
    // One conversion to contiguous float64 (float32, integers, strided views).
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) {
        PyErr_Clear();
        bad(std::string(name) + ": cannot be converted to float64");
    }
    const auto n = std::size_t(d.shape(0));
    const double* x = d.data();
    std::vector<Vec3> p(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double v = x[3 * i + std::size_t(c)];
            if (!std::isfinite(v))
                bad(std::string(name) + ": coordinate " + std::to_string(c) + " of row " + std::to_string(i) + " is " +
                    (std::isnan(v) ? "NaN" : "infinite"));
        }
        p[i] = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    }
    return p;
}

// The rows of an (m, 3) integer array as faces of a mesh with \p n_vertices.
std::vector<Face> faces_from(const py::handle& obj, const char* name, std::size_t n_vertices)
{
    const py::array a = as_array(obj, name);
    const char kind = dtype_kind(a);
    if (kind != 'i' && kind != 'u')
        bad(std::string(name) + ": expected an integer array of shape (m, 3), got dtype " +
            std::string(py::str(a.dtype())));
    if (a.ndim() != 2 || a.shape(1) != 3) bad(std::string(name) + ": expected shape (m, 3), got " + shape_text(a));
    if (a.shape(0) == 0) bad(std::string(name) + ": no faces (shape (0, 3))");
    if (kind == 'u' && a.itemsize() == 8) {
        // uint64 indices above INT64_MAX would wrap in the int64 conversion.
        const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
        for (py::ssize_t i = 0; i < u.size(); ++i)
            if (u.data()[i] >= n_vertices)
                bad(std::string(name) + ": row " + std::to_string(i / 3) + " has vertex index " +
                    std::to_string(u.data()[i]) + ", out of range [0, " + std::to_string(n_vertices) + ")");
    }
    const auto d = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) {
        PyErr_Clear();
        bad(std::string(name) + ": cannot be converted to int64");
    }
    const auto m = std::size_t(d.shape(0));
    const std::int64_t* x = d.data();
    std::vector<Face> f(m);
    for (std::size_t i = 0; i < m; ++i)
        for (int c = 0; c < 3; ++c) {
            const std::int64_t v = x[3 * i + std::size_t(c)];
            if (v < 0 || std::uint64_t(v) >= n_vertices)
                bad(std::string(name) + ": row " + std::to_string(i) + " has vertex index " + std::to_string(v) +
                    ", out of range [0, " + std::to_string(n_vertices) + ")");
            f[i][std::size_t(c)] = std::int32_t(v);
        }
    return f;
}

// A mesh from V and F as a LoadedMesh whose "file" is the array (the reports
// name it "<array V>"); no input hygiene (arrays are used as given).
LoadedMesh mesh_from(const ArrayLike& V, const ArrayLike& F, const char* vname, const char* fname)
{
    LoadedMesh m;
    m.mesh.points = points_from(V.object, vname);
    if (m.mesh.points.size() > std::size_t(std::numeric_limits<std::int32_t>::max()))
        bad(std::string(vname) + ": more than 2^31 - 1 vertices");
    m.mesh.faces = faces_from(F.object, fname, m.mesh.points.size());
    m.input.path = std::string("<array ") + vname + ">";
    m.input.file_vertices = m.mesh.n_vertices();
    m.input.file_faces = m.mesh.n_faces();
    return m;
}

// For compare: F None or an empty (0, 3) array makes V a point cloud
// (cloud_distance.h); else mesh_from().
LoadedMesh mesh_or_cloud_from(const ArrayLike& V, const ArrayLike& F, const char* vname, const char* fname)
{
    bool cloud = F.object.is_none();
    if (!cloud) {
        const py::array f = as_array(F.object, fname);
        cloud = f.ndim() == 2 && f.shape(0) == 0 && f.shape(1) == 3;
    }
    if (!cloud) return mesh_from(V, F, vname, fname);
    LoadedMesh m;
    m.mesh.points = points_from(V.object, vname);
    m.input.path = std::string("<array ") + vname + ">";
    m.input.file_vertices = m.mesh.n_vertices();
    m.input.point_cloud = true;
    return m;
}

std::string path_from(const py::handle& obj, const char* name)
{
    try {
        return py::module_::import("os").attr("fsdecode")(obj).cast<std::string>();
    } catch (const py::error_already_set&) {
        throw py::type_error(std::string(name) + ": expected a path (str, bytes or os.PathLike)");
    }
}

// read_mesh() (read_mesh_or_cloud() with \p cloud) with a missing file as
// FileMissing (FileNotFoundError).
LoadedMesh read_file(const std::string& path, bool cloud = false)
{
    try {
        return cloud ? read_mesh_or_cloud(path) : read_mesh(path);
    } catch (const IoError& e) {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) throw FileMissing{"no such file", path};
        throw;
    }
}

// ---------------------------------------------------------------- options

// Levels from any iterable of integers (list, range, numpy array; no numpy
// needed, so compare_files() and profile_file() work without it).
std::vector<int> levels_from(const py::handle& obj)
{
    const std::string expected = "levels: expected a sequence of ints such as range(1, 21) or [1, 5, 20], got ";
    if (py::isinstance<py::str>(obj) || py::isinstance<py::bytes>(obj) || !py::isinstance<py::iterable>(obj))
        bad(expected + std::string(py::repr(obj)));
    std::vector<int> levels;
    for (const py::handle item : py::reinterpret_borrow<py::iterable>(obj)) {
        const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(item.ptr()));
        if (!index) {
            PyErr_Clear();
            bad(expected + "the item " + std::string(py::repr(item)));
        }
        int overflow = 0;
        const long long l = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
        if (overflow != 0 || l < 1 || l > 100000)
            bad("levels: level " + std::string(py::str(index)) + " is out of 1..100000");
        levels.push_back(int(l));
    }
    return levels;
}

// None, "default" (default_radii()) or a sequence of numbers > 0.
std::vector<double> radii_from(const py::handle& obj)
{
    if (obj.is_none()) return {};
    if (py::isinstance<py::str>(obj)) {
        if (obj.cast<std::string>() == "default") return default_radii();
        bad("radii: expected None, \"default\" or a sequence of numbers > 0, got " + std::string(py::str(obj)));
    }
    if (!py::isinstance<py::sequence>(obj))
        bad("radii: expected None, \"default\" or a sequence of numbers > 0, got " + std::string(py::str(obj)));
    std::vector<double> radii;
    for (const auto& item : obj.cast<py::sequence>()) {
        if (!py::isinstance<py::float_>(item) && !py::isinstance<py::int_>(item))
            bad("radii: " + std::string(py::str(item)) + " is not a number");
        const double r = item.cast<double>();
        if (!(r > 0.0) || !std::isfinite(r))
            bad("radii: radius " + std::string(py::str(item)) + " is not finite and > 0");
        radii.push_back(r);
    }
    return radii;
}

ProfileOptions profile_options(const py::handle& levels, bool global_level, const std::string& curvature,
                               const std::string& weighting, bool keep_vertex_data, std::vector<double> radii = {})
{
    ProfileOptions p;
    p.levels = levels_from(levels);
    p.radii = std::move(radii);
    p.global = global_level;
    p.curvature.method = parse_enum<CurvatureMethod>(curvature);
    p.curvature.weighting = parse_enum<RowWeighting>(weighting);
    p.keep_vertex_data = keep_vertex_data;
    if (p.levels.empty() && p.radii.empty() && !p.global)
        bad("levels: empty and global_level=False: nothing to compute");
    return p;
}

// The sampling options as the CLI's to_compare_options() sets them.
SamplingOptions sampling_options(const std::optional<long long>& samples, const std::optional<double>& density,
                                 const std::string& face_sampling, std::uint64_t seed, bool vertex_samples,
                                 bool edge_samples, bool face_samples)
{
    SamplingOptions s;
    if (samples) {
        if (*samples <= 0)
            bad("samples: " + std::to_string(*samples) + " must be > 0 (None: 10 x the larger face count)");
        s.samples = std::size_t(*samples);
    }
    if (density) {
        if (!(*density > 0.0) || !std::isfinite(*density)) bad("density: must be finite and > 0");
        s.density = *density;
    }
    if (s.samples && s.density) bad("samples and density exclude each other");
    s.face_scheme = parse_enum<FaceSampling>(face_sampling);
    s.seed = seed;
    s.vertices = vertex_samples;
    s.edges = edge_samples;
    s.faces = face_samples;
    validate(s);
    return s;
}

// ---------------------------------------------------------------- results out

// nlohmann::json to Python: object -> dict, array -> list, float -> float,
// integers -> int, bool -> bool, null -> None, string -> str.
py::object to_python(const nlohmann::json& j)
{
    switch (j.type()) {
        case nlohmann::json::value_t::null:
            return py::none();
        case nlohmann::json::value_t::boolean:
            return py::bool_(j.get<bool>());
        case nlohmann::json::value_t::number_integer:
            return py::int_(j.get<std::int64_t>());
        case nlohmann::json::value_t::number_unsigned:
            return py::int_(j.get<std::uint64_t>());
        case nlohmann::json::value_t::number_float:
            return py::float_(j.get<double>());
        case nlohmann::json::value_t::string:
            return py::str(j.get_ref<const std::string&>());
        case nlohmann::json::value_t::array: {
            py::list l(j.size());
            std::size_t i = 0;
            for (const auto& v : j) l[i++] = to_python(v);
            return std::move(l);
        }
        case nlohmann::json::value_t::object: {
            py::dict d;
            for (const auto& item : j.items()) d[py::str(item.key())] = to_python(item.value());
            return std::move(d);
        }
        default:
            throw std::runtime_error("meshdiff: a JSON value of an unexpected type (binary or discarded)");
    }
}

py::array_t<double> vector_array(const std::vector<double>& v)
{
    py::array_t<double> a(py::ssize_t(v.size()));
    if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(double));
    return a;
}

py::array_t<double> points_array(const std::vector<Vec3>& p)
{
    py::array_t<double> a({py::ssize_t(p.size()), py::ssize_t(3)});
    double* x = a.mutable_data();
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) x[3 * i + c] = p[i][Eigen::Index(c)];
    return a;
}

py::array_t<std::int32_t> faces_array(const std::vector<Face>& f)
{
    py::array_t<std::int32_t> a({py::ssize_t(f.size()), py::ssize_t(3)});
    std::int32_t* x = a.mutable_data();
    for (std::size_t i = 0; i < f.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) x[3 * i + c] = f[i][c];
    return a;
}

py::dict input_report_dict(const LoadedMesh& m)
{
    py::dict d;
    d["path"] = m.input.path;
    d["file_vertices"] = m.input.file_vertices;
    d["file_faces"] = m.input.file_faces;
    d["unreferenced_vertices_removed"] = m.input.unreferenced_vertices;
    d["polygons_triangulated"] = m.input.polygons_triangulated;
    d["repeated_index_faces_removed"] = m.input.repeated_index_faces;
    py::dict scalars;
    for (const VertexScalar& s : m.vertex_scalars) scalars[py::str(s.name)] = vector_array(s.values);
    d["vertex_scalars"] = scalars;
    return d;
}

py::dict direction_dict(const nlohmann::json& stats, const SampledDirection& d)
{
    py::dict out = to_python(stats);
    const SurfaceSamples& s = d.samples;
    out["points"] = points_array(s.points);
    out["distances"] = vector_array(d.distances);
    // Positive outside the other surface; None when it cannot be signed against.
    out["signed_distances"] = d.signed_distances.empty() ? py::object(py::none()) : vector_array(d.signed_distances);
    py::array_t<std::uint8_t> kinds(py::ssize_t(s.size()));
    py::array_t<std::int64_t> elements(py::ssize_t(s.size()));
    for (std::size_t i = 0; i < s.size(); ++i) {
        kinds.mutable_data()[i] = std::uint8_t(s.kind[i]);
        elements.mutable_data()[i] = std::int64_t(s.element[i]);
    }
    out["kinds"] = kinds;
    out["elements"] = elements;
    return out;
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

CompareOptions compare_options(const py::object& levels, const py::object& radii, bool global_level,
                               const std::string& curvature, const std::string& weighting, double k, bool roughness,
                               bool distance, const std::optional<long long>& samples,
                               const std::optional<double>& density, const std::string& face_sampling,
                               std::uint64_t seed, bool vertex_samples, bool edge_samples, bool face_samples,
                               const std::string& hausdorff, double hausdorff_tolerance,
                               const std::optional<double>& hausdorff_abs_tolerance,
                               const std::optional<std::vector<double>>& fscore, long long histogram)
{
    CompareOptions c;
    if (fscore) c.summary.fscore_thresholds = *fscore;
    if (histogram < 0 || histogram > (long long)kMaxHistogramBins)
        bad(fmt::format("histogram: {} is outside [0, {}]", histogram, kMaxHistogramBins));
    c.summary.histogram_bins = std::size_t(histogram);
    try {
        validate(c.summary);
    } catch (const InvalidArgumentError& e) {
        bad(fmt::format("fscore: {}", e.what()));
    }
    c.profile = profile_options(levels, global_level, curvature, weighting, false, radii_from(radii));
    if (!(k > 0.0) || !std::isfinite(k)) bad(fmt::format("k: {} must be finite and > 0", k));
    c.k = k;
    c.roughness = roughness;
    c.distance = distance;
    if (!roughness && !distance) bad("roughness=False and distance=False: nothing to compare");
    c.sampling = sampling_options(samples, density, face_sampling, seed, vertex_samples, edge_samples, face_samples);
    if (hausdorff == "sampled") {
        c.hausdorff.reset();
    } else if (hausdorff == "certified") {
        c.hausdorff->relative_tolerance = hausdorff_abs_tolerance ? 0.0 : hausdorff_tolerance;
        c.hausdorff->absolute_tolerance = hausdorff_abs_tolerance.value_or(0.0);
        if (!(hausdorff_tolerance >= 1e-12 && hausdorff_tolerance <= 0.5))
            bad(fmt::format("hausdorff_tolerance: {} is outside [1e-12, 0.5]", hausdorff_tolerance));
        if (hausdorff_abs_tolerance && !(*hausdorff_abs_tolerance > 0.0 && std::isfinite(*hausdorff_abs_tolerance)))
            bad(fmt::format("hausdorff_abs_tolerance: {} must be finite and > 0", *hausdorff_abs_tolerance));
    } else {
        bad(fmt::format("hausdorff: '{}' is not certified or sampled", hausdorff));
    }
    return c;
}

py::dict run_compare(const LoadedMesh& a, const LoadedMesh& b, const CompareOptions& options, int threads)
{
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        j = comparison_json(compare_meshes(a, b, options));
    }
    return to_python(j);
}

py::dict py_compare(const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2, const ArrayLike& F2,
                    const py::object& levels, const py::object& radii, bool global_level, const std::string& curvature,
                    const std::string& weighting, double k, bool roughness, bool distance,
                    const std::optional<long long>& samples, const std::optional<double>& density,
                    const std::string& face_sampling, std::uint64_t seed, bool vertex_samples, bool edge_samples,
                    bool face_samples, const std::string& hausdorff, double hausdorff_tolerance,
                    const std::optional<double>& hausdorff_abs_tolerance,
                    const std::optional<std::vector<double>>& fscore, long long histogram, int threads)
{
    const CompareOptions options =
        compare_options(levels, radii, global_level, curvature, weighting, k, roughness, distance, samples, density,
                        face_sampling, seed, vertex_samples, edge_samples, face_samples, hausdorff, hausdorff_tolerance,
                        hausdorff_abs_tolerance, fscore, histogram);
    const LoadedMesh a = mesh_or_cloud_from(V1, F1, "V1", "F1");
    const LoadedMesh b = mesh_or_cloud_from(V2, F2, "V2", "F2");
    return run_compare(a, b, options, threads);
}

py::dict py_compare_files(const py::object& original, const py::object& processed, const py::object& levels,
                          const py::object& radii, bool global_level, const std::string& curvature,
                          const std::string& weighting, double k, bool roughness, bool distance,
                          const std::optional<long long>& samples, const std::optional<double>& density,
                          const std::string& face_sampling, std::uint64_t seed, bool vertex_samples, bool edge_samples,
                          bool face_samples, const std::string& hausdorff, double hausdorff_tolerance,
                          const std::optional<double>& hausdorff_abs_tolerance,
                          const std::optional<std::vector<double>>& fscore, long long histogram, int threads)
{
    const CompareOptions options =
        compare_options(levels, radii, global_level, curvature, weighting, k, roughness, distance, samples, density,
                        face_sampling, seed, vertex_samples, edge_samples, face_samples, hausdorff, hausdorff_tolerance,
                        hausdorff_abs_tolerance, fscore, histogram);
    const std::string pa = path_from(original, "original"), pb = path_from(processed, "processed");
    LoadedMesh a, b;
    {
        py::gil_scoped_release release;
        a = read_file(pa, true);
        b = read_file(pb, true);
    }
    return run_compare(a, b, options, threads);
}

py::dict run_profile(const LoadedMesh& m, const ProfileOptions& options, int threads)
{
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        const RoughnessProfile p = roughness_profile(m.mesh, options);
        j = profile_json(mesh_facts(m), p);
    }
    return to_python(j);
}

py::dict py_profile(const ArrayLike& V, const ArrayLike& F, const py::object& levels, const py::object& radii,
                    bool global_level, const std::string& curvature, const std::string& weighting, int threads)
{
    const ProfileOptions options =
        profile_options(levels, global_level, curvature, weighting, false, radii_from(radii));
    return run_profile(mesh_from(V, F, "V", "F"), options, threads);
}

py::dict py_profile_file(const py::object& path_obj, const py::object& levels, const py::object& radii,
                         bool global_level, const std::string& curvature, const std::string& weighting, int threads)
{
    const ProfileOptions options =
        profile_options(levels, global_level, curvature, weighting, false, radii_from(radii));
    const std::string path = path_from(path_obj, "path");
    LoadedMesh m;
    {
        py::gil_scoped_release release;
        m = read_file(path);
    }
    return run_profile(m, options, threads);
}

py::dict py_corsini_profile(const ArrayLike& V, const ArrayLike& F, const py::object& levels, bool global_level,
                            bool unbiased, int threads)
{
    CorsiniOptions options;
    options.levels = levels_from(levels);
    options.global = global_level;
    options.unbiased = unbiased;
    const LoadedMesh m = mesh_from(V, F, "V", "F");
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        j = corsini_profile_json(mesh_facts(m), corsini_profile(m.mesh, options));
    }
    return to_python(j);
}

py::array_t<double> py_mean_curvature(const ArrayLike& V, const ArrayLike& F, const std::string& method,
                                      const std::string& weighting, int min_neighbors, double max_normal_angle_deg,
                                      int threads)
{
    CurvatureOptions o;
    o.method = parse_enum<CurvatureMethod>(method);
    o.weighting = parse_enum<RowWeighting>(weighting);
    o.min_neighbors = min_neighbors;
    o.max_normal_angle_deg = max_normal_angle_deg;
    const LoadedMesh m = mesh_from(V, F, "V", "F");
    CurvatureField field;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        field = mean_curvature(m.mesh, o);
    }
    return vector_array(field.H);
}

py::tuple py_roughness(const ArrayLike& V, const ArrayLike& F, const py::object& levels, bool global_level,
                       const std::string& curvature, const std::string& weighting, int threads)
{
    const ProfileOptions options = profile_options(levels, global_level, curvature, weighting, true);
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
                             const std::optional<long long>& samples, const std::optional<double>& density,
                             const std::string& face_sampling, std::uint64_t seed, bool vertex_samples,
                             bool edge_samples, bool face_samples, bool return_samples, int threads)
{
    const SamplingOptions o =
        sampling_options(samples, density, face_sampling, seed, vertex_samples, edge_samples, face_samples);
    const LoadedMesh a = mesh_from(V1, F1, "V1", "F1");
    const LoadedMesh b = mesh_from(V2, F2, "V2", "F2");
    SampledSurfaceDistance r;
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        if (return_samples)
            r = surface_distance_samples(a.mesh, b.mesh, o);
        else
            r.distance = surface_distance(a.mesh, b.mesh, o);
        j = surface_distance_json(r.distance, o);
    }
    if (!return_samples) return to_python(j);
    py::dict out = to_python(j);
    out["forward"] = direction_dict(j["forward"], r.forward);
    out["backward"] = direction_dict(j["backward"], r.backward);
    return out;
}

py::array_t<double> py_vertex_distances(const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2,
                                        const ArrayLike& F2, int threads)
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

// ---------------------------------------------------------------- DistanceIndex

class DistanceIndex
{
public:
    DistanceIndex(const ArrayLike& V, const ArrayLike& F)
    {
        const LoadedMesh m = mesh_from(V, F, "V", "F");
        py::gil_scoped_release release;
        index_ = std::make_unique<ClosestPointIndex>(m.mesh);
    }

    py::tuple query(const ArrayLike& P, int threads) const
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

    std::size_t n_faces() const { return index_->n_faces(); }
    std::size_t memory_bytes() const { return index_->memory_bytes(); }
    py::tuple bounds() const
    {
        const BoundingBox b = index_->bounds();
        return py::make_tuple(points_array({b.min}).attr("reshape")(3), points_array({b.max}).attr("reshape")(3));
    }

private:
    std::unique_ptr<ClosestPointIndex> index_;
};

// ---------------------------------------------------------------- docstrings

constexpr const char* kModuleDoc = R"doc(meshdiff: how a processed triangle mesh differs from its original.

Roughness profiles after Kushunapally, Razdan & Bridges 2007 (per-vertex mean
curvature H, its deviation D_L from the mean over the L-ring, sigma_L =
RMS(D_L)), the per-level roughness distance d_L, and Metro-style surface
distances, on numpy arrays or mesh files. The full reference is docs/python.md.

Meshes are V, F: V an (n, 3) array of vertex positions (any float or integer
dtype; converted once to float64), F an (m, 3) integer array of vertex indices
(counter-clockwise seen from outside). Arrays are used as given; read_mesh()
applies the CLI's input hygiene to files.

Conventions (METHOD.md):
- "forward" is first mesh -> second mesh: samples on the FIRST mesh (the
  original), exact point-to-triangle distances to the second.
- Distances are in the meshes' own length unit; "relative" values divide by the
  bounding-box diagonal of the FIRST mesh ("metro" ones by Metro's widened
  union box).
- H > 0 where the surface is convex with outward normals (unit sphere: +1);
  roughness is computed on the mesh scaled to mean vertex distance 1 from the
  centroid, so sigma and D_L are dimensionless.
- threads=0 uses all cores (or OMP_NUM_THREADS), as the CLI's --threads 0;
  results do not depend on the thread count. The GIL is released while
  computing.

Errors: ValueError for bad arrays, options or unusable meshes (the message
names the argument), FileNotFoundError / OSError for files that are missing or
unreadable, RuntimeError for numerical failures.)doc";

constexpr const char* kReadMeshDoc = R"doc(Reads a .ply, .obj, .off or .stl file with the input hygiene of the CLI:
unreferenced vertices dropped, polygons fan-triangulated, faces with a repeated
corner dropped; coordinates as double precision.

Returns V (n, 3) float64 and F (m, 3) int32. With report=True also a dict:
path, file_vertices, file_faces, unreferenced_vertices_removed,
polygons_triangulated, repeated_index_faces_removed (the names of the JSON
"mesh" object) and vertex_scalars (PLY vertex properties other than x, y, z,
name -> (n,) float64 array, e.g. exact_H from `meshdiff generate`).

Raises FileNotFoundError if the file does not exist, OSError if it cannot be
read or parsed, ValueError if it is not a usable mesh (no faces, NaN/Inf
coordinates, index out of range).)doc";

constexpr const char* kCompareOptionsDoc = R"doc(
Options (keyword-only, named like the CLI flags of `meshdiff compare`):
  levels=range(1, 21)   ring levels L (ints >= 1), in the order reported  [--levels]
  radii=None            metric levels: radii > 0 on the unit-scaled mesh, or "default";
                        adds d_r per radius (METHOD.md 5a)                 [--radii]
  global_level=True     also the global level                              [--no-global]
  curvature="goldfeather"  H estimator: goldfeather, quadric, meyer        [--curvature]
  weighting="none"      row weighting of the fits: none, inverse-square    [--weighting]
  k=1e-4                the constant of d_L = ln(|s'-s|/s + k) - ln(k)     [-k]
  roughness=True        compute both profiles and d_L                      [--no-roughness]
  distance=True         compute the surface distance                       [--no-distance]
  samples=None          samples per direction (None: 10 x the larger face count, as Metro)  [-n]
  density=None          samples per unit area instead of a count           [--density]
  face_sampling="similar"  face sampling: similar (Metro's lattice) or montecarlo  [--face-sampling]
  seed=1                seed of montecarlo sampling                        [--seed]
  vertex_samples=True, edge_samples=True, face_samples=True   sample kinds [--no-*-samples]
  hausdorff="certified" certified: an interval [lower, upper] holding each one-sided Hausdorff
                        distance, with where it is attained; sampled: the sampled maxima only
                                                                           [--hausdorff]
  hausdorff_tolerance=1e-4  width of that interval relative to the value   [--hausdorff-tolerance]
  hausdorff_abs_tolerance=None  the width in the meshes' unit instead      [--hausdorff-abs-tolerance]
  fscore=None           F-score thresholds relative to the original's diagonal,
                        e.g. [0.001, 0.005] -> surface_distance["fscore"]  [--fscore]
  histogram=0           bins of each direction's histogram, 0: none         [--histogram]
  threads=0             OpenMP threads, 0: all cores                        [--threads]
)doc";

constexpr const char* kCompareDoc = R"doc(Compares the original mesh (V1, F1) with the processed mesh (V2, F2): both
roughness profiles, the per-level roughness distance d_L and the Metro-style
surface distance. Returns the dict of `meshdiff ORIGINAL PROCESSED --json`
(schema "meshdiff.compare/2"): keys schema, meshdiff_version, original,
processed (each a "meshdiff.profile/1" dict), roughness_distance,
surface_distance (None for a half switched off; with the area-weighted means,
chamfer, fscore and psnr of METHOD.md section 6), same_connectivity (None with
same_connectivity_unavailable when the meshes' connectivity differs). Surface distances are in the
meshes' unit; "forward" samples the original (V1, F1); "relative" values divide
by the original's bounding-box diagonal. The arrays' "path" is "<array V1>" and
"<array V2>"; arrays get no input hygiene (isolated vertices are reported as
warnings). F1 or F2 None (or an empty (0, 3) array) makes that side a point
cloud: its points are its samples (point-to-surface or point-to-point
distances; "distance_kind" per direction), roughness is skipped
(roughness_unavailable says why); see METHOD.md section 6.

Example: meshdiff.compare(V, F, V2, F2, levels=[1, 5, 20])["surface_distance"]["hausdorff"]["upper"]
)doc";

constexpr const char* kCompareFilesDoc =
    R"doc(As compare() on two files read as read_mesh() reads them (a file with
vertices and no faces is a point cloud, as in `meshdiff compare`): the same dict as
`meshdiff ORIGINAL PROCESSED --json` with the same options, bit for bit (the
"path" fields are the paths as given here).

Raises FileNotFoundError / OSError for missing or unreadable files.
)doc";

constexpr const char* kProfileOptionsDoc = R"doc(
Options (keyword-only, as `meshdiff profile`):
  levels=range(1, 21), global_level=True, curvature="goldfeather",
  weighting="none", threads=0   (see compare())
  radii=None     metric levels [--radii]: a sequence of radii > 0 on the unit-scaled
                 mesh, or "default" (0.0125 * 2**(k/2), k = 0..8); adds "radii",
                 "sigma_radii" and "radius_details" to the dict (METHOD.md 5a)
)doc";

constexpr const char* kProfileDoc = R"doc(The roughness profile of one mesh: the dict of `meshdiff profile MESH --json`
(schema "meshdiff.profile/1"): sigma per level and globally (dimensionless: the
mesh is scaled to mean vertex distance 1 from its centroid first), the
normalisation, curvature statistics, per-level details (vertices used, share of
sigma^2 of the worst 0.1% of vertices, their ids) and warnings.
)doc";

constexpr const char* kProfileFileDoc = R"doc(profile() of a file read as read_mesh() reads it: bit for bit the dict of
`meshdiff profile PATH --json`.
)doc";

constexpr const char* kCorsiniProfileDoc =
    R"doc(Corsini et al.'s dihedral-angle roughness of one mesh (METHOD.md 6a): the dict
of `meshdiff profile MESH --measure corsini --json` (schema "meshdiff.corsini/1").
In it, "corsini" holds per level L the area-weighted mean over the vertices of
the variance of the dihedral angles of the edges within L rings (rad^2), the
global variance, and the multi-scale roughness (the mean over the levels).
levels: ring levels (each >= 1); global_level: add the global level;
unbiased: variance with divisor n - 1 instead of n.
)doc";

constexpr const char* kMeanCurvatureDoc =
    R"doc(Per-vertex mean curvature H, an (n,) float64 array in 1 / (the mesh's length
unit), NaN where undefined (isolated vertices; boundary vertices for "meyer").
Sign: H > 0 where convex with outward normals (a sphere of radius r: +1/r).
method: "goldfeather" (cubic fit, the default), "quadric" or "meyer"
(cotangent formula). Not normalised: profile() and roughness() estimate H on
the mesh scaled to mean vertex distance 1, i.e. H_there = H * scale.
)doc";

constexpr const char* kRoughnessDoc =
    R"doc(Per-vertex roughness: D[i, j] = D_L(i) = H(i) - mean of H over the vertices
within L = levels[j] edges of i (i excluded), on the mesh scaled to mean vertex
distance 1 from its centroid (dimensionless). D is (n, len(levels)) float64,
with one more column, the global level (mean over all other vertices), when
global_level=True; NaN where D is undefined (undefined H, or no neighbour with
a defined H). sigma[j] = sqrt(mean of D[:, j]^2 over the non-NaN entries),
the profile's sigma_L (same order).
)doc";

constexpr const char* kSurfaceDistanceDoc =
    R"doc(Metro-style surface distance between the first mesh A = (V1, F1) and the second
B = (V2, F2), in the meshes' length unit. Returns the "surface_distance" object
of compare(): forward (A -> B: samples on A, distance to B's surface) and
backward (B -> A) statistics min, max, mean, rms, std, p50, p95, p99, sample
counts, and "relative" (divided by A's bounding-box diagonal); hausdorff (max
of both maxima), diagonal, metro_diagonal, sampling.

With return_samples=True, forward and backward also hold the samples behind the
statistics: points (k, 3) float64, distances (k,) float64 (exact distance to
the other surface), kinds (k,) uint8 (0 vertex, 1 edge, 2 face: see
SAMPLE_KINDS), elements (k,) int64 (the vertex, a face of the edge, or the
face sampled) and signed_distances (k,) float64 (positive outside the other
surface; None when "signed" is None). The statistics are the same bit for bit.
)doc";

constexpr const char* kVertexDistancesDoc =
    R"doc(The exact distance of every vertex of the first mesh (V1; isolated vertices
included) to the surface of the second (V2, F2), an (n1,) float64 array in the
meshes' unit: a per-vertex distance map of the first mesh. F1 is validated
only.
)doc";

constexpr const char* kDistanceIndexDoc =
    R"doc(A bounding-volume hierarchy over the triangles of (V, F), built once and queried
many times for exact closest points (point-to-triangle; no distance cut-off).
The index keeps its own copy of the mesh. Queries are thread-safe and release
the GIL.
)doc";

constexpr const char* kQueryDoc = R"doc(For each row of P ((k, 3), any float dtype): distance (k,) float64 to the
closest point of the surface, face (k,) int64 (the face it lies on; the lowest
index on ties), closest_point (k, 3) float64. As libigl's
point_mesh_squared_distance, but with distances, not squared distances.
)doc";

}  // namespace

PYBIND11_MODULE(meshdiff, m)
{
    m.doc() = kModuleDoc;
    m.attr("__version__") = MESHDIFF_VERSION;
    m.attr("SAMPLE_KINDS") = py::make_tuple("vertex", "edge", "face", "point");
    py::register_exception_translator(translate_exceptions);

    const py::object default_levels = py::module_::import("builtins").attr("range")(1, 21);

    m.def("read_mesh", &py_read_mesh, kReadMeshDoc, py::arg("path"), py::kw_only(), py::arg("report") = false);

    const std::string compare_doc = std::string(kCompareDoc) + kCompareOptionsDoc;
    const std::string compare_files_doc = std::string(kCompareFilesDoc) + kCompareOptionsDoc;
    auto compare_options_args = [&](auto&& def) {
        def(py::arg("levels") = default_levels, py::arg("radii") = py::none(), py::arg("global_level") = true,
            py::arg("curvature") = "goldfeather", py::arg("weighting") = "none", py::arg("k") = 1e-4,
            py::arg("roughness") = true, py::arg("distance") = true, py::arg("samples") = py::none(),
            py::arg("density") = py::none(), py::arg("face_sampling") = "similar", py::arg("seed") = 1,
            py::arg("vertex_samples") = true, py::arg("edge_samples") = true, py::arg("face_samples") = true,
            py::arg("hausdorff") = "certified", py::arg("hausdorff_tolerance") = 1e-4,
            py::arg("hausdorff_abs_tolerance") = py::none(), py::arg("fscore") = py::none(), py::arg("histogram") = 0,
            py::arg("threads") = 0);
    };
    compare_options_args([&](auto... options) {
        m.def("compare", &py_compare, compare_doc.c_str(), py::arg("V1"), py::arg("F1"), py::arg("V2"), py::arg("F2"),
              py::kw_only(), options...);
    });
    compare_options_args([&](auto... options) {
        m.def("compare_files", &py_compare_files, compare_files_doc.c_str(), py::arg("original"), py::arg("processed"),
              py::kw_only(), options...);
    });

    const std::string profile_doc = std::string(kProfileDoc) + kProfileOptionsDoc;
    const std::string profile_file_doc = std::string(kProfileFileDoc) + kProfileOptionsDoc;
    m.def("profile", &py_profile, profile_doc.c_str(), py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = default_levels, py::arg("radii") = py::none(), py::arg("global_level") = true,
          py::arg("curvature") = "goldfeather", py::arg("weighting") = "none", py::arg("threads") = 0);
    m.def("profile_file", &py_profile_file, profile_file_doc.c_str(), py::arg("path"), py::kw_only(),
          py::arg("levels") = default_levels, py::arg("radii") = py::none(), py::arg("global_level") = true,
          py::arg("curvature") = "goldfeather", py::arg("weighting") = "none", py::arg("threads") = 0);

    m.def("corsini_profile", &py_corsini_profile, kCorsiniProfileDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = default_levels, py::arg("global_level") = true, py::arg("unbiased") = false,
          py::arg("threads") = 0);
    m.def("mean_curvature", &py_mean_curvature, kMeanCurvatureDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("method") = "goldfeather", py::arg("weighting") = "none", py::arg("min_neighbors") = 6,
          py::arg("max_normal_angle_deg") = 60.0, py::arg("threads") = 0);
    m.def("roughness", &py_roughness, kRoughnessDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = default_levels, py::arg("global_level") = false, py::arg("curvature") = "goldfeather",
          py::arg("weighting") = "none", py::arg("threads") = 0);

    m.def("surface_distance", &py_surface_distance, kSurfaceDistanceDoc, py::arg("V1"), py::arg("F1"), py::arg("V2"),
          py::arg("F2"), py::kw_only(), py::arg("samples") = py::none(), py::arg("density") = py::none(),
          py::arg("face_sampling") = "similar", py::arg("seed") = 1, py::arg("vertex_samples") = true,
          py::arg("edge_samples") = true, py::arg("face_samples") = true, py::arg("return_samples") = false,
          py::arg("threads") = 0);
    m.def("vertex_distances", &py_vertex_distances, kVertexDistancesDoc, py::arg("V1"), py::arg("F1"), py::arg("V2"),
          py::arg("F2"), py::kw_only(), py::arg("threads") = 0);

    py::class_<DistanceIndex>(m, "DistanceIndex", kDistanceIndexDoc)
        .def(py::init<const ArrayLike&, const ArrayLike&>(), py::arg("V"), py::arg("F"))
        .def("query", &DistanceIndex::query, kQueryDoc, py::arg("P"), py::kw_only(), py::arg("threads") = 0)
        .def_property_readonly("n_faces", &DistanceIndex::n_faces, "number of indexed triangles")
        .def_property_readonly("bounds", &DistanceIndex::bounds, "(min, max): the box of the indexed triangles")
        .def_property_readonly("memory_bytes", &DistanceIndex::memory_bytes, "approximate heap memory of the index")
        .def("__repr__", [](const DistanceIndex& d) {
            return "<meshdiff.DistanceIndex over " + std::to_string(d.n_faces()) + " triangles>";
        });
}

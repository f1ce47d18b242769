// The Python module `meshdiff`: the library on numpy arrays (docs/python.md).
//
// Every function converts its arguments once (with the GIL held), releases the
// GIL for the computation and builds the Python result with the GIL held again.
// The dicts are the CLI's JSON reports (report/json.h) converted value by value,
// so the numbers are bit for bit those of `meshdiff ... --json`.
#include "meshdiff/compare.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/options.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/roughness/corsini.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/version.h"

#include <fmt/format.h>
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
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

// The keyword of an options field (meshdiff/options.h: option_fields()), e.g.
// "profile.levels" -> "levels"; "" for a field Python does not offer. The one
// table from field to keyword: every OptionError is worded with it.
std::string py_spelling(const std::string& field)
{
    static const std::map<std::string, std::string> spelling = {
        {"profile.levels", "levels"},
        {"profile.radii", "radii"},
        {"profile.global", "global_level"},
        {"profile.curvature.method", "curvature"},
        {"profile.curvature.weighting", "weighting"},
        {"measure", "measure"},
        {"corsini_unbiased", "unbiased_variance"},
        {"k", "k"},
        {"roughness", "roughness"},
        {"distance", "distance"},
        {"sampling.samples", "samples"},
        {"sampling.density", "density"},
        {"sampling.face_scheme", "face_sampling"},
        {"sampling.seed", "seed"},
        {"sampling.vertices", "vertex_samples"},
        {"sampling.edges", "edge_samples"},
        {"sampling.faces", "face_samples"},
        {"hausdorff", "hausdorff"},
        {"hausdorff.relative_tolerance", "hausdorff_tolerance"},
        {"hausdorff.absolute_tolerance", "hausdorff_abs_tolerance"},
        {"hausdorff.max_evaluations", "hausdorff_budget"},
        {"summary.fscore_thresholds", "fscore"},
        {"summary.histogram_bins", "histogram"},
        {"threads", "threads"},
        {"outputs.json", "json"},
        {"outputs.distance_map", "distance_map"},
        {"outputs.distance_map_original", "distance_map_original"},
        {"outputs.distance_maps", "distance_maps"},
        {"outputs.samples_out", "samples_out"},
        {"outputs.color_range", "color_range"},
        {"outputs.vertex_data", "vertex_data"},
        {"outputs.exact", "exact"},
        {"outputs.exact_property", "exact_property"},
    };
    const auto it = spelling.find(field);
    return it == spelling.end() ? std::string() : it->second;
}

std::string py_spelling(const char* field)
{
    const std::string s = py_spelling(std::string(field));
    return s.empty() ? std::string(field) : s;
}

void translate_exceptions(std::exception_ptr p)
{
    try {
        if (p) std::rethrow_exception(p);
    } catch (const OptionError& e) {
        PyErr_SetString(PyExc_ValueError, worded(e, [](const std::string& f) { return py_spelling(f); }).c_str());
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
            // The limit of the file readers (mesh.h): beyond it products of coordinates overflow.
            if (std::abs(v) > max_coordinate)
                bad(fmt::format("{}: coordinate {} of row {} is {}, beyond meshdiff's limit of +-{}", name, c, i, v,
                                max_coordinate));
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
//
// Every keyword is taken as a Python object and converted here: a wrong type
// is a TypeError naming the keyword; every value, limit, default and
// combination is then the library's (validate(), options.h), whose
// OptionErrors translate_exceptions() words with py_spelling().

using Obj = const py::object&;

std::string repr(Obj v)
{
    return std::string(py::repr(v));
}

[[noreturn]] void type_error(const char* field, const std::string& expected, Obj got)
{
    throw py::type_error(py_spelling(field) + ": expected " + expected + ", got " + repr(got));
}

bool is_text(Obj v)
{
    return py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v);
}

// True/False (also numpy.bool_); None keeps \p default_value.
bool flag(Obj v, const char* field, bool default_value)
{
    if (v.is_none()) return default_value;
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
    if (py::hasattr(v, "dtype") && py::hasattr(v, "ndim") && v.attr("ndim").cast<int>() == 0 &&
        std::string(py::str(v.attr("dtype").attr("kind"))) == "b")
        return PyObject_IsTrue(v.ptr()) == 1;
    type_error(field, "True or False", v);
}

// A real number (int, float, numpy scalars); None: not given. Beyond the
// range of float it is +-inf, for the rules to refuse as a value.
std::optional<double> number(Obj v, const char* field)
{
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::bool_>(v) || is_text(v)) type_error(field, "a number", v);
    PyObject* f = PyNumber_Float(v.ptr());
    if (!f) {
        if (PyErr_ExceptionMatches(PyExc_OverflowError)) {
            PyErr_Clear();
            return py::int_(v) < py::int_(0) ? -HUGE_VAL : HUGE_VAL;
        }
        PyErr_Clear();
        type_error(field, "a number", v);
    }
    const double d = PyFloat_AsDouble(f);
    Py_DECREF(f);
    return d;
}

// A whole number (int, numpy integers) in 0..2^64-1; None: not given.
std::optional<std::uint64_t> whole(Obj v, const char* field)
{
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::bool_>(v)) type_error(field, "an int", v);
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()));
    if (!index) {
        PyErr_Clear();
        type_error(field, "an int", v);
    }
    return parse_whole_number(field, std::string(py::str(index)));
}

// A str; None: not given.
std::optional<std::string> text(Obj v, const char* field)
{
    if (v.is_none()) return std::nullopt;
    if (!py::isinstance<py::str>(v)) type_error(field, "a str", v);
    return v.cast<std::string>();
}

// An output path (str, bytes, os.PathLike); None: no output.
std::string output_path(Obj v, const char* field)
{
    if (v.is_none()) return {};
    std::string path;
    try {
        path = py::module_::import("os").attr("fsdecode")(v).cast<std::string>();
    } catch (const py::error_already_set&) {
        type_error(field, "a path (str, bytes or os.PathLike) or None", v);
    }
    if (path.empty()) throw OptionError(field, "an empty path (None: no output)");
    return path;
}

template <class E>
std::optional<E> choice(Obj v, const char* field)
{
    const auto name = text(v, field);
    if (!name) return std::nullopt;
    return parse_enum_option<E>(field, *name);
}

// The items of an iterable that is not text, at most \p most (the rules
// refuse a list longer than \p most - 1 without needing the rest).
std::vector<py::object> items_of(Obj v, const char* field, const std::string& expected, std::size_t most)
{
    if (is_text(v) || !py::isinstance<py::iterable>(v)) type_error(field, expected, v);
    std::vector<py::object> out;
    for (const py::handle item : py::reinterpret_borrow<py::iterable>(v)) {
        out.push_back(py::reinterpret_borrow<py::object>(item));
        if (out.size() >= most) break;
    }
    return out;
}

// Levels: an iterable of ints (list, range, numpy array), or the CLI's text ("1-20").
std::optional<std::vector<int>> levels_arg(Obj v)
{
    const char* field = "profile.levels";
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(v)) return parse_levels(v.cast<std::string>());
    const std::string expected = "a sequence of ints such as range(1, 21) or [1, 5, 20]";
    std::vector<int> levels;
    for (const py::object& item : items_of(v, field, expected, kMaxLevels + 1)) {
        if (py::isinstance<py::bool_>(item)) type_error(field, expected, item);
        const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(item.ptr()));
        if (!index) {
            PyErr_Clear();
            type_error(field, expected + " (the item " + repr(item) + " is not an int)", v);
        }
        levels.push_back(parse_level(std::string(py::str(index))));
    }
    return levels;
}

// Numbers: an iterable of numbers (list, numpy array of any float dtype).
std::vector<double> numbers_arg(Obj v, const char* field, const std::string& expected, std::size_t most)
{
    std::vector<double> out;
    for (const py::object& item : items_of(v, field, expected, most)) {
        if (py::isinstance<py::bool_>(item) || is_text(item)) type_error(field, expected, item);
        PyObject* f = PyNumber_Float(item.ptr());
        if (!f) {
            PyErr_Clear();
            type_error(field, expected + " (the item " + repr(item) + " is not a number)", v);
        }
        out.push_back(PyFloat_AsDouble(f));
        Py_DECREF(f);
    }
    return out;
}

// Radii: None, "default" (or the CLI's text), or an iterable of numbers.
std::optional<std::vector<double>> radii_arg(Obj v)
{
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(v)) return parse_radii(v.cast<std::string>());
    return numbers_arg(v, "profile.radii", "None, \"default\" or a sequence of numbers", kMaxRadii + 1);
}

// F-score thresholds: None, the CLI's text, or an iterable of numbers.
std::optional<std::vector<double>> fscore_arg(Obj v)
{
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(v)) return parse_fscore(v.cast<std::string>());
    return numbers_arg(v, "summary.fscore_thresholds", "None or a sequence of numbers", kMaxFscoreThresholds + 1);
}

// The ring-level options of a profile, over \p defaults.
ProfileOptions profile_options(Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting,
                               ProfileOptions p = {})
{
    if (auto l = levels_arg(levels)) p.levels = std::move(*l);
    if (auto r = radii_arg(radii)) p.radii = std::move(*r);
    p.global = flag(global_level, "profile.global", p.global);
    if (auto c = choice<CurvatureMethod>(curvature, "profile.curvature.method")) p.curvature.method = *c;
    if (auto w = choice<RowWeighting>(weighting, "profile.curvature.weighting")) p.curvature.weighting = *w;
    return p;
}

// The sampling options, over the library's defaults.
SamplingOptions sampling_options(Obj samples, Obj density, Obj face_sampling, Obj seed, Obj vertex_samples,
                                 Obj edge_samples, Obj face_samples)
{
    SamplingOptions s;
    if (auto n = whole(samples, "sampling.samples")) s.samples = std::size_t(*n);
    if (auto d = number(density, "sampling.density")) s.density = *d;
    if (auto f = choice<FaceSampling>(face_sampling, "sampling.face_scheme")) s.face_scheme = *f;
    if (auto v = whole(seed, "sampling.seed")) s.seed = *v;
    s.vertices = flag(vertex_samples, "sampling.vertices", s.vertices);
    s.edges = flag(edge_samples, "sampling.edges", s.edges);
    s.faces = flag(face_samples, "sampling.faces", s.faces);
    validate(s);
    return s;
}

// Sets the OpenMP thread count of the calling thread for one call (None or
// 0: leave the default, all cores or OMP_NUM_THREADS, as the CLI does) and
// restores it.
class ThreadScope
{
public:
    explicit ThreadScope(Obj threads) : saved_(omp_get_max_threads())
    {
        const std::uint64_t n = whole(threads, "threads").value_or(0);
        std::string warning;
        const int use = usable_threads((long long)std::min<std::uint64_t>(n, std::uint64_t(LLONG_MAX)), warning);
        // A RuntimeWarning (an exception only where warnings are made errors).
        if (!warning.empty() &&
            PyErr_WarnEx(PyExc_RuntimeWarning, (py_spelling("threads") + ": " + warning).c_str(), 2) < 0)
            throw py::error_already_set();
        if (use > 0) omp_set_num_threads(use);
    }
    ~ThreadScope() { omp_set_num_threads(saved_); }
    ThreadScope(const ThreadScope&) = delete;
    ThreadScope& operator=(const ThreadScope&) = delete;

private:
    int saved_;
};

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

// The comparison options (compare(), compare_files()).
struct CompareKeywords
{
    py::object levels, radii, global_level, curvature, weighting, measure, unbiased_variance, k, roughness, distance,
        samples, density, face_sampling, seed, vertex_samples, edge_samples, face_samples, hausdorff,
        hausdorff_tolerance, hausdorff_abs_tolerance, hausdorff_budget, fscore, histogram;
    py::object json, distance_map, distance_map_original, distance_maps, samples_out, color_range;
    py::object threads;
};

CompareOptions compare_options(const CompareKeywords& a)
{
    CompareOptions c;
    c.profile = profile_options(a.levels, a.radii, a.global_level, a.curvature, a.weighting);
    if (auto m = choice<RoughnessMeasure>(a.measure, "measure")) c.measure = *m;
    c.corsini_unbiased = flag(a.unbiased_variance, "corsini_unbiased", c.corsini_unbiased);
    if (auto k = number(a.k, "k")) c.k = *k;
    c.roughness = flag(a.roughness, "roughness", c.roughness);
    c.distance = flag(a.distance, "distance", c.distance);
    c.sampling = sampling_options(a.samples, a.density, a.face_sampling, a.seed, a.vertex_samples, a.edge_samples,
                                  a.face_samples);
    if (auto f = fscore_arg(a.fscore)) c.summary.fscore_thresholds = std::move(*f);
    if (auto h = whole(a.histogram, "summary.histogram_bins")) c.summary.histogram_bins = std::size_t(*h);
    HausdorffRequest h;
    if (auto m = choice<HausdorffMethod>(a.hausdorff, "hausdorff")) h.method = *m;
    h.relative_tolerance = number(a.hausdorff_tolerance, "hausdorff.relative_tolerance");
    h.absolute_tolerance = number(a.hausdorff_abs_tolerance, "hausdorff.absolute_tolerance");
    if (auto b = whole(a.hausdorff_budget, "hausdorff.max_evaluations")) h.budget = std::size_t(*b);
    c.hausdorff = hausdorff_options(h);
    validate(c);
    return c;
}

CompareOutputs compare_outputs(const CompareKeywords& a)
{
    CompareOutputs o;
    o.json = output_path(a.json, "outputs.json");
    o.distance_map = output_path(a.distance_map, "outputs.distance_map");
    o.distance_map_original = output_path(a.distance_map_original, "outputs.distance_map_original");
    o.distance_maps = output_path(a.distance_maps, "outputs.distance_maps");
    o.samples_out = output_path(a.samples_out, "outputs.samples_out");
    if (!a.color_range.is_none()) {
        const std::string expected = "a pair of numbers (MIN, MAX)";
        const std::vector<double> r = numbers_arg(a.color_range, "outputs.color_range", expected, 3);
        if (r.size() != 2) type_error("outputs.color_range", expected, a.color_range);
        o.color_range = std::pair{r[0], r[1]};
    }
    return o;
}

// compare_meshes() with the outputs \p a asks for, as `meshdiff compare` runs it.
py::dict run_compare(const CompareKeywords& a, const std::function<std::pair<LoadedMesh, LoadedMesh>()>& load,
                     const std::string& original_name, const std::string& processed_name,
                     const std::vector<std::string>& inputs)
{
    const CompareOutputs outputs = compare_outputs(a);
    const CompareOptions checked = compare_options(a);
    validate(outputs, checked, inputs);
    const CompareOptions options = with_outputs(checked, outputs);
    nlohmann::json j;
    {
        ThreadScope scope(a.threads);
        py::gil_scoped_release release;
        const auto [original, processed] = load();
        const Comparison c = compare_meshes(original, processed, options);
        StagedOutputs staged;  // every output file, or none
        write_outputs(c, original, processed, outputs, original_name, processed_name);
        j = comparison_json(c);
        if (!outputs.json.empty()) write_json_file(outputs.json, j);
        staged.commit();
    }
    return to_python(j);
}

py::dict py_compare(const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2, const ArrayLike& F2,
                    const CompareKeywords& a)
{
    auto meshes = std::make_shared<std::pair<LoadedMesh, LoadedMesh>>(mesh_or_cloud_from(V1, F1, "V1", "F1"),
                                                                      mesh_or_cloud_from(V2, F2, "V2", "F2"));
    return run_compare(a, [meshes] { return std::move(*meshes); }, "<array V1>", "<array V2>", {});
}

py::dict py_compare_files(Obj original, Obj processed, const CompareKeywords& a)
{
    const std::string pa = path_from(original, "original"), pb = path_from(processed, "processed");
    return run_compare(a, [&] { return std::pair{read_file(pa, true), read_file(pb, true)}; }, pa, pb, {pa, pb});
}

// The profile options (profile(), profile_file()).
struct ProfileKeywords
{
    py::object levels, radii, global_level, curvature, weighting, measure, unbiased_variance;
    py::object json, vertex_data, color_range, exact, exact_property;
    py::object threads;
};

ProfileRequest profile_request(const ProfileKeywords& a)
{
    ProfileRequest r;
    r.profile = profile_options(a.levels, a.radii, a.global_level, a.curvature, a.weighting);
    if (auto m = choice<RoughnessMeasure>(a.measure, "measure")) r.measure = *m;
    r.corsini_unbiased = flag(a.unbiased_variance, "corsini_unbiased", r.corsini_unbiased);
    r.json = output_path(a.json, "outputs.json");
    r.vertex_data = output_path(a.vertex_data, "outputs.vertex_data");
    if (auto c = number(a.color_range, "outputs.color_range")) r.color_range = *c;
    r.exact = flag(a.exact, "outputs.exact", r.exact);
    if (auto p = text(a.exact_property, "outputs.exact_property")) r.exact_property = *p;
    return r;
}

py::dict run_profile(const ProfileKeywords& a, const std::function<LoadedMesh()>& load,
                     const std::vector<std::string>& inputs)
{
    const ProfileRequest r = profile_request(a);
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
    return run_profile(a, [mesh] { return std::move(*mesh); }, {});
}

py::dict py_profile_file(Obj path_obj, const ProfileKeywords& a)
{
    const std::string path = path_from(path_obj, "path");
    return run_profile(a, [&] { return read_file(path); }, {path});
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
                       Obj weighting, Obj threads)
{
    ProfileOptions defaults;
    defaults.global = false;  // roughness(): the global column only when asked for
    ProfileOptions options = profile_options(levels, py::none(), global_level, curvature, weighting, defaults);
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
                             Obj edge_samples, Obj face_samples, Obj return_samples, Obj threads)
{
    const SamplingOptions o =
        sampling_options(samples, density, face_sampling, seed, vertex_samples, edge_samples, face_samples);
    const bool with_samples = flag(return_samples, "return_samples", false);
    const LoadedMesh a = mesh_from(V1, F1, "V1", "F1");
    const LoadedMesh b = mesh_from(V2, F2, "V2", "F2");
    SampledSurfaceDistance r;
    nlohmann::json j;
    {
        ThreadScope scope(threads);
        py::gil_scoped_release release;
        if (with_samples)
            r = surface_distance_samples(a.mesh, b.mesh, o);
        else
            r.distance = surface_distance(a.mesh, b.mesh, o);
        j = surface_distance_json(r.distance, o);
    }
    if (!with_samples) return to_python(j);
    py::dict out = to_python(j);
    out["forward"] = direction_dict(j["forward"], r.forward);
    out["backward"] = direction_dict(j["backward"], r.backward);
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
- threads=None or 0 uses all cores (or OMP_NUM_THREADS), as the CLI's --threads 0;
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
Options (keyword-only, named like the CLI flags of `meshdiff compare`; None:
not given, the library's default, as a flag left out). The rules and limits
are the library's, the CLI's too (docs/cli.md states the limits; LIMITS holds
them): a bad value is a ValueError, a wrong type a TypeError, naming the keyword.
  levels=None           ring levels L (ints >= 1, or "1-5,10"); None: 1..20  [--levels]
  radii=None            metric levels: radii > 0 on the unit-scaled mesh, or "default";
                        adds d_r per radius (METHOD.md 5a)                 [--radii]
  global_level=True     also the global level                              [--no-global]
  curvature=None        H estimator: goldfeather (default), quadric, meyer [--curvature]
  weighting=None        row weighting of the fits: none (default), inverse-square  [--weighting]
  measure=None          sigma (default) or corsini (METHOD.md 6a)          [--measure]
  unbiased_variance=False  corsini: variance with divisor n - 1            [--unbiased-variance]
  k=None                the constant of d_L = ln(|s'-s|/s + k) - ln(k); 1e-4  [-k]
  roughness=True        compute both profiles and d_L                      [--no-roughness]
  distance=True         compute the surface distance                       [--no-distance]
  samples=None          samples per direction (None: 10 x the larger face count, as Metro)  [-n]
  density=None          samples per unit area instead of a count           [--density]
  face_sampling=None    similar (Metro's lattice, default) or montecarlo   [--face-sampling]
  seed=None             seed of montecarlo sampling (default 1)            [--seed]
  vertex_samples=True, edge_samples=True, face_samples=True   sample kinds [--no-*-samples]
  hausdorff=None        certified (default): an interval [lower, upper] holding each one-sided
                        Hausdorff distance, with where it is attained; sampled: the sampled
                        maxima only                                        [--hausdorff]
  hausdorff_tolerance=None  width of that interval relative to the value; 1e-4 unless only
                        the absolute one is given                          [--hausdorff-tolerance]
  hausdorff_abs_tolerance=None  the width in the meshes' unit; with both, the interval stops
                        at max(relative x value, absolute), as math.isclose [--hausdorff-abs-tolerance]
  hausdorff_budget=None most triangle bounds per direction                 [--hausdorff-budget]
  fscore=None           F-score thresholds relative to the original's diagonal,
                        e.g. [0.001, 0.005] -> surface_distance["fscore"]  [--fscore]
  histogram=None        bins of each direction's histogram, 0 or None: none [--histogram]
  json=None             also write the JSON report to this path            [--json]
  distance_map=None, distance_map_original=None, distance_maps=None
                        write distance maps (PLY), as the CLI              [--distance-map, ...]
  samples_out=None      write both directions' samples (PLY point cloud)   [--samples-out]
  color_range=None      (MIN, MAX) of the maps' colours                    [--color-range]
  threads=None          OpenMP threads; None or 0: all cores               [--threads]
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
Options (keyword-only, as `meshdiff profile`; None: the library's default):
  levels=None, radii=None, global_level=True, curvature=None, weighting=None,
  measure=None, unbiased_variance=False, threads=None   (see compare());
  with radii (or "default": 0.0125 * 2**(k/2), k = 0..8) the dict also holds
  "radii", "sigma_radii" and "radius_details" (METHOD.md 5a); with
  measure="corsini" it is the dict of `meshdiff profile --measure corsini`.
  json=None          also write the JSON report to this path          [--json]
  vertex_data=None   write the normalised mesh with H, D_L per vertex [--vertex-data]
  color_range=None   R of the symmetric H colour range of vertex_data [--color-range]
  exact=False        also the profile of the exact H stored in the input
                     (under "exact"), and the error of the estimate   [--exact]
  exact_property=None  the vertex property holding it ("exact_H")     [--exact-property]
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
    // The library's limits of the options (docs/python.md states them; a test checks them against these).
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

    m.def("read_mesh", &py_read_mesh, kReadMeshDoc, py::arg("path"), py::kw_only(), py::arg("report") = false);

    const std::string compare_doc = std::string(kCompareDoc) + kCompareOptionsDoc;
    const std::string compare_files_doc = std::string(kCompareFilesDoc) + kCompareOptionsDoc;
    const std::string profile_doc = std::string(kProfileDoc) + kProfileOptionsDoc;
    const std::string profile_file_doc = std::string(kProfileFileDoc) + kProfileOptionsDoc;
    const CompareOptions defaults;
    const ProfileRequest pdefaults;
    auto compare_keywords =
        [](Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure, Obj unbiased_variance,
           Obj k, Obj roughness, Obj distance, Obj samples, Obj density, Obj face_sampling, Obj seed,
           Obj vertex_samples, Obj edge_samples, Obj face_samples, Obj hausdorff, Obj hausdorff_tolerance,
           Obj hausdorff_abs_tolerance, Obj hausdorff_budget, Obj fscore, Obj histogram, Obj json, Obj distance_map,
           Obj distance_map_original, Obj distance_maps, Obj samples_out, Obj color_range, Obj threads) {
            CompareKeywords kw;
            kw.levels = levels;
            kw.radii = radii;
            kw.global_level = global_level;
            kw.curvature = curvature;
            kw.weighting = weighting;
            kw.measure = measure;
            kw.unbiased_variance = unbiased_variance;
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
            kw.color_range = color_range;
            kw.threads = threads;
            return kw;
        };
    m.def(
        "compare",
        [compare_keywords](const ArrayLike& V1, const ArrayLike& F1, const ArrayLike& V2, const ArrayLike& F2,
                           Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
                           Obj unbiased_variance, Obj k, Obj roughness, Obj distance, Obj samples, Obj density,
                           Obj face_sampling, Obj seed, Obj vertex_samples, Obj edge_samples, Obj face_samples,
                           Obj hausdorff, Obj hausdorff_tolerance, Obj hausdorff_abs_tolerance, Obj hausdorff_budget,
                           Obj fscore, Obj histogram, Obj json, Obj distance_map, Obj distance_map_original,
                           Obj distance_maps, Obj samples_out, Obj color_range, Obj threads) {
            return py_compare(
                V1, F1, V2, F2,
                compare_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance, k,
                                 roughness, distance, samples, density, face_sampling, seed, vertex_samples,
                                 edge_samples, face_samples, hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance,
                                 hausdorff_budget, fscore, histogram, json, distance_map, distance_map_original,
                                 distance_maps, samples_out, color_range, threads));
        },
        compare_doc.c_str(), py::arg("V1"), py::arg("F1"), py::arg("V2"), py::arg("F2"), py::kw_only(),
        py::arg("levels") = py::none(), py::arg("radii") = py::none(),
        py::arg("global_level") = py::bool_(defaults.profile.global), py::arg("curvature") = py::none(),
        py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
        py::arg("unbiased_variance") = py::bool_(defaults.corsini_unbiased), py::arg("k") = py::none(),
        py::arg("roughness") = py::bool_(defaults.roughness), py::arg("distance") = py::bool_(defaults.distance),
        py::arg("samples") = py::none(), py::arg("density") = py::none(), py::arg("face_sampling") = py::none(),
        py::arg("seed") = py::none(), py::arg("vertex_samples") = py::bool_(defaults.sampling.vertices),
        py::arg("edge_samples") = py::bool_(defaults.sampling.edges),
        py::arg("face_samples") = py::bool_(defaults.sampling.faces), py::arg("hausdorff") = py::none(),
        py::arg("hausdorff_tolerance") = py::none(), py::arg("hausdorff_abs_tolerance") = py::none(),
        py::arg("hausdorff_budget") = py::none(), py::arg("fscore") = py::none(), py::arg("histogram") = py::none(),
        py::arg("json") = py::none(), py::arg("distance_map") = py::none(),
        py::arg("distance_map_original") = py::none(), py::arg("distance_maps") = py::none(),
        py::arg("samples_out") = py::none(), py::arg("color_range") = py::none(), py::arg("threads") = py::none());
    m.def(
        "compare_files",
        [compare_keywords](Obj original, Obj processed, Obj levels, Obj radii, Obj global_level, Obj curvature,
                           Obj weighting, Obj measure, Obj unbiased_variance, Obj k, Obj roughness, Obj distance,
                           Obj samples, Obj density, Obj face_sampling, Obj seed, Obj vertex_samples, Obj edge_samples,
                           Obj face_samples, Obj hausdorff, Obj hausdorff_tolerance, Obj hausdorff_abs_tolerance,
                           Obj hausdorff_budget, Obj fscore, Obj histogram, Obj json, Obj distance_map,
                           Obj distance_map_original, Obj distance_maps, Obj samples_out, Obj color_range,
                           Obj threads) {
            return py_compare_files(
                original, processed,
                compare_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance, k,
                                 roughness, distance, samples, density, face_sampling, seed, vertex_samples,
                                 edge_samples, face_samples, hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance,
                                 hausdorff_budget, fscore, histogram, json, distance_map, distance_map_original,
                                 distance_maps, samples_out, color_range, threads));
        },
        compare_files_doc.c_str(), py::arg("original"), py::arg("processed"), py::kw_only(),
        py::arg("levels") = py::none(), py::arg("radii") = py::none(),
        py::arg("global_level") = py::bool_(defaults.profile.global), py::arg("curvature") = py::none(),
        py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
        py::arg("unbiased_variance") = py::bool_(defaults.corsini_unbiased), py::arg("k") = py::none(),
        py::arg("roughness") = py::bool_(defaults.roughness), py::arg("distance") = py::bool_(defaults.distance),
        py::arg("samples") = py::none(), py::arg("density") = py::none(), py::arg("face_sampling") = py::none(),
        py::arg("seed") = py::none(), py::arg("vertex_samples") = py::bool_(defaults.sampling.vertices),
        py::arg("edge_samples") = py::bool_(defaults.sampling.edges),
        py::arg("face_samples") = py::bool_(defaults.sampling.faces), py::arg("hausdorff") = py::none(),
        py::arg("hausdorff_tolerance") = py::none(), py::arg("hausdorff_abs_tolerance") = py::none(),
        py::arg("hausdorff_budget") = py::none(), py::arg("fscore") = py::none(), py::arg("histogram") = py::none(),
        py::arg("json") = py::none(), py::arg("distance_map") = py::none(),
        py::arg("distance_map_original") = py::none(), py::arg("distance_maps") = py::none(),
        py::arg("samples_out") = py::none(), py::arg("color_range") = py::none(), py::arg("threads") = py::none());
    auto profile_keywords = [](Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
                               Obj unbiased_variance, Obj json, Obj vertex_data, Obj color_range, Obj exact,
                               Obj exact_property, Obj threads) {
        ProfileKeywords kw;
        kw.levels = levels;
        kw.radii = radii;
        kw.global_level = global_level;
        kw.curvature = curvature;
        kw.weighting = weighting;
        kw.measure = measure;
        kw.unbiased_variance = unbiased_variance;
        kw.json = json;
        kw.vertex_data = vertex_data;
        kw.color_range = color_range;
        kw.exact = exact;
        kw.exact_property = exact_property;
        kw.threads = threads;
        return kw;
    };
    m.def(
        "profile",
        [profile_keywords](const ArrayLike& V, const ArrayLike& F, Obj levels, Obj radii, Obj global_level,
                           Obj curvature, Obj weighting, Obj measure, Obj unbiased_variance, Obj json, Obj vertex_data,
                           Obj color_range, Obj exact, Obj exact_property, Obj threads) {
            return py_profile(
                V, F,
                profile_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance, json,
                                 vertex_data, color_range, exact, exact_property, threads));
        },
        profile_doc.c_str(), py::arg("V"), py::arg("F"), py::kw_only(), py::arg("levels") = py::none(),
        py::arg("radii") = py::none(), py::arg("global_level") = py::bool_(pdefaults.profile.global),
        py::arg("curvature") = py::none(), py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
        py::arg("unbiased_variance") = py::bool_(pdefaults.corsini_unbiased), py::arg("json") = py::none(),
        py::arg("vertex_data") = py::none(), py::arg("color_range") = py::none(),
        py::arg("exact") = py::bool_(pdefaults.exact), py::arg("exact_property") = py::none(),
        py::arg("threads") = py::none());
    m.def(
        "profile_file",
        [profile_keywords](Obj path, Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, Obj measure,
                           Obj unbiased_variance, Obj json, Obj vertex_data, Obj color_range, Obj exact,
                           Obj exact_property, Obj threads) {
            return py_profile_file(
                path, profile_keywords(levels, radii, global_level, curvature, weighting, measure, unbiased_variance,
                                       json, vertex_data, color_range, exact, exact_property, threads));
        },
        profile_file_doc.c_str(), py::arg("path"), py::kw_only(), py::arg("levels") = py::none(),
        py::arg("radii") = py::none(), py::arg("global_level") = py::bool_(pdefaults.profile.global),
        py::arg("curvature") = py::none(), py::arg("weighting") = py::none(), py::arg("measure") = py::none(),
        py::arg("unbiased_variance") = py::bool_(pdefaults.corsini_unbiased), py::arg("json") = py::none(),
        py::arg("vertex_data") = py::none(), py::arg("color_range") = py::none(),
        py::arg("exact") = py::bool_(pdefaults.exact), py::arg("exact_property") = py::none(),
        py::arg("threads") = py::none());

    m.def("corsini_profile", &py_corsini_profile, kCorsiniProfileDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = py::none(), py::arg("global_level") = py::bool_(true),
          py::arg("unbiased") = py::bool_(false), py::arg("threads") = py::none());
    m.def("mean_curvature", &py_mean_curvature, kMeanCurvatureDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("method") = py::none(), py::arg("weighting") = py::none(), py::arg("min_neighbors") = py::none(),
          py::arg("max_normal_angle_deg") = py::none(), py::arg("threads") = py::none());
    m.def("roughness", &py_roughness, kRoughnessDoc, py::arg("V"), py::arg("F"), py::kw_only(),
          py::arg("levels") = py::none(), py::arg("global_level") = py::bool_(false), py::arg("curvature") = py::none(),
          py::arg("weighting") = py::none(), py::arg("threads") = py::none());

    m.def("surface_distance", &py_surface_distance, kSurfaceDistanceDoc, py::arg("V1"), py::arg("F1"), py::arg("V2"),
          py::arg("F2"), py::kw_only(), py::arg("samples") = py::none(), py::arg("density") = py::none(),
          py::arg("face_sampling") = py::none(), py::arg("seed") = py::none(),
          py::arg("vertex_samples") = py::bool_(true), py::arg("edge_samples") = py::bool_(true),
          py::arg("face_samples") = py::bool_(true), py::arg("return_samples") = py::bool_(false),
          py::arg("threads") = py::none());
    m.def("vertex_distances", &py_vertex_distances, kVertexDistancesDoc, py::arg("V1"), py::arg("F1"), py::arg("V2"),
          py::arg("F2"), py::kw_only(), py::arg("threads") = py::none());

    py::class_<DistanceIndex>(m, "DistanceIndex", kDistanceIndexDoc)
        .def(py::init<const ArrayLike&, const ArrayLike&>(), py::arg("V"), py::arg("F"))
        .def("query", &DistanceIndex::query, kQueryDoc, py::arg("P"), py::kw_only(), py::arg("threads") = py::none())
        .def_property_readonly("n_faces", &DistanceIndex::n_faces, "number of indexed triangles")
        .def_property_readonly("bounds", &DistanceIndex::bounds, "(min, max): the box of the indexed triangles")
        .def_property_readonly("memory_bytes", &DistanceIndex::memory_bytes, "approximate heap memory of the index")
        .def("__repr__", [](const DistanceIndex& d) {
            return "<meshdiff.DistanceIndex over " + std::to_string(d.n_faces()) + " triangles>";
        });
}

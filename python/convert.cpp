// The Python module's conversions (convert.h): arrays in, options, results out.
#include "convert.h"

#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/roughness/metric_levels.h"

#include <fmt/format.h>
#include <omp.h>
#include <pybind11_json/pybind11_json.hpp>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <utility>

namespace meshdiff::python {

// ---------------------------------------------------------------- errors

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
        {"profile.normalize", "normalize"},
        {"profile.trim", "trim"},
        {"local", "local"},
        {"local_trim", "local_trim"},
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
        {"outputs.html", "html"},
        {"outputs.color_range", "color_range"},
        {"outputs.html_face_budget", "html_face_budget"},
        {"profile.bootstrap", "bootstrap"},
        {"profile.bootstrap_seed", "bootstrap_seed"},
        {"profile.paper", "paper"},
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
    } catch (const Cancelled&) {
        translate_cancelled();  // Ctrl-C, or an exception of the progress hook
    } catch (const Error& e) {
        PyErr_SetString(PyExc_RuntimeError, e.what());
    }
}

namespace {

[[noreturn]] void bad(const std::string& message)
{
    throw BadArgument(message);
}

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

std::string repr(Obj v)
{
    return std::string(py::repr(v));
}

bool is_text(Obj v)
{
    return py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v);
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

}  // namespace

// ---------------------------------------------------------------- arrays in

std::vector<Vec3> points_from(const py::handle& obj, const char* name, bool allow_empty)
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

LoadedMesh read_file(const std::string& path, bool cloud)
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

[[noreturn]] void type_error(const char* field, const std::string& expected, Obj got)
{
    throw py::type_error(py_spelling(field) + ": expected " + expected + ", got " + repr(got));
}

bool flag(Obj v, const char* field, bool default_value)
{
    if (v.is_none()) return default_value;
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
    if (py::hasattr(v, "dtype") && py::hasattr(v, "ndim") && v.attr("ndim").cast<int>() == 0 &&
        std::string(py::str(v.attr("dtype").attr("kind"))) == "b")
        return PyObject_IsTrue(v.ptr()) == 1;
    type_error(field, "True or False", v);
}

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

std::optional<std::string> text(Obj v, const char* field)
{
    if (v.is_none()) return std::nullopt;
    if (!py::isinstance<py::str>(v)) type_error(field, "a str", v);
    return v.cast<std::string>();
}

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

std::optional<std::vector<double>> radii_arg(Obj v)
{
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(v)) return parse_radii(v.cast<std::string>());
    return numbers_arg(v, "profile.radii", "None, \"default\" or a sequence of numbers", kMaxRadii + 1);
}

std::optional<std::vector<double>> fscore_arg(Obj v)
{
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(v)) return parse_fscore(v.cast<std::string>());
    return numbers_arg(v, "summary.fscore_thresholds", "None or a sequence of numbers", kMaxFscoreThresholds + 1);
}

ProfileOptions profile_options(Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting, ProfileOptions p)
{
    if (auto l = levels_arg(levels)) p.levels = std::move(*l);
    if (auto r = radii_arg(radii)) p.radii = std::move(*r);
    p.global = flag(global_level, "profile.global", p.global);
    if (auto c = choice<CurvatureMethod>(curvature, "profile.curvature.method")) p.curvature.method = *c;
    if (auto w = choice<RowWeighting>(weighting, "profile.curvature.weighting")) p.curvature.weighting = *w;
    return p;
}

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

namespace {

// The profile options, the measure and the Corsini variance of the roughness
// keywords \p a, checked in this order (compare() and profile() alike).
void roughness_options(const RoughnessKeywords& a, ProfileOptions& profile, RoughnessMeasure& measure,
                       bool& corsini_unbiased)
{
    profile = profile_options(a.levels, a.radii, a.global_level, a.curvature, a.weighting,
                              flag(a.paper, "profile.paper", false) ? paper_profile_options() : ProfileOptions{});
    if (auto m = choice<RoughnessMeasure>(a.measure, "measure")) measure = *m;
    corsini_unbiased = flag(a.unbiased_variance, "corsini_unbiased", corsini_unbiased);
    if (auto n = choice<NormalizeMethod>(a.normalize, "profile.normalize")) profile.normalize = *n;
    if (auto t = number(a.trim, "profile.trim")) profile.trim = *t;
    if (auto b = whole(a.bootstrap, "profile.bootstrap")) profile.bootstrap = std::size_t(*b);
    if (auto b = whole(a.bootstrap_seed, "profile.bootstrap_seed")) profile.bootstrap_seed = *b;
}

}  // namespace

CompareOptions compare_options(const CompareKeywords& a)
{
    CompareOptions c;
    roughness_options(a, c.profile, c.measure, c.corsini_unbiased);
    c.local = flag(a.local, "local", c.local);
    if (auto t = number(a.local_trim, "local_trim")) c.local_trim = *t;
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

std::optional<HausdorffOptions> surface_distance_hausdorff(Obj hausdorff, Obj tolerance, Obj abs_tolerance, Obj budget)
{
    HausdorffRequest h;
    h.method = choice<HausdorffMethod>(hausdorff, "hausdorff").value_or(HausdorffMethod::Sampled);
    h.relative_tolerance = number(tolerance, "hausdorff.relative_tolerance");
    h.absolute_tolerance = number(abs_tolerance, "hausdorff.absolute_tolerance");
    if (auto b = whole(budget, "hausdorff.max_evaluations")) h.budget = std::size_t(*b);
    return hausdorff_options(h);
}

CompareOutputs compare_outputs(const CompareKeywords& a)
{
    CompareOutputs o;
    o.json = output_path(a.json, "outputs.json");
    o.distance_map = output_path(a.distance_map, "outputs.distance_map");
    o.distance_map_original = output_path(a.distance_map_original, "outputs.distance_map_original");
    o.distance_maps = output_path(a.distance_maps, "outputs.distance_maps");
    o.samples_out = output_path(a.samples_out, "outputs.samples_out");
    o.html = output_path(a.html, "outputs.html");
    if (auto b = whole(a.html_face_budget, "outputs.html_face_budget")) o.html_face_budget = std::size_t(*b);
    if (py::isinstance<py::str>(a.color_range)) {
        parse_color_range(a.color_range.cast<std::string>(), o);
    } else if (!a.color_range.is_none()) {
        const std::string expected = "a pair of numbers (MIN, MAX), or 'max', 'pNN', 'LO:HI'";
        const std::vector<double> r = numbers_arg(a.color_range, "outputs.color_range", expected, 3);
        if (r.size() != 2) type_error("outputs.color_range", expected, a.color_range);
        o.color_range = std::pair{r[0], r[1]};
    }
    return o;
}

ProfileRequest profile_request(const ProfileKeywords& a)
{
    ProfileRequest r;
    roughness_options(a, r.profile, r.measure, r.corsini_unbiased);
    r.json = output_path(a.json, "outputs.json");
    r.vertex_data = output_path(a.vertex_data, "outputs.vertex_data");
    r.html = output_path(a.html, "outputs.html");
    if (auto b = whole(a.html_face_budget, "outputs.html_face_budget")) r.html_face_budget = std::size_t(*b);
    if (auto c = number(a.color_range, "outputs.color_range")) r.color_range = *c;
    r.exact = flag(a.exact, "outputs.exact", r.exact);
    if (auto p = text(a.exact_property, "outputs.exact_property")) r.exact_property = *p;
    return r;
}

ThreadScope::ThreadScope(Obj threads) : saved_(omp_get_max_threads())
{
    const std::uint64_t n = whole(threads, "threads").value_or(0);
    std::string warning;
    const int use = usable_threads((long long)std::min<std::uint64_t>(n, std::uint64_t(LLONG_MAX)), warning);
    // A RuntimeWarning (an exception only where warnings are made errors).
    if (!warning.empty() &&
        PyErr_WarnEx(PyExc_RuntimeWarning, (py_spelling("threads") + ": " + warning).c_str(), 2) < 0)
        throw py::error_already_set();
    if (use > 0) omp_set_num_threads(use);
    progress_ = std::make_unique<CallProgress>(current_hook());
    progress_scope_ = std::make_unique<ProgressScope>(progress_.get());
}

ThreadScope::~ThreadScope()
{
    progress_scope_.reset();
    progress_->settle(std::uncaught_exceptions() > 0);
    omp_set_num_threads(saved_);
}

// ---------------------------------------------------------------- results out

py::object to_python(const nlohmann::json& j)
{
    return pyjson::from_json(j);  // pybind11_json: the same conversion value by value, kept by its library
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

}  // namespace meshdiff::python

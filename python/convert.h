//! \file convert.h
//! \brief The Python module's conversions (module.cpp binds with them): numpy
//! arrays to meshes and back, path arguments, the keyword options to the
//! library's options, the JSON reports to Python dicts, and the library's
//! exceptions to Python's.
//!
//! Every keyword is taken as a Python object and converted here: a wrong type
//! is a TypeError naming the keyword; every value, limit, default and
//! combination is then the library's (validate(), options.h), whose
//! OptionErrors translate_exceptions() words with py_spelling(). All of it runs
//! with the GIL held.
#pragma once

#include "interrupt.h"
#include "meshdiff/compare.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/geometry/sampling.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/roughness/roughness.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file of the module, for the same casters everywhere
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;

namespace meshdiff::python {

//! An argument that numpy can make an array of (an ndarray, a list of lists,
//! ...): taken as is and checked by the function, so that a wrong shape or dtype
//! is a ValueError naming the argument; shown as numpy.typing.ArrayLike.
struct ArrayLike
{
    py::object object;
};

}  // namespace meshdiff::python

namespace pybind11::detail {
//! Loads any object as an ArrayLike (the checks are the function's).
template <>
struct type_caster<meshdiff::python::ArrayLike>
{
    PYBIND11_TYPE_CASTER(meshdiff::python::ArrayLike, const_name("numpy.typing.ArrayLike"));
    bool load(handle src, bool /*convert*/)
    {
        value.object = reinterpret_borrow<object>(src);
        return true;
    }
    static handle cast(const meshdiff::python::ArrayLike& a, return_value_policy /*policy*/, handle /*parent*/)
    {
        return a.object.inc_ref();
    }
};
}  // namespace pybind11::detail

namespace meshdiff::python {

// ---------------------------------------------------------------- errors

//! A missing file: raised as FileNotFoundError(ENOENT, message, path).
struct FileMissing
{
    std::string message;
    std::string path;
};

//! An argument with the wrong shape, type or values: ValueError.
struct BadArgument : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

//! The keyword of an options field (meshdiff/options.h: option_fields()), e.g.
//! "profile.levels" -> "levels"; "" for a field Python does not offer. The one
//! table from field to keyword: every OptionError is worded with it.
std::string py_spelling(const std::string& field);

//! py_spelling(), or \p field itself for a field Python does not offer.
std::string py_spelling(const char* field);

//! The exception translator of the module (py::register_exception_translator):
//! OptionError, FileMissing, BadArgument, InvalidMeshError and
//! InvalidArgumentError as ValueError (FileMissing as FileNotFoundError),
//! IoError as OSError, SolverError and any other meshdiff::Error as RuntimeError.
void translate_exceptions(std::exception_ptr p);

// ---------------------------------------------------------------- arrays in

//! The rows of an (n, 3) array of numbers as points, converted once to float64.
//! \throw BadArgument naming \p name for another shape or dtype, no rows (unless
//! \p allow_empty), a NaN or infinite coordinate, or one beyond max_coordinate.
std::vector<Vec3> points_from(const py::handle& obj, const char* name, bool allow_empty = false);

//! The rows of an (m, 3) integer array as faces of a mesh with \p n_vertices.
//! \throw BadArgument naming \p name for another shape or dtype, no rows, or an
//! index out of range.
std::vector<Face> faces_from(const py::handle& obj, const char* name, std::size_t n_vertices);

//! A mesh from V and F as a LoadedMesh whose "file" is the array (the reports
//! name it "<array V>"); no input hygiene (arrays are used as given).
LoadedMesh mesh_from(const ArrayLike& V, const ArrayLike& F, const char* vname, const char* fname);

//! For compare: F None or an empty (0, 3) array makes V a point cloud
//! (cloud_distance.h); else mesh_from().
LoadedMesh mesh_or_cloud_from(const ArrayLike& V, const ArrayLike& F, const char* vname, const char* fname);

//! A path argument (str, bytes or os.PathLike) as os.fsdecode() gives it.
//! \throw py::type_error naming \p name for anything else.
std::string path_from(const py::handle& obj, const char* name);

//! read_mesh() (read_mesh_or_cloud() with \p cloud) with a missing file as
//! FileMissing (FileNotFoundError).
LoadedMesh read_file(const std::string& path, bool cloud = false);

// ---------------------------------------------------------------- options

//! A keyword argument as the bindings pass it.
using Obj = const py::object&;

//! Throws the TypeError of the keyword of \p field: "<keyword>: expected
//! <expected>, got <repr of got>".
[[noreturn]] void type_error(const char* field, const std::string& expected, Obj got);

//! True/False (also numpy.bool_); None keeps \p default_value.
bool flag(Obj v, const char* field, bool default_value);

//! A real number (int, float, numpy scalars); None: not given. Beyond the
//! range of float it is +-inf, for the rules to refuse as a value.
std::optional<double> number(Obj v, const char* field);

//! A whole number (int, numpy integers) in 0..2^64-1; None: not given.
std::optional<std::uint64_t> whole(Obj v, const char* field);

//! A str; None: not given.
std::optional<std::string> text(Obj v, const char* field);

//! An output path (str, bytes, os.PathLike); None: no output ("").
//! \throw OptionError(\p field) for an empty path.
std::string output_path(Obj v, const char* field);

//! A str naming a value of the enum \p E (enum_names.h); None: not given.
template <class E>
std::optional<E> choice(Obj v, const char* field)
{
    const auto name = text(v, field);
    if (!name) return std::nullopt;
    return parse_enum_option<E>(field, *name);
}

//! Levels: an iterable of ints (list, range, numpy array), or the CLI's text ("1-20").
std::optional<std::vector<int>> levels_arg(Obj v);

//! Numbers: an iterable of numbers (list, numpy array of any float dtype), at
//! most \p most of them read (the rules refuse a list longer than \p most - 1).
std::vector<double> numbers_arg(Obj v, const char* field, const std::string& expected, std::size_t most);

//! Radii: None, "default" (or the CLI's text), or an iterable of numbers.
std::optional<std::vector<double>> radii_arg(Obj v);

//! F-score thresholds: None, the CLI's text, or an iterable of numbers.
std::optional<std::vector<double>> fscore_arg(Obj v);

//! The ring-level options of a profile, over \p p.
ProfileOptions profile_options(Obj levels, Obj radii, Obj global_level, Obj curvature, Obj weighting,
                               ProfileOptions p = {});

//! The sampling options, over the library's defaults, validated.
SamplingOptions sampling_options(Obj samples, Obj density, Obj face_sampling, Obj seed, Obj vertex_samples,
                                 Obj edge_samples, Obj face_samples);

//! The certification of surface_distance() (hausdorff=..., as compare()'s
//! keywords, by the library's hausdorff_options()): None, its default, keeps
//! the sampled maxima (then no tolerance or budget may be given).
std::optional<HausdorffOptions> surface_distance_hausdorff(Obj hausdorff, Obj tolerance, Obj abs_tolerance, Obj budget);

//! The comparison options (compare(), compare_files()).
//! The roughness keywords that compare() and profile() share.
struct RoughnessKeywords
{
    py::object levels, radii, global_level, curvature, weighting, measure, unbiased_variance, normalize, trim,
        bootstrap, bootstrap_seed, paper;
};

struct CompareKeywords : RoughnessKeywords
{
    py::object local, local_trim, k, roughness, distance, samples, density, face_sampling, seed, vertex_samples,
        edge_samples, face_samples, hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance, hausdorff_budget, fscore,
        histogram;
    py::object json, distance_map, distance_map_original, distance_maps, samples_out, html, color_range,
        html_face_budget;
    py::object threads;
};

//! The CompareOptions of \p a, validated (its outputs aside).
CompareOptions compare_options(const CompareKeywords& a);

//! The output files \p a asks for (json, the maps, the samples) and the colour range.
CompareOutputs compare_outputs(const CompareKeywords& a);

//! The profile options (profile(), profile_file()).
struct ProfileKeywords : RoughnessKeywords
{
    py::object json, vertex_data, html, color_range, exact, exact_property, html_face_budget;
    py::object threads;
};

//! The ProfileRequest of \p a (not yet validated: that needs the inputs).
ProfileRequest profile_request(const ProfileKeywords& a);

//! Sets the OpenMP thread count of the calling thread for one call (None or
//! 0: leave the default, all cores or OMP_NUM_THREADS, as the CLI does) and
//! restores it. A count the system cannot start is lowered with a RuntimeWarning.
//! Also the call's Progress (interrupt.h): Ctrl-C and the progress hook.
//! Constructed and destroyed with the GIL held, around the GIL's release.
class ThreadScope
{
public:
    explicit ThreadScope(Obj threads);
    ~ThreadScope();
    ThreadScope(const ThreadScope&) = delete;
    ThreadScope& operator=(const ThreadScope&) = delete;

private:
    int saved_;
    std::unique_ptr<CallProgress> progress_;
    std::unique_ptr<ProgressScope> progress_scope_;
};

// ---------------------------------------------------------------- results out

//! nlohmann::json to Python: object -> dict, array -> list, float -> float,
//! integers -> int, bool -> bool, null -> None, string -> str.
py::object to_python(const nlohmann::json& j);

//! \p v as an (n,) float64 array.
py::array_t<double> vector_array(const std::vector<double>& v);

//! \p p as an (n, 3) float64 array.
py::array_t<double> points_array(const std::vector<Vec3>& p);

//! \p f as an (m, 3) int32 array.
py::array_t<std::int32_t> faces_array(const std::vector<Face>& f);

//! The input report of read_mesh(report=True): the JSON "mesh" object's names
//! and vertex_scalars (name -> (n,) float64 array).
py::dict input_report_dict(const LoadedMesh& m);

//! The statistics \p stats of one direction with its samples: points,
//! distances, signed_distances (None when unsigned), kinds and elements.
py::dict direction_dict(const nlohmann::json& stats, const SampledDirection& d);

}  // namespace meshdiff::python

//! \file generate.h
//! \brief `meshdiff generate` as a library call: which analytic surface
//! (shapes.h), with the options that apply to it, their defaults, limits and
//! combinations (an option that does not apply to the kind, --subdivisions
//! with --frequency, ...). The front end only maps its spellings to the
//! fields; refusals are OptionErrors naming "generate.<field>".
#pragma once

#include "meshdiff/enum_names.h"
#include "meshdiff/studies/shapes.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace meshdiff {

enum class ShapeKind
{
    Sphere,
    NoisySphere,
    Ellipsoid,
    Torus,
    TorusIrregular,
    Heightfield,
    HeightfieldIrregular,
    Plane,
};

template <>
struct EnumNames<ShapeKind>
{
    static constexpr const char* what = "shape";
    static constexpr std::array<EnumName<ShapeKind>, 8> names{
        {{ShapeKind::Sphere, "sphere"},
         {ShapeKind::NoisySphere, "noisy-sphere"},
         {ShapeKind::Ellipsoid, "ellipsoid"},
         {ShapeKind::Torus, "torus"},
         {ShapeKind::TorusIrregular, "torus-irregular"},
         {ShapeKind::Heightfield, "heightfield"},
         {ShapeKind::HeightfieldIrregular, "heightfield-irregular"},
         {ShapeKind::Plane, "plane"}}};
};

//! The limits of the generator options (the memory one option can ask for).
constexpr int kMaxSubdivisions = 8;                                  //!< 2.6M vertices
constexpr int kMaxFrequency = 1024;                                  //!< 21M faces
constexpr int kMinGridN = 2;                                         //!< grid vertices per side, at least
constexpr int kMaxGridN = 8192;                                      //!< at most 67M grid vertices
constexpr std::size_t kMaxIrregularVertices = std::size_t(1) << 26;  //!< 67M

//! The options of one generated surface: an unset field was not given and
//! takes the kind's default (GenerateDefaults); a field that does not apply
//! to the kind may not be set.
struct GenerateOptions
{
    ShapeKind kind = ShapeKind::Sphere;
    std::optional<int> subdivisions;            //!< icosphere subdivisions (sphere, noisy-sphere, ellipsoid)
    std::optional<int> frequency;               //!< geodesic sphere frequency instead (sphere, noisy-sphere, ellipsoid)
    std::optional<double> radius;               //!< sphere radius (sphere, noisy-sphere)
    std::optional<double> noise;                //!< noisy-sphere: radial noise fraction
    std::optional<std::array<double, 3>> axes;  //!< ellipsoid semi-axes
    std::optional<double> major, minor;         //!< torus radii R and r
    std::optional<int> n;                       //!< grid resolution (torus, heightfield, plane)
    std::optional<std::size_t> vertices;        //!< approximate vertex count (the irregular kinds)
    std::optional<double> amplitude;            //!< height field amplitude
    std::optional<double> spacing;              //!< plane grid spacing
    std::optional<std::uint64_t> seed;          //!< noisy and irregular kinds
};

//! The defaults of the fields not given.
struct GenerateDefaults
{
    static constexpr int subdivisions = 4;
    static constexpr double radius = 1.0;
    static constexpr double noise = 0.02;
    static constexpr std::array<double, 3> axes{1.5, 1.0, 1.0};
    static constexpr double major = 1.0;
    static constexpr double minor = 0.25;
    static constexpr int torus_n = 64;  //!< around the major circle; the tube gets n r / R (at least 3)
    static constexpr int heightfield_n = 33;
    static constexpr int plane_n = 17;
    static constexpr std::size_t torus_vertices = 1024;
    static constexpr std::size_t heightfield_vertices = 1089;
    static constexpr double amplitude = 1.0;
    static constexpr double spacing = 1.0;
    static constexpr std::uint64_t seed = 1;
};

//! The surface \p o asks for, and a one-line description of it (with every
//! parameter used).
struct GeneratedShape
{
    Shape shape;
    std::string description;
};

//! \throw OptionError("generate.<field>") for a field that does not apply to
//!        the kind, subdivisions with frequency, or a value outside its
//!        limits (also InvalidArgumentError from the generators of shapes.h).
GeneratedShape generate_shape(const GenerateOptions& o);

}  // namespace meshdiff

//! \file noise.h
//! \brief Seeded random noise on the vertex positions of an arbitrary mesh: the
//! "processed" meshes of roughness experiments (the paper's noisy surfaces).
//!
//! Each vertex i is moved to p_i + t_i d_i, where
//! - t_i is drawn uniformly from [-A, A) (NoiseDistribution::Uniform) or from a
//!   normal distribution with mean 0 and standard deviation A
//!   (NoiseDistribution::Gaussian);
//! - A = amplitude * unit, the unit being the mesh's mean edge length, its
//!   bounding-box diagonal or 1 (NoiseUnit), measured before any vertex moves;
//! - d_i is the angle-weighted unit vertex normal of normals.h
//!   (NoiseDirection::Normal) or a uniformly random unit vector, the normalised
//!   vector of three independent standard normal numbers
//!   (NoiseDirection::Random).
//!
//! Skipped vertices stay where they are: vertices in no face, boundary vertices
//! (meshdiff::boundary_vertex_mask: on a boundary or non-manifold edge) unless
//! `move_boundary` is set, and, with NoiseDirection::Normal, vertices without a
//! normal (vertex_normals() returned the zero vector).
//!
//! Determinism: the numbers come from std::mt19937_64(seed), mapped to [0, 1)
//! by meshdiff itself (as in shapes.h), never through a std:: distribution, and
//! are drawn in vertex order with a fixed number of raw 64-bit outputs per
//! vertex, whether the vertex moves or not (so skipping one vertex never shifts
//! the noise of the others):
//! 1. NoiseDirection::Random only: 4 outputs, two Box-Muller pairs (g0, g1),
//!    (g2, g3); d = (g0, g1, g2) / |(g0, g1, g2)|, g3 unused.
//! 2. NoiseDistribution::Uniform: 1 output u, t = A (2 u - 1).
//!    NoiseDistribution::Gaussian: 2 outputs, one Box-Muller pair (g, g'), t = A
//!    g, g' unused.
//! The computation is serial, so the result does not depend on the thread
//! count; the same mesh and options give bitwise the same positions wherever
//! the C library's log, sin and cos agree (uniform noise along normals needs
//! neither).
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/enum_names.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace meshdiff {

//! What NoiseOptions::amplitude is measured in.
enum class NoiseUnit
{
    MeanEdge,      //!< the mean length of the mesh's edges (each edge counted once)
    BBoxDiagonal,  //!< the diagonal of the mesh's axis-aligned bounding box
    Absolute       //!< 1: amplitude is a length in the mesh's units
};

//! The direction a vertex is moved along.
enum class NoiseDirection
{
    Normal,  //!< the angle-weighted vertex normal (normals.h); no normal: the vertex stays
    Random   //!< a uniformly distributed random unit vector, drawn per vertex
};

//! The distribution of the signed displacement t along the direction.
enum class NoiseDistribution
{
    Uniform,  //!< t uniform in [-A, A): RMS A / sqrt(3)
    Gaussian  //!< t normal with mean 0 and standard deviation A (unbounded)
};

//! Options of add_noise().
struct NoiseOptions
{
    double amplitude = 0.5;                                       //!< >= 0 and finite, in units of `unit`
    NoiseUnit unit = NoiseUnit::MeanEdge;                         //!< what amplitude is measured in
    NoiseDirection direction = NoiseDirection::Normal;            //!< along the normal or a random direction
    NoiseDistribution distribution = NoiseDistribution::Uniform;  //!< of the signed displacement
    std::uint64_t seed = 1;                                       //!< seed of std::mt19937_64
    bool move_boundary = false;                                   //!< also move boundary vertices
};

//! What add_noise() did.
struct NoiseReport
{
    double amplitude = 0.0;                //!< A = options.amplitude * unit_length, in mesh units
    double unit_length = 0.0;              //!< the unit: mean edge length, bbox diagonal or 1
    double mean_edge = 0.0;                //!< mean edge length of the input mesh
    double diagonal = 0.0;                 //!< bounding-box diagonal of the input mesh
    std::size_t moved = 0;                 //!< vertices given a displacement (of length |t|, possibly 0)
    std::size_t skipped_isolated = 0;      //!< vertices in no face
    std::size_t skipped_boundary = 0;      //!< boundary vertices left in place (move_boundary not set)
    std::size_t skipped_no_direction = 0;  //!< no vertex normal (direction Normal), or a zero random vector
    double max_displacement = 0.0;         //!< largest |t| applied
    std::size_t skipped() const { return skipped_isolated + skipped_boundary + skipped_no_direction; }
};

//! Adds noise to the positions of \p mesh in place (faces are untouched) as
//! described above. Each skipped vertex is counted once: an isolated vertex as
//! isolated, a boundary vertex without a normal as boundary.
//! \throw InvalidArgumentError naming the field if an option is out of range
//!        (amplitude not finite or negative, an enum value out of range) or
//!        A = amplitude * unit is not finite.
//! \throw InvalidMeshError if the mesh fails meshdiff::validate().
NoiseReport add_noise(Mesh& mesh, const NoiseOptions& options);

template <>
struct EnumNames<NoiseUnit>
{
    static constexpr const char* what = "noise unit";
    static constexpr std::array<EnumName<NoiseUnit>, 3> names{
        {{NoiseUnit::MeanEdge, "edge"}, {NoiseUnit::BBoxDiagonal, "diagonal"}, {NoiseUnit::Absolute, "absolute"}}};
};

template <>
struct EnumNames<NoiseDirection>
{
    static constexpr const char* what = "noise direction";
    static constexpr std::array<EnumName<NoiseDirection>, 2> names{
        {{NoiseDirection::Normal, "normal"}, {NoiseDirection::Random, "random"}}};
};

template <>
struct EnumNames<NoiseDistribution>
{
    static constexpr const char* what = "noise distribution";
    static constexpr std::array<EnumName<NoiseDistribution>, 2> names{
        {{NoiseDistribution::Uniform, "uniform"}, {NoiseDistribution::Gaussian, "gaussian"}}};
};

}  // namespace meshdiff

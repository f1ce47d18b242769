//! \file sampling.h
//! \brief Metro-style point sampling of a triangle surface: all vertices, then
//! edges, then face interiors (Cignoni, Rocchini, Scopigno, "Metro", CGF 17(2),
//! 1998; METHOD.md section 6).
//!
//! Order and budget. A total target T is split as in Metro: every referenced
//! vertex is one sample (n_v); the rest R = T - n_v gives a face density
//! rho = R / A (A: area of the non-degenerate faces) and an edge density
//! sqrt(rho) per unit length; every unique edge gets its share; what is left,
//! R - n_e, gives the final face density (R - n_e) / A. Fractional counts carry
//! over from one edge (face) to the next in index order, so the total matches
//! the target up to a few samples and never exceeds it, except that every
//! referenced vertex is always a sample: if the vertices alone reach T, there
//! are no edge or face samples and the total is the vertex count. With edges
//! off, the face density is R / A; with faces off, the edge density is R / L
//! (L: total length of the unique edges). Unlike Metro, the edge density is
//! capped at R / L, so that a small target is not overshot by the edges (Metro
//! then exceeds its target).
//!
//! Face schemes. SimilarTriangles (Metro's default, deterministic): a face that
//! is due n samples gets the k(k+1)/2 interior points of a lattice of triangles
//! similar to it, with the largest k such that k(k+1)/2 <= n; the shortfall
//! carries over to the next face. MonteCarlo: n uniform random points per face
//! from a std::mt19937_64 seeded with `seed` (reproducible on every platform).
//! Edge samples are the n points that cut an edge into n + 1 equal parts.
//!
//! Known limit of SimilarTriangles: the lattice holds interior points only (a
//! band of width 1/(k+2) along the edges has none; Metro relies on the edge
//! samples there), and the per-face shortfall moves samples to the next face,
//! so face samples alone are not area-uniform. Where distances differ between
//! face interiors and edges (a coarse mesh against a fine one), sample means
//! from faces only differ from area-uniform (MonteCarlo) ones by a few percent
//! (3-5% on the bunny pairs of reference/meshlab/README.md).
//!
//! Degenerate (zero-area, see degenerate_face_mask) faces get no face samples;
//! their edges are sampled like any other edge. Unreferenced vertices get no
//! sample.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/enum_names.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace meshdiff {

//! How face interiors are sampled.
enum class FaceSampling
{
    SimilarTriangles,  //!< Metro's similar-triangles lattice (deterministic; default)
    MonteCarlo,        //!< uniform random points, seeded (SamplingOptions::seed)
};

template <>
struct EnumNames<FaceSampling>
{
    static constexpr const char* what = "face sampling";
    static constexpr std::array<EnumName<FaceSampling>, 2> names{
        {{FaceSampling::SimilarTriangles, "similar"}, {FaceSampling::MonteCarlo, "montecarlo"}}};
};

//! The kind of mesh element a sample comes from.
enum class SampleKind : std::uint8_t
{
    OnVertex,  //!< a mesh vertex
    OnEdge,    //!< a point inside an edge
    OnFace,    //!< a point inside a face
    OnPoint,   //!< a point of a point cloud (cloud_distance.h); element: the point's index
};

//! Options of the surface sampling. All fields have defaults.
struct SamplingOptions
{
    bool vertices = true;  //!< sample every referenced vertex
    bool edges = true;     //!< sample the unique edges (density sqrt of the face density)
    bool faces = true;     //!< sample face interiors
    FaceSampling face_scheme = FaceSampling::SimilarTriangles;  //!< face sampling scheme
    //! Total target number of samples (vertices + edges + faces) of one
    //! surface. Unset: 10 x #faces of the sampled mesh for sample_surface(),
    //! 10 x max(#faces A, #faces B) per direction for surface_distance().
    std::optional<std::size_t> samples;
    //! Samples per unit area (in the mesh's length unit, squared); the target
    //! becomes density x area of the sampled mesh (Metro's -a). Exclusive with
    //! `samples`.
    std::optional<double> density;
    std::uint64_t seed = 1;  //!< seed of the MonteCarlo scheme (ignored otherwise)
};

//! The most samples of one surface meshdiff takes (about 10 GB of samples and
//! distances): an explicit target, a density times the area, or the default
//! budget above it is an InvalidArgumentError, not a run that exhausts memory.
constexpr std::size_t kMaxSamples = 250'000'000;

//! Throws OptionError naming the field if: no kind is enabled;
//! `samples` is 0 or above kMaxSamples; `density` is not finite and > 0; both `samples` and
//! `density` are set.
void validate(const SamplingOptions& options);

//! The samples of one surface, in order: vertices, then edges, then faces.
struct SurfaceSamples
{
    std::vector<Vec3> points;      //!< sample positions
    std::vector<SampleKind> kind;  //!< kind per sample
    //! Source element per sample: the vertex index (OnVertex); the lowest index
    //! of a face having the edge (OnEdge); the face index (OnFace).
    std::vector<std::uint32_t> element;
    std::size_t n_vertex = 0;   //!< number of vertex samples
    std::size_t n_edge = 0;     //!< number of edge samples
    std::size_t n_face = 0;     //!< number of face samples
    std::size_t target = 0;     //!< total target T the counts were derived from
    double edge_density = 0.0;  //!< edge samples per unit length used
    double face_density = 0.0;  //!< face samples per unit area used

    std::size_t size() const { return points.size(); }
};

//! The target total of sample_surface() for \p mesh under \p options (see the
//! \p options.samples and \p options.density docs). \p default_target is used
//! when neither is set.
std::size_t sample_target(const Mesh& mesh, const SamplingOptions& options, std::size_t default_target);

//! Samples \p mesh as described in the file comment. Deterministic for
//! SimilarTriangles; for MonteCarlo, a function of `seed`.
//! \throw InvalidArgumentError for invalid options (see validate()).
//! \throw InvalidMeshError if \p mesh is invalid (see meshdiff::validate()).
SurfaceSamples sample_surface(const Mesh& mesh, const SamplingOptions& options = {});
//! The same from \p data, the derived data of the mesh (mesh_data.h).
SurfaceSamples sample_surface(const MeshData& data, const SamplingOptions& options = {});

}  // namespace meshdiff

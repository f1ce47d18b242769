//! \file io.h
//! \brief Reading meshes (PLY ASCII/binary, OBJ, OFF, STL, each through a
//! strict reader of meshdiff's own) with the input hygiene of METHOD.md
//! section 1, and writing PLY with per-vertex scalar properties and colours.
#pragma once

#include "meshdiff/core/mesh.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace meshdiff {

//! max_coordinate (mesh.h): the largest coordinate magnitude read_mesh() accepts.

//! What reading did to the file's contents before anything else.
struct InputReport
{
    std::string path;                       //!< the file as given
    std::size_t file_vertices = 0;          //!< vertices in the file
    std::size_t file_faces = 0;             //!< faces (polygons) in the file
    std::size_t unreferenced_vertices = 0;  //!< dropped: in no face
    std::size_t polygons_triangulated = 0;  //!< faces with more than 3 corners (fan-triangulated)
    std::size_t repeated_index_faces = 0;   //!< dropped: a corner repeated (no area, no edges of its own)
    //! Read by read_mesh_or_cloud() from a file with vertices and no faces:
    //! LoadedMesh::mesh holds every point and no face.
    bool point_cloud = false;
};

//! A named per-vertex scalar (read from or written as a PLY vertex property).
struct VertexScalar
{
    std::string name;
    std::vector<double> values;  //!< one per vertex; NaN is written as NaN
};

struct LoadedMesh
{
    Mesh mesh;
    InputReport input;
    //! Scalar vertex properties of a PLY file other than x, y, z (for example
    //! `exact_H` written by `meshdiff generate`), one value per kept vertex.
    std::vector<VertexScalar> vertex_scalars;
};

//! The vertex scalar called \p name of \p loaded.
//! \throw InvalidArgumentError if there is none (the message names the file).
const VertexScalar& vertex_scalar(const LoadedMesh& loaded, const std::string& name);

//! Reads \p path. The format follows the extension (.ply .obj .off .stl).
//! Unreferenced vertices are dropped (and counted), polygons fan-triangulated,
//! faces with a repeated corner dropped (and counted); coordinates are kept in
//! double precision as the reader delivers them.
//! PLY coordinates keep the precision of the file; OBJ, OFF and STL ones are
//! rounded to float, as OpenMesh's readers, which meshdiff used before, did.
//! \throw IoError if the file is missing, not a regular file (a FIFO, a device,
//!        a directory), unreadable, of an unknown format, empty, truncated,
//!        unparsable, or if its header counts do not match its body (too few
//!        bytes for a count, or data after the declared elements).
//! \throw InvalidMeshError if it has no vertices, no faces (the message says
//!        it is a point cloud, which only compare accepts), a face with fewer
//!        than 3 corners, a face index out of range, a NaN/Inf coordinate or
//!        one beyond max_coordinate.
LoadedMesh read_mesh(const std::filesystem::path& path);

//! read_mesh(), except that a file with vertices and no faces (no face element,
//! or a face count of 0) is read as a point cloud: every point is kept, in file
//! order, with its scalar properties; InputReport::point_cloud is set and
//! LoadedMesh::mesh has no faces. Only compare reads its inputs this way (STL
//! cannot hold a cloud; an OBJ with only `p` elements stays an error). The
//! checks of the coordinates are those of read_mesh(); a file with no vertex
//! is an error as there.
//! \throw as read_mesh(), except for "no faces".
LoadedMesh read_mesh_or_cloud(const std::filesystem::path& path);

//! True if \p loaded is a point cloud (its mesh has no faces).
bool is_point_cloud(const LoadedMesh& loaded);

//! Writes a binary little-endian PLY with x y z (double), the given scalar
//! properties, optional RGB colours (uchar red green blue) and the faces.
//! \throw IoError if the file cannot be written.
//! \throw InvalidArgumentError if a property has the wrong size.
void write_ply(const std::filesystem::path& path, const Mesh& mesh, const std::vector<VertexScalar>& scalars = {},
               const std::vector<std::array<std::uint8_t, 3>>& colors = {},
               const std::vector<std::string>& comments = {});

//! Writes a mesh in the format of the extension: .ply through write_ply() with
//! the scalar properties and comments; .obj, .off, .stl through OpenMesh's
//! writers, which keep neither (see writes_vertex_properties()).
//! \throw IoError on failure (also for non-manifold faces in .obj .off .stl).
//! \throw InvalidArgumentError if a property has the wrong size.
void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const std::vector<VertexScalar>& scalars = {},
                const std::vector<std::string>& comments = {});

//! True if write_mesh() keeps vertex properties and comments in the format of
//! \p path (PLY).
bool writes_vertex_properties(const std::filesystem::path& path);

}  // namespace meshdiff

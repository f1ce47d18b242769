//! \file sample_cloud.h
//! \brief The samples of both directions of a surface distance, written as one
//! binary PLY point cloud (`meshdiff compare --samples-out FILE.ply`), for
//! MeshLab, CloudCompare, numpy or one's own statistics.
//!
//! Format: `format binary_little_endian 1.0`, one element `vertex` with, per
//! sample, `double x, y, z` (the sample position), `double distance` (its exact
//! distance to the other surface), `double signed_distance` (the same, positive
//! outside the other surface, negative inside: signed_distance.h; NaN in a
//! direction whose other surface cannot be signed against, which a header
//! comment then says), `uchar kind` (0 vertex, 1 edge, 2 face:
//! SampleKind), `uchar direction` (0 forward: a sample of the original,
//! distance to the processed surface; 1 backward) and `int face` (the face of
//! the sampled mesh: the face sampled; for an edge sample the lowest-index face
//! having the edge; for a vertex sample the lowest-index face using the vertex).
//! 46 bytes per sample, no padding: numpy reads the body with
//! `np.frombuffer(body, dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8"),
//! ("distance", "<f8"), ("signed_distance", "<f8"), ("kind", "u1"),
//! ("direction", "u1"), ("face", "<i4")])`.
//! Forward samples first, then backward, each in sample order. Header comments
//! state the meaning of the codes and the meshes' paths.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/distance/surface_distance.h"

#include <filesystem>
#include <string>
#include <vector>

namespace meshdiff {

//! Bytes per sample in the file body.
constexpr std::size_t kSampleCloudStride = 46;

//! Writes \p forward (samples of \p a, the original) and \p backward (samples
//! of \p b) to \p path as described in the file comment, atomically
//! (output_file.h), with \p comments as extra header comments.
//! \throw InvalidArgumentError if a direction's samples and distances (or its
//!        signed distances, when it has any) differ in size or a sample's
//!        element is not in its mesh.
//! \throw IoError if the file cannot be written.
void write_sample_cloud(const std::filesystem::path& path, const Mesh& a, const SampledDirection& forward,
                        const Mesh& b, const SampledDirection& backward, const std::vector<std::string>& comments = {});

}  // namespace meshdiff

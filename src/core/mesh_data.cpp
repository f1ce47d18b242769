#include "meshdiff/core/mesh_data.h"

#include "core/derivations.h"
#include "core/release.h"

namespace meshdiff {

const BoundingBox& MeshData::box() const
{
    std::call_once(box_once_, [this] { box_ = bounding_box(mesh_); });
    return box_;
}

const std::vector<char>& MeshData::degenerate_faces() const
{
    std::call_once(degenerate_once_, [this] { degenerate_ = meshdiff::degenerate_face_mask(mesh_, box()); });
    return degenerate_;
}

const Adjacency& MeshData::vertex_faces() const
{
    const std::lock_guard<std::mutex> lock(vertex_faces_mutex_);
    if (!has_vertex_faces_) {
        vertex_faces_ = meshdiff::vertex_faces(mesh_);
        has_vertex_faces_ = true;
    }
    return vertex_faces_;
}

void detail::release_vertex_faces(const MeshData& data)
{
    const std::lock_guard<std::mutex> lock(data.vertex_faces_mutex_);
    detail::release(data.vertex_faces_.offset);
    detail::release(data.vertex_faces_.index);
    data.has_vertex_faces_ = false;
}

void MeshData::validate(const std::string& what) const
{
    // A throw leaves the flag unset: the next call validates (and throws) again.
    std::call_once(valid_once_, [&] { meshdiff::validate(mesh_, what); });
}

}  // namespace meshdiff

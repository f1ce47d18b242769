#include "meshdiff/core/mesh_data.h"

#include "core/derivations.h"

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
    std::call_once(vertex_faces_once_, [this] { vertex_faces_ = meshdiff::vertex_faces(mesh_); });
    return vertex_faces_;
}

void MeshData::validate(const std::string& what) const
{
    // A throw leaves the flag unset: the next call validates (and throws) again.
    std::call_once(valid_once_, [&] { meshdiff::validate(mesh_, what); });
}

}  // namespace meshdiff

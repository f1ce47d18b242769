//! \file distance_kind.h
//! \brief Which distance a direction of a surface distance measures: between
//! two meshes (Metro), or with a point cloud on one or both sides
//! (cloud_distance.h; METHOD.md section 6, "Point clouds").
#pragma once

#include "meshdiff/enum_names.h"

namespace meshdiff {

//! Which distance a direction measures.
enum class DistanceKind
{
    SurfaceToSurface,  //!< samples of a mesh, exact distance to a mesh (Metro)
    PointToSurface,    //!< points of a cloud, exact distance to a mesh
    SurfaceToPoint,    //!< samples of a mesh, distance to the nearest point of a cloud
    PointToPoint,      //!< points of a cloud, distance to the nearest point of a cloud
};

template <>
struct EnumNames<DistanceKind>
{
    static constexpr const char* what = "distance kind";
    static constexpr std::array<EnumName<DistanceKind>, 4> names{
        {{DistanceKind::SurfaceToSurface, "surface-to-surface"},
         {DistanceKind::PointToSurface, "point-to-surface"},
         {DistanceKind::SurfaceToPoint, "surface-to-point"},
         {DistanceKind::PointToPoint, "point-to-point"}}};
};

//! True if the direction samples a point cloud (PointToSurface, PointToPoint).
constexpr bool from_cloud(DistanceKind k)
{
    return k == DistanceKind::PointToSurface || k == DistanceKind::PointToPoint;
}

//! True if the direction measures to a point cloud (SurfaceToPoint, PointToPoint).
constexpr bool to_cloud(DistanceKind k)
{
    return k == DistanceKind::SurfaceToPoint || k == DistanceKind::PointToPoint;
}

}  // namespace meshdiff

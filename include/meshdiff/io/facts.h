//! \file facts.h
//! \brief What meshdiff knows about an input mesh before and after a profile:
//! the reading report, the topology report, the box and the area, and the
//! warnings that limit what the numbers mean, as structured values (kind,
//! level, value, text). The presentation layer (meshdiff/report/) prints them;
//! programs test the kind, never the text.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/enum_names.h"
#include "meshdiff/io/io.h"

#include <string>
#include <vector>

namespace meshdiff {

struct RoughnessProfile;  // roughness/roughness.h

//! Everything the reports say about one input mesh.
struct MeshFacts
{
    InputReport input;
    TopologyReport topology;
    BoundingBox box;
    double area = 0.0;
};

//! The facts of a mesh as read.
MeshFacts mesh_facts(const LoadedMesh& loaded);
//! The same from \p data, the derived data of loaded.mesh (mesh_data.h).
MeshFacts mesh_facts(const LoadedMesh& loaded, const MeshData& data);

//! What a warning is about.
enum class WarningKind
{
    UnreferencedVertices,  //!< value: vertices dropped by reading
    RepeatedCornerFaces,   //!< value: faces dropped by reading
    IsolatedVertices,      //!< value: vertices in no face (read_mesh drops them; a mesh built in code may have them)
    NonManifold,           //!< value: non-manifold edges (the vertices are in the text)
    OrientationConflicts,  //!< value: edges used twice in the same direction
    DegenerateFaces,       //!< value: zero-area faces (topology.h)
    DuplicateFaces,        //!< value: faces repeating an earlier one's vertex set
    OpenSurface,           //!< value: boundary edges (the loops are in the text)
    Components,            //!< value: connected components (more than 1)
    UndefinedCurvature,    //!< value: vertices with undefined H
    OutliersDominate,      //!< level: the level; value: top_share (above 0.5)
    NoDefinedD,            //!< level: the level; value: 0 (no vertex has a defined D)
    CappedNeighbourhoods,  //!< value: curvature fits on a capped 2-ring (curvature.h, kMaxFitNeighbors)
    SparseNeighbourhoods,  //!< level: the level; value: share of vertices without a neighbourhood (above 0.1)
    SteepFits              //!< value: share of jet fits steeper than 30 degrees (above kJetSteepShare)
};

template <>
struct EnumNames<WarningKind>
{
    static constexpr const char* what = "warning kind";
    static constexpr std::array<EnumName<WarningKind>, 15> names{
        {{WarningKind::UnreferencedVertices, "unreferenced-vertices"},
         {WarningKind::RepeatedCornerFaces, "repeated-corner-faces"},
         {WarningKind::IsolatedVertices, "isolated-vertices"},
         {WarningKind::NonManifold, "non-manifold"},
         {WarningKind::OrientationConflicts, "orientation-conflicts"},
         {WarningKind::DegenerateFaces, "degenerate-faces"},
         {WarningKind::DuplicateFaces, "duplicate-faces"},
         {WarningKind::OpenSurface, "open-surface"},
         {WarningKind::Components, "components"},
         {WarningKind::UndefinedCurvature, "undefined-curvature"},
         {WarningKind::OutliersDominate, "outliers-dominate"},
         {WarningKind::NoDefinedD, "no-defined-d"},
         {WarningKind::CappedNeighbourhoods, "capped-neighbourhoods"},
         {WarningKind::SparseNeighbourhoods, "sparse-neighbourhoods"},
         {WarningKind::SteepFits, "steep-fits"}}};
};

//! One warning about a mesh or its profile.
struct Warning
{
    WarningKind kind = WarningKind::UnreferencedVertices;
    int level = -1;       //!< the ring level it concerns, 0 for the global level, -1 for the mesh
    double value = 0.0;   //!< the count or share it is about (see WarningKind)
    std::string text;     //!< one line for people
    double radius = 0.0;  //!< the metric level it concerns (level is then -1), 0 otherwise
};

//! The warnings about \p facts (defects of the mesh) and, with \p profile,
//! about its profile (undefined curvature, capped curvature neighbourhoods,
//! outlier-dominated levels, levels without a defined D), in that order.
std::vector<Warning> warnings(const MeshFacts& facts, const RoughnessProfile* profile = nullptr);

}  // namespace meshdiff

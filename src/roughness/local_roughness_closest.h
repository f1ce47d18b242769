//! \file local_roughness_closest.h (detail)
//! \brief The local roughness difference handing over the closest points it
//! finds: what compare_meshes() passes on to the surface distance, whose
//! backward direction needs the same ones.
#pragma once

#include "meshdiff/roughness/local_roughness.h"

#include "roughness/level_stream.h"

#include <optional>
#include <vector>

namespace meshdiff::detail {

//! local_roughness_distance(), and, when \p closest is given, the closest
//! points of mesh's vertices on other (other_index.closest_points(mesh.points))
//! moved into it.
LocalRoughnessDistance local_roughness_distance(const Mesh& mesh, const RoughnessProfile& profile, const Mesh& other,
                                                const RoughnessProfile& other_profile,
                                                const ClosestPointIndex& other_index, double trim,
                                                bool keep_vertex_data, LocalRoughnessParts parts,
                                                std::vector<ClosestPoint>* closest);

//! The local difference's ring levels and global level (no radii) over the
//! vertices of \p mesh, folded in the ring search of mesh's own profile
//! (roughness_profile_keeping_H() with start() as its hook): one search of
//! its rings instead of two. The same numbers as local_roughness_distance()
//! to the last bit where H and the change of H are defined at the same
//! vertices (otherwise within the rounding of the sums: fold_levels()).
//! Lives at one address from start() to finish().
class LocalRingsInProfile
{
public:
    //! \p other_profile must carry H; \p closest as local_roughness_distance().
    LocalRingsInProfile(const Mesh& mesh, const Mesh& other, const RoughnessProfile& other_profile,
                        const ClosestPointIndex& other_index, double trim, bool keep_vertex_data, bool global,
                        std::vector<ClosestPoint>* closest);
    LocalRingsInProfile(const LocalRingsInProfile&) = delete;
    LocalRingsInProfile& operator=(const LocalRingsInProfile&) = delete;

    //! The hook: the change of H from mesh's H (on its normalised mesh
    //! \p unit, for the vertex areas), folded at \p levels, the profile's,
    //! which must be those both profiles have.
    std::optional<SecondFold> start(const Mesh& unit, const std::vector<double>& H, const std::vector<int>& levels);
    //! The result, once mesh's profile is made (it gives has_global).
    LocalRoughnessDistance finish(const RoughnessProfile& profile);

private:
    const Mesh& mesh_;
    const Mesh& other_;
    const RoughnessProfile& other_profile_;
    const ClosestPointIndex& index_;
    double trim_;
    bool keep_, global_, started_ = false;
    std::vector<ClosestPoint>* closest_;
    std::vector<double> F_, area_;
    LocalRoughnessDistance r_;
};

}  // namespace meshdiff::detail

// The 0.2 include paths (meshdiff/hausdorff.h, ...) still compile against the
// installed package: each forwards to its subsystem folder (meshdiff/distance/
// hausdorff.h, ...) until 0.3. tests/consumer_test.sh checks that this file
// includes every forwarder the package installs.
#include "meshdiff/closest_point.h"
#include "meshdiff/cloud_distance.h"
#include "meshdiff/colormap.h"
#include "meshdiff/corsini.h"
#include "meshdiff/cotangent.h"
#include "meshdiff/curvature.h"
#include "meshdiff/distance_kind.h"
#include "meshdiff/facts.h"
#include "meshdiff/generate.h"
#include "meshdiff/hausdorff.h"
#include "meshdiff/io.h"
#include "meshdiff/mesh.h"
#include "meshdiff/metric_levels.h"
#include "meshdiff/neighborhood.h"
#include "meshdiff/noise.h"
#include "meshdiff/normalize.h"
#include "meshdiff/normals.h"
#include "meshdiff/options.h"
#include "meshdiff/output_file.h"
#include "meshdiff/point_triangle.h"
#include "meshdiff/progress.h"
#include "meshdiff/roughness.h"
#include "meshdiff/roughness_distance.h"
#include "meshdiff/same_connectivity.h"
#include "meshdiff/sample_cloud.h"
#include "meshdiff/sampling.h"
#include "meshdiff/shapes.h"
#include "meshdiff/signed_distance.h"
#include "meshdiff/smoothing.h"
#include "meshdiff/smoothing_record.h"
#include "meshdiff/surface_distance.h"
#include "meshdiff/topology.h"
#include "meshdiff/vertex_maps.h"

#include <iostream>

int main()
{
    // Types and functions of several folders, reached through the old paths.
    const meshdiff::Mesh mesh = meshdiff::icosphere(1, 1.0).mesh;
    const meshdiff::SurfaceDistance d = meshdiff::surface_distance(mesh, mesh);
    std::cout << "old paths: " << mesh.n_faces() << " faces, hausdorff " << d.hausdorff << "\n";
    return d.hausdorff < 1e-12 ? 0 : 1;  // a mesh against itself: rounding only
}

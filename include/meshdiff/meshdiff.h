//! \file meshdiff.h
//! \brief All of meshdiff's computing library (target meshdiff::meshdiff) in
//! one include, folder by folder from the bottom floor up. The presentation
//! (target meshdiff::report: JSON and text reports, per-vertex maps and their
//! colours) is in meshdiff/report/.
#pragma once

#include "meshdiff/enum_names.h"
#include "meshdiff/error.h"
#include "meshdiff/version.h"

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/progress.h"
#include "meshdiff/core/tolerances.h"
#include "meshdiff/core/topology.h"

#include "meshdiff/io/facts.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"

#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/geometry/cotangent.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/geometry/normals.h"
#include "meshdiff/geometry/point_triangle.h"
#include "meshdiff/geometry/sampling.h"
#include "meshdiff/geometry/vertex_areas.h"

#include "meshdiff/roughness/corsini.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/neighborhood.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/roughness/roughness_distance.h"

#include "meshdiff/distance/cloud_distance.h"
#include "meshdiff/distance/distance_kind.h"
#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/distance/same_connectivity.h"
#include "meshdiff/distance/sample_cloud.h"
#include "meshdiff/distance/signed_distance.h"
#include "meshdiff/distance/surface_distance.h"

#include "meshdiff/studies/generate.h"
#include "meshdiff/studies/noise.h"
#include "meshdiff/studies/shapes.h"
#include "meshdiff/studies/smoothing.h"
#include "meshdiff/studies/smoothing_record.h"

#include "meshdiff/compare.h"
#include "meshdiff/frontend/options.h"

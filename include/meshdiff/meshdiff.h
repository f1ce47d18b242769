//! \file meshdiff.h
//! \brief All of meshdiff's computing library in one include. The JSON and text
//! presentation (target meshdiff::report) is in meshdiff/report/json.h and
//! meshdiff/report/text.h.
#pragma once

#include "meshdiff/closest_point.h"
#include "meshdiff/colormap.h"
#include "meshdiff/compare.h"
#include "meshdiff/corsini.h"
#include "meshdiff/cotangent.h"
#include "meshdiff/curvature.h"
#include "meshdiff/enum_names.h"
#include "meshdiff/error.h"
#include "meshdiff/facts.h"
#include "meshdiff/hausdorff.h"
#include "meshdiff/io.h"
#include "meshdiff/mesh.h"
#include "meshdiff/metric_levels.h"
#include "meshdiff/neighborhood.h"
#include "meshdiff/noise.h"
#include "meshdiff/normalize.h"
#include "meshdiff/normals.h"
#include "meshdiff/point_triangle.h"
#include "meshdiff/roughness.h"
#include "meshdiff/roughness_distance.h"
#include "meshdiff/sampling.h"
#include "meshdiff/shapes.h"
#include "meshdiff/smoothing.h"
#include "meshdiff/smoothing_record.h"
#include "meshdiff/surface_distance.h"
#include "meshdiff/topology.h"
#include "meshdiff/version.h"
#include "meshdiff/vertex_maps.h"

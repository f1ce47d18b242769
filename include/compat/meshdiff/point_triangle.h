//! \file point_triangle.h
//! \brief The 0.2 path of meshdiff/geometry/point_triangle.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/geometry/point_triangle.h"

//! \file closest_point.h
//! \brief The 0.2 path of meshdiff/geometry/closest_point.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/geometry/closest_point.h"

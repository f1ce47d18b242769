//! \file curvature.h
//! \brief The 0.2 path of meshdiff/roughness/curvature.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/roughness/curvature.h"

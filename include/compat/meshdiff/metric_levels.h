//! \file metric_levels.h
//! \brief The 0.2 path of meshdiff/roughness/metric_levels.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/roughness/metric_levels.h"

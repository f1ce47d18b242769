//! \file sample_cloud.h
//! \brief The 0.2 path of meshdiff/distance/sample_cloud.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/distance/sample_cloud.h"

//! \file cloud_distance.h
//! \brief The 0.2 path of meshdiff/distance/cloud_distance.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/distance/cloud_distance.h"

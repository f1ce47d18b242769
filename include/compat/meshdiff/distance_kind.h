//! \file distance_kind.h
//! \brief The 0.2 path of meshdiff/distance/distance_kind.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/distance/distance_kind.h"

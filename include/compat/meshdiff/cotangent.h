//! \file cotangent.h
//! \brief The 0.2 path of meshdiff/geometry/cotangent.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/geometry/cotangent.h"

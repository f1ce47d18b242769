//! \file normals.h
//! \brief The 0.2 path of meshdiff/geometry/normals.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/geometry/normals.h"

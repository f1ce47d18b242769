//! \file sampling.h
//! \brief The 0.2 path of meshdiff/geometry/sampling.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/geometry/sampling.h"

//! \file hausdorff.h
//! \brief The 0.2 path of meshdiff/distance/hausdorff.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/distance/hausdorff.h"

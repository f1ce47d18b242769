//! \file colormap.h
//! \brief The 0.2 path of meshdiff/report/colormap.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/report/colormap.h"

//! \file smoothing.h
//! \brief The 0.2 path of meshdiff/studies/smoothing.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/studies/smoothing.h"

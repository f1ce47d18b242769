//! \file progress.h
//! \brief The 0.2 path of meshdiff/core/progress.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/core/progress.h"

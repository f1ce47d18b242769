//! \file options.h
//! \brief The 0.2 path of meshdiff/frontend/options.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/frontend/options.h"

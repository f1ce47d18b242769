//! \file neighborhood.h
//! \brief The 0.2 path of meshdiff/roughness/neighborhood.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/roughness/neighborhood.h"

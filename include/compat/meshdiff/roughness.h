//! \file roughness.h
//! \brief The 0.2 path of meshdiff/roughness/roughness.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/roughness/roughness.h"

//! \file shapes.h
//! \brief The 0.2 path of meshdiff/studies/shapes.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/studies/shapes.h"

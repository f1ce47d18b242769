//! \file generate.h
//! \brief The 0.2 path of meshdiff/studies/generate.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/studies/generate.h"

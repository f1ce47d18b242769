//! \file mesh.h
//! \brief The 0.2 path of meshdiff/core/mesh.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/core/mesh.h"

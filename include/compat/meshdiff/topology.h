//! \file topology.h
//! \brief The 0.2 path of meshdiff/core/topology.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/core/topology.h"

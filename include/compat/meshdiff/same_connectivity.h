//! \file same_connectivity.h
//! \brief The 0.2 path of meshdiff/distance/same_connectivity.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/distance/same_connectivity.h"

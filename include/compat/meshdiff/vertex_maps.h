//! \file vertex_maps.h
//! \brief The 0.2 path of meshdiff/report/vertex_maps.h: forwards to it, and goes at 0.3.
#pragma once

#include "meshdiff/report/vertex_maps.h"

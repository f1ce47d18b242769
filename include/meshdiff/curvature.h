//! \file curvature.h
//! \brief (placeholder, being written)
#pragma once
#include "meshdiff/mesh.h"

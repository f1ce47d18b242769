//! \file roughness_distance.h
//! \brief (placeholder, being written)
#pragma once
#include "meshdiff/mesh.h"

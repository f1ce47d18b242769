#include <gtest/gtest.h>

#include "meshdiff/surface_distance.h"

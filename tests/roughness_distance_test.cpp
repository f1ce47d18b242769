#include <gtest/gtest.h>

#include "meshdiff/roughness_distance.h"

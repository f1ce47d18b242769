#include <gtest/gtest.h>

#include "meshdiff/curvature.h"

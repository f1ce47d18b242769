#include <gtest/gtest.h>

#include "meshdiff/closest_point.h"

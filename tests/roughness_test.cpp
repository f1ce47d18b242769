#include <gtest/gtest.h>

#include "meshdiff/roughness.h"

#include <gtest/gtest.h>

#include "meshdiff/shapes.h"

#include <gtest/gtest.h>

#include "meshdiff/normals.h"

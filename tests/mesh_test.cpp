#include <gtest/gtest.h>

#include "meshdiff/mesh.h"

#include <gtest/gtest.h>

#include "meshdiff/smoothing.h"

#include <gtest/gtest.h>

#include "meshdiff/sampling.h"

#include <gtest/gtest.h>

#include "meshdiff/neighborhood.h"

#include <gtest/gtest.h>

#include "meshdiff/normalize.h"

#include <gtest/gtest.h>

#include "meshdiff/io.h"

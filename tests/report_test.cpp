#include <gtest/gtest.h>

#include "meshdiff/report.h"

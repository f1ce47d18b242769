#include "meshdiff/closest_point.h"

#include "meshdiff/surface_distance.h"

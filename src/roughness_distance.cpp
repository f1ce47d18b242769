#include "meshdiff/roughness_distance.h"

#include "meshdiff/curvature.h"
